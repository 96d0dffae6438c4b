#pragma once
// The last two values a fit asked for, kept: a numeric Jacobian steps one parameter away from a
// base point and back, so the base's value is asked for again right after a step's.
#include <array>
#include <utility>

namespace planter::analysis {

// slots[1] is the last used, slots[0] the one before. Returns the slot `matches` accepts, or
// the older one refilled by `fill`.
template <class Slot, class Matches, class Fill>
Slot& recent_two(std::array<Slot, 2>& slots, Matches matches, Fill fill) {
  if (matches(slots[0])) {
    std::swap(slots[0], slots[1]);
  } else if (!matches(slots[1])) {
    std::swap(slots[0], slots[1]);
    fill(slots[1]);
  }
  return slots[1];
}

}  // namespace planter::analysis
