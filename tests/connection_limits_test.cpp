// Who may hold a console connection (console/connection_limits.h): a cap per address and in all,
// and the operator's address past the total, so others' connections cannot keep it from Stop.
#include "console/connection_limits.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "console/client_address.h"

namespace planter::console {
namespace {

TEST(ConnectionLimits, OneAddressGetsItsShareAndNoMore) {
  ConnectionLimits limits(ConnectionCaps{3, 10, 2});
  std::vector<Ticket> held;
  for (int i = 0; i < 3; ++i) held.push_back(limits.admit("10.0.0.9"));
  for (const Ticket& t : held) EXPECT_EQ(t.admission, Admission::kAdmitted);
  EXPECT_EQ(limits.admit("10.0.0.9").admission, Admission::kAddressFull);
  EXPECT_EQ(limits.admit("10.0.0.8").admission, Admission::kAdmitted) << "another address";
  limits.release("10.0.0.9", held.back());
  EXPECT_EQ(limits.admit("10.0.0.9").admission, Admission::kAdmitted) << "a slot given back";
}

TEST(ConnectionLimits, ACrowdFillsTheTotalButNotTheOperatorsWay) {
  ConnectionLimits limits(ConnectionCaps{2, 4, 2});
  limits.remember_operator("192.168.1.20");
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < 2; ++i)
      EXPECT_EQ(limits.admit("10.0.0." + std::to_string(a)).admission, Admission::kAdmitted);
  EXPECT_EQ(limits.admit("10.0.0.7").admission, Admission::kServerFull);
  const Ticket op = limits.admit("192.168.1.20");
  EXPECT_EQ(op.admission, Admission::kAdmitted);
  EXPECT_FALSE(op.counted);
  EXPECT_EQ(limits.admit("192.168.1.20").admission, Admission::kAdmitted);
  EXPECT_EQ(limits.admit("192.168.1.20").admission, Admission::kAddressFull)
      << "the operator's own share is capped too";
  EXPECT_EQ(limits.open(), 6u);
  // Its connection given back does not free a slot of the total for the crowd.
  limits.release("192.168.1.20", op);
  EXPECT_EQ(limits.admit("10.0.0.7").admission, Admission::kServerFull);
}

TEST(ConnectionLimits, OnlyTheNewestOperatorsAreRemembered) {
  ConnectionLimits limits(ConnectionCaps{1, 1, 2});
  ASSERT_EQ(limits.admit("10.0.0.1").admission, Admission::kAdmitted);  // the total is full
  for (const char* a : {"a", "b", "c"}) limits.remember_operator(a);
  EXPECT_EQ(limits.admit("a").admission, Admission::kServerFull) << "forgotten";
  EXPECT_EQ(limits.admit("b").admission, Admission::kAdmitted);
  EXPECT_EQ(limits.admit("c").admission, Admission::kAdmitted);
}

TEST(ConnectionLimits, ATicketCountedOnceIsGivenBackOnceWhateverHappenedBetween) {
  ConnectionLimits limits(ConnectionCaps{4, 1, 2});
  const Ticket t = limits.admit("10.0.0.1");
  ASSERT_TRUE(t.counted);
  limits.remember_operator("10.0.0.1");  // logged in while connected
  limits.release("10.0.0.1", t);
  EXPECT_EQ(limits.open(), 0u);
  EXPECT_EQ(limits.admit("10.0.0.2").admission, Admission::kAdmitted) << "the total is free";
  limits.release("10.0.0.3", Ticket{});  // a refused one gives nothing back
  EXPECT_EQ(limits.admit("10.0.0.4").admission, Admission::kServerFull);
}

// Issue 53, item 2: 8 addresses each holding idle connections filled the total, and the
// operator's first login (an address not yet remembered) got 503 every time.
TEST(ConnectionLimits, AFullServerCutsAnIdleConnectionOfTheAddressHoldingMostForANewcomer) {
  std::vector<int> cut;
  ConnectionLimits limits(ConnectionCaps{8, 32, 8}, [&](int sock) { cut.push_back(sock); });
  std::vector<Ticket> crowd;
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 8; ++a) {
      crowd.push_back(limits.admit("10.0.0." + std::to_string(a), 100 + 10 * a + k));
      ASSERT_EQ(crowd.back().admission, Admission::kAdmitted);
    }
  // Busy (reading a request): no slot is taken from a connection at work.
  EXPECT_EQ(limits.admit("192.168.1.20", 7).admission, Admission::kServerFull);
  for (const Ticket& t : crowd) ASSERT_TRUE(limits.set_idle(t, true));
  // The crowd's own addresses hold 4 each: none takes another's slot, so they do not churn.
  EXPECT_EQ(limits.admit("10.0.0.3", 99).admission, Admission::kServerFull);
  const Ticket first_login = limits.admit("192.168.1.20", 7);
  EXPECT_EQ(first_login.admission, Admission::kAdmitted);
  ASSERT_EQ(cut.size(), 1u);
  EXPECT_EQ(cut[0], 100) << "the oldest idle connection of an address holding the most";
  EXPECT_FALSE(limits.set_idle(crowd[0], false)) << "the cut connection is told to end";
  EXPECT_EQ(limits.open(), 32u);
  limits.release("10.0.0.0", crowd[0]);  // its worker ends it: nothing counted twice
  EXPECT_EQ(limits.open(), 32u);
  // A second viewer gets in too, from another address holding the most.
  EXPECT_EQ(limits.admit("192.168.1.30", 8).admission, Admission::kAdmitted);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_NE(cut[1], 100);
  EXPECT_TRUE(limits.set_idle(first_login, true));
  limits.release("192.168.1.20", first_login);
  EXPECT_EQ(limits.open(), 31u);
}

// Issue 53, item 10: what a per-address limit counts, and an address in a URL.
TEST(ClientAddress, AnIpv6HostCountsAsItsSlash64AndLoopbackAsOne) {
  EXPECT_EQ(client_key("192.168.1.20"), "192.168.1.20");
  EXPECT_EQ(client_key("2001:db8:1:2:aaaa:bbbb:cccc:dddd"), "2001:db8:1:2::/64");
  EXPECT_EQ(client_key("2001:db8:1:2::9"), "2001:db8:1:2::/64") << "a privacy address, same /64";
  EXPECT_NE(client_key("2001:db8:1:3::9"), client_key("2001:db8:1:2::9"));
  EXPECT_EQ(client_key("::ffff:10.0.0.7"), "10.0.0.7");
  EXPECT_EQ(client_key("::1"), client_key("127.0.0.1"));
  EXPECT_EQ(client_key("not an address"), "not an address");
  EXPECT_EQ(url_host("::1"), "[::1]");
  EXPECT_EQ(url_host("::"), "[::]");
  EXPECT_EQ(url_host("0.0.0.0"), "0.0.0.0");
}

TEST(ClientAddress, ASlash64SharesOneCapWhateverAddressesItTakes) {
  ConnectionLimits limits(ConnectionCaps{2, 32, 2});
  EXPECT_EQ(limits.admit(client_key("2001:db8::1")).admission, Admission::kAdmitted);
  EXPECT_EQ(limits.admit(client_key("2001:db8::2")).admission, Admission::kAdmitted);
  EXPECT_EQ(limits.admit(client_key("2001:db8::3")).admission, Admission::kAddressFull);
  EXPECT_EQ(limits.admit(client_key("2001:db8:0:1::3")).admission, Admission::kAdmitted);
}

}  // namespace
}  // namespace planter::console
