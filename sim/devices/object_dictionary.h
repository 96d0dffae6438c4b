#pragma once
// A device's object dictionary: typed entries created at init, read and written afterwards
// without allocation. The device side of CANopen: the simulated nodes' (the controller is the
// client and never holds one).
// Entries are kept sorted by (index, sub) and found by binary search: a simulated drive is
// asked about 350 times a tick, and a linear scan of its 140 entries was most of the
// lockstep simulator's time (issue 30).
#include <cstdint>
#include <string>
#include <vector>

#include "firmware/canopen/access.h"

namespace planter::canopen {

struct ObjectEntry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t size = 4;  // bytes for numbers; 0 for a visible string
  Access access = Access::kReadWrite;
  std::uint64_t value = 0;
  std::string text;  // visible strings (names, versions); set at init
};

class ObjectDictionary {
 public:
  void add(std::uint16_t index, std::uint8_t sub, std::uint8_t size, Access access,
           std::uint64_t value = 0);
  void add_string(std::uint16_t index, std::uint8_t sub, std::string text);

  // Numbers are written through set() or store(), never through the pointer, so the
  // revision below sees every change.
  [[nodiscard]] ObjectEntry* find(std::uint16_t index, std::uint8_t sub);
  [[nodiscard]] const ObjectEntry* find(std::uint16_t index, std::uint8_t sub) const;
  [[nodiscard]] bool has_index(std::uint16_t index) const;
  // Entry pointers stay valid until the next add.

  // Application access (no access checks): the device's own logic.
  [[nodiscard]] std::uint64_t get(std::uint16_t index, std::uint8_t sub) const;
  [[nodiscard]] std::int64_t get_signed(std::uint16_t index, std::uint8_t sub) const;
  void set(std::uint16_t index, std::uint8_t sub, std::uint64_t value);
  // set() through an entry already found: the hot paths keep pointers (see revision()).
  void store(ObjectEntry& entry, std::uint64_t value);

  // Changes with every add (entry pointers move) and every change of a communication object
  // (0x1000-0x1FFF: PDO parameters and mappings, heartbeat). A device keeps entry pointers and
  // its resolved PDO tables while this stays the same, instead of searching on every frame.
  [[nodiscard]] std::uint64_t revision() const { return revision_; }

 private:
  [[nodiscard]] static std::uint32_t key_of(std::uint16_t index, std::uint8_t sub) {
    return (static_cast<std::uint32_t>(index) << 8) | sub;
  }
  [[nodiscard]] std::size_t first_at_or_after(std::uint32_t key) const;
  void insert(ObjectEntry entry);

  std::vector<std::uint32_t> keys_;  // key_of each entry, ascending; beside entries_ for the search
  std::vector<ObjectEntry> entries_;
  std::uint64_t revision_ = 0;
};

}  // namespace planter::canopen
