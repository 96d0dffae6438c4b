#pragma once
// A device's object dictionary: typed entries created at init, read and written afterwards
// without allocation. Used by the simulated nodes and by any device built on this code.
#include <cstdint>
#include <string>
#include <vector>

namespace planter::canopen {

enum class Access : std::uint8_t { kReadOnly, kWriteOnly, kReadWrite, kConst };

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

  [[nodiscard]] ObjectEntry* find(std::uint16_t index, std::uint8_t sub);
  [[nodiscard]] const ObjectEntry* find(std::uint16_t index, std::uint8_t sub) const;
  [[nodiscard]] bool has_index(std::uint16_t index) const;

  // Application access (no access checks): the device's own logic.
  [[nodiscard]] std::uint64_t get(std::uint16_t index, std::uint8_t sub) const;
  [[nodiscard]] std::int64_t get_signed(std::uint16_t index, std::uint8_t sub) const;
  void set(std::uint16_t index, std::uint8_t sub, std::uint64_t value);

 private:
  std::vector<ObjectEntry> entries_;
};

}  // namespace planter::canopen
