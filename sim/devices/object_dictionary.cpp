#include "sim/devices/object_dictionary.h"

#include <algorithm>
#include <utility>

#include "firmware/canopen/pdo.h"

namespace planter::canopen {

namespace {
bool is_communication_object(std::uint16_t index) { return index >= 0x1000 && index <= 0x1FFF; }
}  // namespace

void ObjectDictionary::insert(ObjectEntry entry) {
  ++revision_;
  // After entries of the same key, so a duplicate add changes nothing that find returns.
  const std::uint32_t key = key_of(entry.index, entry.sub);
  const auto at = std::upper_bound(keys_.begin(), keys_.end(), key);
  const auto offset = at - keys_.begin();
  keys_.insert(at, key);
  entries_.insert(entries_.begin() + offset, std::move(entry));
}

void ObjectDictionary::add(std::uint16_t index, std::uint8_t sub, std::uint8_t size, Access access,
                           std::uint64_t value) {
  insert(ObjectEntry{index, sub, size, access, value, {}});
}

void ObjectDictionary::add_string(std::uint16_t index, std::uint8_t sub, std::string text) {
  insert(ObjectEntry{index, sub, 0, Access::kConst, 0, std::move(text)});
}

std::size_t ObjectDictionary::first_at_or_after(std::uint32_t key) const {
  return static_cast<std::size_t>(std::lower_bound(keys_.begin(), keys_.end(), key) -
                                  keys_.begin());
}

ObjectEntry* ObjectDictionary::find(std::uint16_t index, std::uint8_t sub) {
  const std::uint32_t key = key_of(index, sub);
  const std::size_t i = first_at_or_after(key);
  return i < keys_.size() && keys_[i] == key ? &entries_[i] : nullptr;
}

const ObjectEntry* ObjectDictionary::find(std::uint16_t index, std::uint8_t sub) const {
  const std::uint32_t key = key_of(index, sub);
  const std::size_t i = first_at_or_after(key);
  return i < keys_.size() && keys_[i] == key ? &entries_[i] : nullptr;
}

bool ObjectDictionary::has_index(std::uint16_t index) const {
  const std::size_t i = first_at_or_after(key_of(index, 0));
  return i < keys_.size() && (keys_[i] >> 8) == index;
}

std::uint64_t ObjectDictionary::get(std::uint16_t index, std::uint8_t sub) const {
  const ObjectEntry* e = find(index, sub);
  return e != nullptr ? e->value : 0;
}

std::int64_t ObjectDictionary::get_signed(std::uint16_t index, std::uint8_t sub) const {
  const ObjectEntry* e = find(index, sub);
  if (e == nullptr || e->size == 0) return 0;
  return sign_extend(e->value, 8u * e->size);
}

void ObjectDictionary::set(std::uint16_t index, std::uint8_t sub, std::uint64_t value) {
  if (ObjectEntry* e = find(index, sub)) store(*e, value);
}

void ObjectDictionary::store(ObjectEntry& e, std::uint64_t value) {
  if (is_communication_object(e.index)) ++revision_;
  e.value = e.size >= 8 ? value : (value & ((1ull << (8u * e.size)) - 1));
}

}  // namespace planter::canopen
