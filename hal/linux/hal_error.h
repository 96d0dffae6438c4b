#pragma once
// A hardware resource that cannot be opened as configured (missing interface, wrong chip,
// a line the chip does not have). Thrown only at init, never from the real-time loop.
#include <stdexcept>
#include <string>

namespace planter::hal::linux_backend {

class HalError : public std::runtime_error {
 public:
  explicit HalError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace planter::hal::linux_backend
