// Who may command the machine from the console, on a clock the test moves: the login limits,
// session expiry, roles, the command rate, the loop's command channel, and a full disk under
// the audit log.
#include "console/operator_sessions.h"

#include <gtest/gtest.h>
#include <httplib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <thread>

#include "console/audit_log.h"
#include "console/command_channel.h"
#include "console/console_server.h"
#include "console/recording_control.h"
#include "console/refused_logins.h"

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

// Issue 28, item 3: wrong secrets from 8 addresses at 10 a second kept the operator out.
TEST(OperatorSessions, AFloodFromManyAddressesIsLimitedButNeverLocksTheOperatorOut) {
  Fixture f;
  for (int i = 0; i < 8 * 150; ++i) {
    f.now += kSecond / 10;
    f.sessions.login("10.0.1." + std::to_string(i % 8), "guess");
    if (i % 40 == 39) {  // the operator, every 4 s, from the phone's own address
      const LoginResult r = f.sessions.login("10.0.9.9", "abcde-fghij-kmnpq");
      ASSERT_EQ(r.status, LoginResult::Status::kOk) << "at " << i;
      EXPECT_EQ(r.role, Role::kOperator);
    }
  }
  // Past the total, a wrong secret from a fresh address is refused as rate-limited.
  for (int i = 0; i < 20; ++i) f.sessions.login("10.0.3." + std::to_string(i), "guess");
  EXPECT_EQ(f.sessions.login("10.0.4.1", "guess").status, LoginResult::Status::kRateLimited);
  EXPECT_EQ(f.sessions.login("10.0.4.2", "abcde-fghij-kmnpq").status, LoginResult::Status::kOk);
}

// Issue 28, item 5: 70 viewer logins in 0.85 s evicted an idle operator session.
TEST(OperatorSessions, ViewerLoginsNeverEndAnOperatorsSessionAndLoginsAreLimited) {
  Fixture f;
  const LoginResult op = f.sessions.login("10.0.0.1", "abcde-fghij-kmnpq");
  ASSERT_EQ(op.status, LoginResult::Status::kOk);
  int ok = 0, limited = 0;
  for (int i = 0; i < 700; ++i) {
    const auto r = f.sessions.login("10.0.5." + std::to_string(i % 70), "viewer-secret-1234");
    ok += r.status == LoginResult::Status::kOk;
    limited += r.status == LoginResult::Status::kTooManyLogins;
  }
  EXPECT_EQ(ok, 700) << "10 per address, under the 20 a minute allowed";
  EXPECT_TRUE(f.sessions.find(op.token).has_value()) << "the operator's session was evicted";
  for (int i = 0; i < 20; ++i) f.sessions.login("10.0.6.1", "viewer-secret-1234");
  EXPECT_EQ(f.sessions.login("10.0.6.1", "viewer-secret-1234").status,
            LoginResult::Status::kTooManyLogins);
  EXPECT_EQ(limited, 0);
}

TEST(RefusedLoginTally, AFloodIsOneLineAMinuteAndTheFirstRefusalIsSaidAtOnce) {
  RefusedLoginTally tally(60.0);
  const auto first = tally.add("10.0.0.1", "wrong secret", 0);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->words, "wrong secret");
  int lines = 1;
  // 680 refusals a second for 10 minutes, from 8 addresses.
  for (std::int64_t i = 1; i < 680 * 600; ++i)
    lines += tally
                 .add("10.0.1." + std::to_string(i % 8), i % 3 ? "wrong secret" : "too many x",
                      i * kSecond / 680)
                 .has_value();
  const auto rest = tally.take(600 * kSecond);
  lines += rest.has_value();
  EXPECT_LE(lines, 12) << "10 minutes";
  ASSERT_TRUE(rest.has_value());
  EXPECT_EQ(rest->address, "-");
  EXPECT_NE(rest->words.find("from 8 addresses"), std::string::npos) << rest->words;
  EXPECT_FALSE(tally.take(601 * kSecond).has_value());
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
    f.now += 10 * kSecond;  // within the limit on logins per address
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
  EXPECT_NE(login->body.find("only stop is taken"), std::string::npos) << login->body;
  auto depth = cli.Post("/api/command", headers, R"({"command":"set_depth_mm","value":90})",
                        "application/json");
  ASSERT_TRUE(depth);
  EXPECT_EQ(depth->status, 503);
  EXPECT_NE(depth->body.find("/dev/full cannot be written"), std::string::npos) << depth->body;
  EXPECT_EQ(served.load(), 0) << "a command went to the loop with no audit line possible";
  // Issue 28, item 3: stop is never refused for want of an audit log.
  auto command = cli.Post("/api/command", headers, R"({"command":"stop"})", "application/json");
  stop = true;
  loop.join();
  server.stop();
  ASSERT_TRUE(command);
  EXPECT_EQ(command->status, 200) << command->body;
  EXPECT_NE(command->body.find("cannot be written: only stop is taken"), std::string::npos)
      << command->body;
  EXPECT_EQ(served.load(), 1);
}

