// Who may command the machine from the console, on a clock the test moves: the login limits,
// session expiry, roles, the command rate, the loop's command channel, and a full disk under
// the audit log.
#include "console/operator_sessions.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <atomic>
#include <set>
#include <thread>

#include "console/audit_log.h"
#include "console/command_channel.h"
#include "console/console_server.h"

namespace planter::console {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

struct Fixture {
  std::int64_t now = 0;
  SessionPolicy policy;
  OperatorSessions sessions{Secrets{"abcde-fghij-kmnpq", "viewer-secret-1234"}, policy,
                            [this] { return now; }};
};

TEST(OperatorSessions, FiveWrongSecretsThenEvenTheRightOneWaitsForTheWindow) {
  Fixture f;
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(f.sessions.login("10.0.0.9", "guess").status, LoginResult::Status::kWrongSecret);
  const LoginResult limited = f.sessions.login("10.0.0.9", "abcde-fghij-kmnpq");
  EXPECT_EQ(limited.status, LoginResult::Status::kRateLimited);
  EXPECT_GT(limited.retry_after_s, 59.0);
  EXPECT_TRUE(limited.token.empty());
  // Another address is not held back by this one's guesses.
  EXPECT_EQ(f.sessions.login("10.0.0.10", "abcde-fghij-kmnpq").status, LoginResult::Status::kOk);
  f.now += 61 * kSecond;
  EXPECT_EQ(f.sessions.login("10.0.0.9", "abcde-fghij-kmnpq").status, LoginResult::Status::kOk);
}

TEST(OperatorSessions, GuessesFromManyAddressesAreLimitedInTotal) {
  Fixture f;
  for (int i = 0; i < 20; ++i)
    f.sessions.login("10.0.1." + std::to_string(i),
                     "guess");  // 1 each: under the per-address limit
  EXPECT_EQ(f.sessions.login("10.0.2.1", "abcde-fghij-kmnpq").status,
            LoginResult::Status::kRateLimited);
}

TEST(OperatorSessions, TheSecretIsTypedAsPeopleTypeIt) {
  Fixture f;
  const LoginResult r = f.sessions.login("a", "ABCDE FGHIJ KMNPQ");
  ASSERT_EQ(r.status, LoginResult::Status::kOk);
  EXPECT_EQ(r.role, Role::kOperator);
  EXPECT_EQ(f.sessions.login("a", "viewer-secret-1234").role, Role::kViewer);
  EXPECT_EQ(f.sessions.login("a", "abcde-fghij-kmnp").status, LoginResult::Status::kWrongSecret);
  EXPECT_EQ(f.sessions.login("a", "").status, LoginResult::Status::kWrongSecret);
}

TEST(OperatorSessions, ASessionEndsAfterItsIdleTimeAndAfterItsDay) {
  Fixture f;
  const LoginResult r = f.sessions.login("a", "abcde-fghij-kmnpq");
  f.now += 14 * 60 * kSecond;
  ASSERT_TRUE(f.sessions.find(r.token));  // used: the idle time starts again
  f.now += 14 * 60 * kSecond;
  ASSERT_TRUE(f.sessions.find(r.token));
  f.now += 15 * 60 * kSecond;
  EXPECT_FALSE(f.sessions.find(r.token)) << "15 min idle";
  const LoginResult busy = f.sessions.login("a", "abcde-fghij-kmnpq");
  for (int i = 0; i < 12 * 6; ++i) {
    f.now += 10 * 60 * kSecond;
    if (!f.sessions.find(busy.token)) {
      EXPECT_GE(i, 12 * 6 - 1) << "ended before 12 h";
      return;
    }
  }
  FAIL() << "a session used every 10 min outlived 12 h";
}

TEST(OperatorSessions, TokensAreRandomAndTheAuditNameIsNotPartOfTheToken) {
  Fixture f;
  std::set<std::string> tokens;
  for (int i = 0; i < 50; ++i) {
    const LoginResult r = f.sessions.login("a", "abcde-fghij-kmnpq");
    EXPECT_EQ(r.token.size(), 43u);
    EXPECT_NE(r.token, r.csrf);
    EXPECT_EQ(r.token.find(r.id), std::string::npos);
    tokens.insert(r.token);
  }
  EXPECT_EQ(tokens.size(), 50u);
  const std::string s = OperatorSessions::new_secret();
  EXPECT_EQ(s.size(), 23u);
  EXPECT_EQ(s.find_first_of("01ilo"), std::string::npos);
  EXPECT_NE(s, OperatorSessions::new_secret());
}

TEST(OperatorSessions, CommandsAreLimitedPerSession) {
  Fixture f;
  const std::string token = f.sessions.login("a", "abcde-fghij-kmnpq").token;
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(f.sessions.take_command(token));
  EXPECT_FALSE(f.sessions.take_command(token));
  f.now += 10 * kSecond;
  EXPECT_TRUE(f.sessions.take_command(token));
  f.sessions.logout(token);
  EXPECT_FALSE(f.sessions.find(token));
  EXPECT_FALSE(f.sessions.take_command(token));
}

TEST(CommandChannel, TheLoopAnswersEachRequestAndSilenceIsSaid) {
  CommandChannel channel;
  ConsoleReply none = channel.submit(ConsoleCommandKind::kRun, 0, std::chrono::milliseconds(20));
  EXPECT_EQ(none.result, ConsoleResult::kNoAnswer);
  EXPECT_NE(std::string(none.text).find("did not answer"), std::string::npos);
  std::atomic<bool> stop{false};
  std::thread loop([&] {
    while (!stop) {
      channel.serve([](const ConsoleRequest& req, ConsoleReply& reply) {
        reply.result = req.value > 100 ? ConsoleResult::kOutOfRange : ConsoleResult::kAccepted;
        reply.say(command_name(req.kind));
      });
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  // The unanswered run above is answered late and must not be taken for this one.
  ConsoleReply depth = channel.submit(ConsoleCommandKind::kSetDepth, 90, std::chrono::seconds(2));
  EXPECT_EQ(depth.result, ConsoleResult::kAccepted);
  ConsoleReply far = channel.submit(ConsoleCommandKind::kSetDepth, 300, std::chrono::seconds(2));
  EXPECT_EQ(far.result, ConsoleResult::kOutOfRange);
  EXPECT_STREQ(far.text, "set_depth_mm");
  stop = true;
  loop.join();
  ConsoleCommandKind kind{};
  EXPECT_TRUE(parse_command_name("record_start", kind));
  EXPECT_EQ(kind, ConsoleCommandKind::kRecordStart);
  EXPECT_FALSE(parse_command_name("set_depth", kind));
}

// A full disk (/dev/full) under the audit log: the write is seen to fail, and from then the
// console gives no command, saying which file; nothing reaches the loop.
TEST(AuditLog, AFullDiskIsSeenAndThenNoCommandIsGiven) {
  {
    AuditLog log("/dev/full");
    EXPECT_FALSE(log.append("10.0.0.1", "-", "login", "-", "wrong secret"));
    EXPECT_FALSE(log.ok());
  }
  CommandChannel channel;
  ConsoleOptions o;
  o.port = 0;
  o.commands = &channel;
  o.audit_log = "/dev/full";
  o.secrets.pairing = "abcde-fghij-kmnpq";
  ConsoleInfo info;
  info.depth_range_mm = {40, 160, false};
  ConsoleServer server(o, info);
  server.start();
  httplib::Client cli("127.0.0.1", server.port());
  auto login = cli.Post("/api/login", R"({"secret":"abcde-fghij-kmnpq"})", "application/json");
  ASSERT_TRUE(login);
  ASSERT_EQ(login->status, 200);  // logging in is no command; its audit line failed
  const std::string cookie = login->get_header_value("Set-Cookie");
  const auto at = login->body.find("\"csrf\":\"");
  ASSERT_NE(at, std::string::npos);
  const httplib::Headers headers = {{"Cookie", cookie.substr(0, cookie.find(';'))},
                                    {"X-CSRF-Token", login->body.substr(at + 8, 43)}};
  std::atomic<int> served{0};
  std::atomic<bool> stop{false};
  std::thread loop([&] {
    while (!stop) {
      channel.serve([&](const ConsoleRequest&, ConsoleReply& reply) {
        ++served;
        reply.result = ConsoleResult::kAccepted;
      });
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  auto command = cli.Post("/api/command", headers, R"({"command":"stop"})", "application/json");
  stop = true;
  loop.join();
  server.stop();
  ASSERT_TRUE(command);
  EXPECT_EQ(command->status, 503);
  EXPECT_NE(command->body.find("/dev/full cannot be written"), std::string::npos) << command->body;
  EXPECT_EQ(served.load(), 0) << "a command went to the loop with no audit line possible";
}

}  // namespace
}  // namespace planter::console
