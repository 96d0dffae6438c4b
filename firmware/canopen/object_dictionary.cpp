#include "firmware/canopen/object_dictionary.h"

#include <utility>

#include "firmware/canopen/pdo.h"

namespace planter::canopen {

void ObjectDictionary::add(std::uint16_t index, std::uint8_t sub, std::uint8_t size, Access access,
                           std::uint64_t value) {
  entries_.push_back(ObjectEntry{index, sub, size, access, value, {}});
}

void ObjectDictionary::add_string(std::uint16_t index, std::uint8_t sub, std::string text) {
  entries_.push_back(ObjectEntry{index, sub, 0, Access::kConst, 0, std::move(text)});
}

ObjectEntry* ObjectDictionary::find(std::uint16_t index, std::uint8_t sub) {
  for (auto& e : entries_) {
    if (e.index == index && e.sub == sub) return &e;
  }
  return nullptr;
}

const ObjectEntry* ObjectDictionary::find(std::uint16_t index, std::uint8_t sub) const {
  for (const auto& e : entries_) {
    if (e.index == index && e.sub == sub) return &e;
  }
  return nullptr;
}

bool ObjectDictionary::has_index(std::uint16_t index) const {
  for (const auto& e : entries_) {
    if (e.index == index) return true;
  }
  return false;
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
  if (ObjectEntry* e = find(index, sub)) {
    e->value = e->size >= 8 ? value : (value & ((1ull << (8u * e->size)) - 1));
  }
}

}  // namespace planter::canopen
