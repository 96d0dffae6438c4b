// NMEA 0183 as the simulator writes it and the log check reads it (config/nmea.h).
#include "config/nmea.h"

#include <gtest/gtest.h>

#include <sstream>

namespace planter::config {
namespace {

TEST(Nmea, ChecksumIsTheXorBetweenDollarAndStar) {
  // The GGA example that NMEA primers quote, with its stated checksum 0x47.
  EXPECT_EQ(nmea_checksum("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"), 0x47);
}

TEST(Nmea, WhatTheSimulatorWritesReadsBack) {
  hal::GnssFix f;
  f.mode = hal::GnssMode::k3D;
  f.satellites = 12;
  f.hdop = 0.9;
  f.speed_mps = 0.0612;
  f.track_deg = 91.3;
  f.lat_deg = -36.7123456;
  f.lon_deg = 117.5098765;
  const std::string text = nmea_sentences(f, 1777622400.0 + 3723.45);  // 09:02:03.45
  const std::string rmc = text.substr(0, text.find('\n') + 1);
  std::string why;
  const auto r = parse_nmea_rmc(rmc, why);
  ASSERT_TRUE(r) << why << ": " << rmc;
  EXPECT_TRUE(r->valid);
  EXPECT_NEAR(r->time_of_day_s, 9 * 3600 + 2 * 60 + 3.45, 1e-6);
  EXPECT_NEAR(r->speed_mps, 0.0612, 0.0006);  // three decimals of a knot
  EXPECT_NEAR(r->track_deg, 91.3, 1e-9);
  EXPECT_NEAR(r->lat_deg, -36.7123456, 1e-6);
  EXPECT_NEAR(r->lon_deg, 117.5098765, 1e-6);
  std::istringstream log(text);
  const NmeaLogCheck c = check_nmea_log(log, 1.0);
  EXPECT_EQ(c.sentences, 2u);
  EXPECT_EQ(c.problem_count, 0u);
}

TEST(Nmea, ABrokenSentenceIsRefusedWithItsReason) {
  std::string why;
  EXPECT_FALSE(parse_nmea_rmc(
      "$GPRMC,080000.00,A,3641.99940,N,11730.00122,E,0.040,210.51,010526,,,A*00", why));
  EXPECT_NE(why.find("checksum 00"), std::string::npos) << why;
  EXPECT_FALSE(parse_nmea_rmc("GPRMC,080000.00", why));
  EXPECT_FALSE(parse_nmea_rmc("$GPRMC,080000.00*", why));
  std::istringstream log("$GPRMC,080000.00,V,,,,,,,010526,,,N*75\r\nnoise\r\n");
  const NmeaLogCheck c = check_nmea_log(log, 1.0);
  EXPECT_EQ(c.problem_count, 1u);
  ASSERT_EQ(c.problems.size(), 1u);
  EXPECT_EQ(c.problems[0].rfind("line 2: ", 0), 0u) << c.problems[0];
}

}  // namespace
}  // namespace planter::config
