#include "firmware/canopen/pdo.h"

#include <gtest/gtest.h>

using namespace planter::canopen;

TEST(Pdo, PackUnpackRoundTripLittleEndian) {
  PdoMapping m;
  m.entries[m.count++] = {0x6041, 0, 16};
  m.entries[m.count++] = {0x606C, 0, 32};
  ASSERT_TRUE(m.valid());
  const std::uint64_t values[2] = {0x0627, static_cast<std::uint32_t>(-1234)};
  std::uint8_t data[8]{};
  ASSERT_EQ(pdo_pack(m, values, data), 6);
  EXPECT_EQ(data[0], 0x27);
  EXPECT_EQ(data[1], 0x06);
  std::uint64_t out[2]{};
  ASSERT_TRUE(pdo_unpack(m, data, 6, out));
  EXPECT_EQ(out[0], 0x0627u);
  EXPECT_EQ(sign_extend(out[1], 32), -1234);
}

TEST(Pdo, ShortFrameIsRejected) {
  PdoMapping m;
  m.entries[m.count++] = {0x6064, 0, 32};
  std::uint8_t data[8]{};
  std::uint64_t out[1]{99};
  EXPECT_FALSE(pdo_unpack(m, data, 3, out));
  EXPECT_EQ(out[0], 99u);
}

TEST(Pdo, MappingValueAndValidity) {
  const PdoEntry e{0x607A, 0, 32};
  EXPECT_EQ(e.mapping_value(), 0x607A0020u);
  EXPECT_EQ(PdoEntry::from_mapping_value(0x71300110u).index, 0x7130);
  PdoMapping m;
  m.entries[m.count++] = {0x6040, 0, 12};
  EXPECT_FALSE(m.valid());
}