// Issue 28, item 3: the log's last line was cut when the disk filled; item 7: a FIFO held the
// console's start with no word.
TEST(AuditLog, ALineThatDoesNotFitIsTakenBackAndAFifoIsRefused) {
  const std::string dir =
      std::filesystem::temp_directory_path() / ("planter-audit-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string fifo = dir + "/fifo.log";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(AuditLog{fifo}, std::runtime_error);
  const std::string path = dir + "/audit.log";
  {
    AuditLog log(path);
    ASSERT_TRUE(log.append("10.0.0.1", "-", "login", "-", "logged in as operator"));
    const auto size = std::filesystem::file_size(path);
    // A file-size limit just past the first line stands for the full disk: the second line's
    // write stops part-way (EFBIG).
    rlimit old{};
    getrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = size + 20;
    setrlimit(RLIMIT_FSIZE, &small);
    const bool second = log.append("10.0.0.1", "abc", "set_depth_mm", "90", "accepted");
    setrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, SIG_DFL);
    EXPECT_FALSE(second);
    EXPECT_EQ(std::filesystem::file_size(path), size) << "a cut line was left";
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace planter::console

namespace planter::console {
namespace {

// Issue 28, item 4: with Host and Origin both evil.example:PORT, state, history and the
// recordings list answered 200 (DNS rebinding).
TEST(ConsoleServer, AHostThatIsNotThisMachineIsRefusedBeforeAnyRoute) {
  ConsoleOptions o;
  o.port = 0;
  ConsoleInfo info;
  ConsoleServer server(o, info);
  server.start();
  httplib::Client cli("127.0.0.1", server.port());
  const std::string port = std::to_string(server.port());
  for (const char* path : {"/api/state", "/api/history", "/api/info", "/"}) {
    auto evil = cli.Get(
        path, {{"Host", "evil.example:" + port}, {"Origin", "http://evil.example:" + port}});
    ASSERT_TRUE(evil);
    EXPECT_EQ(evil->status, 421) << path;
    // It names none of the names it answers to (a rebinding page reads the body).
    EXPECT_NE(evil->body.find("not reached by that name"), std::string::npos) << evil->body;
    EXPECT_EQ(evil->body.find("127.0.0.1"), std::string::npos) << evil->body;
    EXPECT_EQ(evil->body.find("localhost"), std::string::npos) << evil->body;
    auto own = cli.Get(path, {{"Host", "127.0.0.1:" + port}});
    ASSERT_TRUE(own);
    EXPECT_EQ(own->status, 200) << path;
  }
  auto local = cli.Get("/api/info", {{"Host", "LOCALHOST:" + port}});
  ASSERT_TRUE(local);
  EXPECT_EQ(local->status, 200);
  server.stop();
}

}  // namespace
}  // namespace planter::console

namespace planter::console {
namespace {

// Issue 28, item 7: start, stop, start within a second replaced the first recording.
TEST(Recordings, TwoStartsWithinASecondGetTwoNames) {
  const std::string a = recording_file_name("live"), b = recording_file_name("live");
  EXPECT_NE(a, b);
  EXPECT_TRUE(std::regex_match(a, std::regex(R"(live-\d{8}T\d{6}\.\d{3}Z-\d+\.csv)"))) << a;
}

}  // namespace
}  // namespace planter::console

namespace planter::console {
namespace {

// Issue 28, item 6: with no client for 150 s, the first state was 48 s old and the history had
// silent gaps: the loop's samples waited for a request to be moved, and the queue dropped the
// new ones when full. 3000 samples in 3 s (three queues full) with no client: every one kept.
TEST(ConsoleServer, SamplesAreKeptWhileNoOneIsLooking) {
  ConsoleOptions o;
  o.port = 0;
  ConsoleInfo info;
  ConsoleServer server(o, info);
  server.start();
  for (int i = 0; i < 3000; ++i) {
    LiveSample s;
    s.t_s = 0.001 * i;
    ASSERT_TRUE(server.publish(s)) << "sample " << i << " dropped";
    std::this_thread::sleep_for(std::chrono::microseconds(1000));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  httplib::Client cli("127.0.0.1", server.port());
  auto history = cli.Get("/api/history");
  server.stop();
  ASSERT_TRUE(history);
  const auto j = nlohmann::json::parse(history->body);
  ASSERT_EQ(j["t_s"].size(), 3000u);
  EXPECT_DOUBLE_EQ(j["t_s"].back().get<double>(), 2.999);
  EXPECT_EQ(server.dropped(), 0u);
}

}  // namespace
}  // namespace planter::console
