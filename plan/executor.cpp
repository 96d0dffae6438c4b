#include "plan/executor.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "config/durable_file.h"
#include "config/output_set.h"

namespace planter::plan {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The last line of a log, for the failure's message.
std::string last_line(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last.empty() ? "(empty log)" : last;
}

// A line on a terminal, rewritten as the runs finish; nothing on a log or a pipe.
class Progress {
 public:
  Progress(std::string label, std::size_t total)
      : label_(std::move(label)), total_(total), show_(!label_.empty() && ::isatty(2) == 1) {}
  void update(std::size_t done, std::size_t running, std::size_t failed) {
    if (!show_) return;
    const double s = std::chrono::duration<double>(Clock::now() - start_).count();
    std::fprintf(stderr, "\r%s: %zu of %zu runs done, %zu running, %zu failed", label_.c_str(),
                 done, total_, running, failed);
    if (done > done_at_start_ && done < total_)
      std::fprintf(
          stderr, ", about %.0f s left",
          s / static_cast<double>(done - done_at_start_) * static_cast<double>(total_ - done));
    std::fprintf(stderr, "\x1b[K");
  }
  void start(std::size_t done) { done_at_start_ = done; }
  ~Progress() {
    if (show_) std::fprintf(stderr, "\n");
  }

 private:
  std::string label_;
  std::size_t total_;
  bool show_;
  std::size_t done_at_start_ = 0;
  Clock::time_point start_ = Clock::now();
};

std::vector<std::size_t> missing_runs(const PlanRuns& runs) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < runs.count; ++i)
    if (!runs.complete(i)) out.push_back(i);
  return out;
}

struct Failure {
  std::size_t index;
  std::string what, log;
};

[[noreturn]] void throw_failures(const std::vector<Failure>& failures, std::size_t total,
                                 const std::string& dir) {
  std::ostringstream m;
  m << failures.size() << " of " << total << " runs of the plan in " << dir << " failed; the "
    << total - failures.size() << " complete are kept, and running the same command again runs "
    << "only the missing ones:";
  for (std::size_t k = 0; k < failures.size() && k < 10; ++k) {
    m << "\n  run " << failures[k].index << ": " << failures[k].what;
    if (!failures[k].log.empty())
      m << " (" << failures[k].log << ": " << last_line(failures[k].log) << ")";
  }
  if (failures.size() > 10) m << "\n  ...";
  throw std::runtime_error(m.str());
}

void run_local(const PlanRuns& runs, const std::vector<std::size_t>& todo, const ExecutorOptions& o,
               Progress& progress, std::size_t done_before) {
  const int jobs =
      o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::atomic<std::size_t> next{0}, done{done_before}, running{0};
  std::mutex mutex;
  std::vector<Failure> failures;
  auto worker = [&] {
    for (std::size_t k = next++; k < todo.size(); k = next++) {
      ++running;
      try {
        runs.run_here(todo[k]);
        ++done;
      } catch (const std::exception& e) {
        const std::lock_guard<std::mutex> lock(mutex);
        failures.push_back({todo[k], e.what(), ""});
      }
      --running;
      const std::lock_guard<std::mutex> lock(mutex);
      progress.update(done, running, failures.size());
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (!failures.empty()) {
    std::sort(failures.begin(), failures.end(),
              [](const Failure& a, const Failure& b) { return a.index < b.index; });
    throw_failures(failures, todo.size() + done_before, runs.dir);
  }
}

// The output of a command run through the shell, and its exit status.
std::pair<std::string, int> capture(const std::string& command) {
  std::FILE* p = ::popen(command.c_str(), "r");
  if (p == nullptr) throw std::runtime_error("cannot run: " + command);
  std::string out;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int rc = ::pclose(p);
  return {out, WIFEXITED(rc) ? WEXITSTATUS(rc) : 128};
}

// A program run with these arguments, no shell between (a user's string stays one word):
// its standard output and error together, and its exit status.
std::pair<std::string, int> capture_argv(const std::vector<std::string>& argv) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("cannot run " + argv.front() + ": no pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (spawned != 0) {
    ::close(fds[0]);
    throw std::runtime_error("cannot run " + argv.front() + ": " + std::strerror(spawned));
  }
  std::string out;
  std::array<char, 4096> buf{};
  ssize_t n = 0;
  while ((n = ::read(fds[0], buf.data(), buf.size())) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) out.append(buf.data(), static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return {out, WIFEXITED(status) ? WEXITSTATUS(status) : 128};
}

// Words split at blanks, as --sbatch-args is read (no quotes: no shell reads it).
std::vector<std::string> blank_separated(const std::string& s) {
  std::vector<std::string> words;
  std::istringstream in(s);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// "sweep: clamp force" -> "sweep-clamp-force": a job name is one word of plain characters.
std::string job_name(const std::string& label) {
  std::string name;
  for (char c : label.empty() ? std::string("plan") : label) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
    if (plain)
      name += c;
    else if (!name.empty() && name.back() != '-')
      name += '-';
  }
  return name;
}

// The runs each task of the array executes, `per_task` at a time, in the plan's order.
std::vector<std::vector<std::size_t>> tasks_of(const std::vector<std::size_t>& todo,
                                               std::size_t per_task) {
  std::vector<std::vector<std::size_t>> tasks;
  for (std::size_t k = 0; k < todo.size(); k += per_task)
    tasks.emplace_back(
        todo.begin() + static_cast<std::ptrdiff_t>(k),
        todo.begin() + static_cast<std::ptrdiff_t>(std::min(todo.size(), k + per_task)));
  return tasks;
}

std::string task_log(const std::string& dir, std::size_t task) {
  char name[48];
  std::snprintf(name, sizeof name, "/logs/task-%05zu.slurm.log", task);
  return dir + name;
}

// Each array task's state by its index, from "JOB_INDEX<separator>STATE" lines; a state such as
// "CANCELLED by 0" is kept to its first word, and a line for a range of pending tasks
// ("JOB_[5-14%1]") is skipped.
std::map<std::size_t, std::string> parse_task_states(const std::string& job,
                                                     const std::string& text, char separator) {
  std::map<std::size_t, std::string> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t bar = line.find(separator), under = line.find('_');
    if (bar == std::string::npos || under == std::string::npos || under > bar) continue;
    if (line.compare(0, under, job) != 0) continue;
    const std::string index = line.substr(under + 1, bar - under - 1);
    if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string state = line.substr(bar + 1);
    state = state.substr(0, state.find_first_of(" |"));
    out[std::stoul(index)] = state;
  }
  return out;
}

// Every task's state from squeue, one line a task (-r), ended ones included (-t all): squeue
// keeps them for the cluster's MinJobAge (scripts/slurm-cluster.sh keeps them an hour). Empty
// when the job is gone from the controller.
std::map<std::size_t, std::string> queued_states(const std::string& job) {
  const auto [out, rc] = capture("squeue -h -r -t all -j " + job + " -o '%i %T' 2>/dev/null");
  return rc == 0 ? parse_task_states(job, out, ' ') : std::map<std::size_t, std::string>{};
}

// The tasks' final states: from sacct where the cluster keeps accounting, else from squeue.
std::map<std::size_t, std::string> final_states(const std::string& job) {
  const auto [accounted, rc] = capture("sacct -n -P -X -j " + job + " -o JobID,State 2>/dev/null");
  std::map<std::size_t, std::string> out;
  if (rc == 0) out = parse_task_states(job, accounted, '|');
  return out.empty() ? queued_states(job) : out;
}

bool task_alive(const std::string& state) {
  for (const char* s : {"PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "SUSPENDED", "REQUEUED",
                        "RESIZING", "SIGNALING", "STAGE_OUT"})
    if (state == s) return true;
  return false;
}

bool task_failed(const std::string& state) {
  for (const char* s : {"FAILED", "TIMEOUT", "CANCELLED", "NODE_FAIL", "OUT_OF_MEMORY", "BOOT_FAIL",
                        "DEADLINE", "PREEMPTED"})
    if (state == s) return true;
  return false;
}

void run_slurm(const PlanRuns& runs, std::vector<std::size_t> todo, const ExecutorOptions& o,
               const std::string& label, Progress& progress, std::size_t done_before) {
  const std::string& dir = runs.dir;
  std::string time_limit = o.time_limit;
  if (time_limit.empty() && !o.plan_only && !todo.empty()) {
    // A dry run: the first missing run here, timed, sets each task's limit (ten times it, at
    // least a minute): a task that takes ten times longer than its like is stuck.
    const auto t0 = Clock::now();
    ExecutorOptions here = o;
    here.jobs = 1;
    run_local(runs, {todo.front()}, here, progress, done_before);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    const double per_task = static_cast<double>(std::max(1, o.runs_per_task));
    const long minutes = std::max(1L, static_cast<long>(std::ceil(10.0 * s * per_task / 60.0)));
    time_limit = std::to_string(minutes);
    todo.erase(todo.begin());
    ++done_before;
    if (todo.empty()) return;
  }
  // The folder is written into the script's lines: a control character there would end a line.
  if (const std::string why = control_character_refusal("the plan's folder", dir); !why.empty())
    throw std::runtime_error(why);
  const std::string script = dir + "/plan.sbatch";
  const auto tasks = tasks_of(todo, static_cast<std::size_t>(std::max(1, o.runs_per_task)));
  std::string lines;
  for (const auto& task : tasks) {
    for (std::size_t i : task) lines += std::to_string(i) + (i == task.back() ? "\n" : " ");
  }
  config::write_output_file(dir + "/tasks.txt", lines);
  config::write_output_file(script, sbatch_script(runs, tasks.size(), o, label, time_limit));
  if (o.plan_only) throw PlanWritten{dir, "sbatch " + script};
  std::vector<std::string> sbatch{"sbatch", "--parsable"};
  for (std::string& w : blank_separated(o.sbatch_args)) sbatch.push_back(std::move(w));
  sbatch.push_back(script);
  const auto [out, rc] = capture_argv(sbatch);
  if (rc != 0) {
    // sbatch's own words, and what to fix.
    std::string fix = "Slurm is not reachable from here: check `sinfo` (and SLURM_CONF)";
    if (out.find("partition") != std::string::npos) {
      const auto [partitions, listed] = capture("sinfo -h -o %P 2>/dev/null");
      fix =
          "the partitions here: " +
          (listed == 0 && !partitions.empty() ? partitions : std::string("(sinfo answered none)"));
      std::replace(fix.begin(), fix.end(), '\n', ' ');
    }
    throw std::runtime_error("sbatch refused " + script + ": " + out + fix);
  }
  const std::string job = out.substr(0, out.find_first_of(";\n"));
  if (job.empty() || job.find_first_not_of("0123456789") != std::string::npos)
    throw std::runtime_error("sbatch answered '" + out + "', not a job id");
  std::fprintf(stderr, "%s: submitted %zu runs as Slurm job %s, %zu tasks (logs in %s/logs)\n",
               label.empty() ? "plan" : label.c_str(), todo.size(), job.c_str(), tasks.size(),
               dir.c_str());
  for (;;) {
    std::size_t done = done_before;
    for (std::size_t i : todo) done += runs.complete(i) ? 1 : 0;
    // One look at the queue a poll: the tasks still alive, and those that failed so far.
    std::size_t alive = 0, failed = 0;
    for (const auto& [task, state] : queued_states(job)) {
      alive += task_alive(state);
      failed += task_failed(state);
    }
    progress.update(done, alive, failed);
    if (alive == 0) break;
    std::this_thread::sleep_for(std::chrono::duration<double>(o.poll_s));
  }
  const std::map<std::size_t, std::string> states = final_states(job);
  std::vector<Failure> failures;
  for (std::size_t t = 0; t < tasks.size(); ++t) {
    const auto state = states.find(t);
    // A task cancelled while still pending leaves no record: Slurm shrinks the array.
    const std::string ended =
        state == states.end()
            ? "left no result and has no record in Slurm (cancelled before it started, or its "
              "record expired)"
            : "ended " + state->second +
                  (state->second == "TIMEOUT" ? " (raise --time-limit)" : "") +
                  " without its result";
    // A task Slurm ran that left no log never saw the plan's folder.
    const std::string log = task_log(dir, t);
    const bool unseen = state != states.end() && !fs::exists(log);
    for (std::size_t i : tasks[t])
      if (!runs.complete(i))
        failures.push_back({i,
                            "task " + job + "_" + std::to_string(t) + " " + ended +
                                (unseen ? " and wrote no log at " + log +
                                              ": the plan's folder and the program must be on "
                                              "a filesystem the nodes see"
                                        : ""),
                            unseen ? "" : log});
  }
  if (!failures.empty()) throw_failures(failures, todo.size() + done_before, dir);
}

}  // namespace

std::string control_character_refusal(const std::string& what, const std::string& value) {
  for (std::size_t i = 0; i < value.size(); ++i) {
    const auto c = static_cast<unsigned char>(value[i]);
    if (c < 0x20 || c == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02x", c);
      return what + ": a control character (" + code + ") at byte " + std::to_string(i + 1) +
             "; a Slurm script's line cannot carry it, so it is refused";
    }
  }
  return "";
}

std::string sbatch_script(const PlanRuns& runs, std::size_t tasks, const ExecutorOptions& o,
                          const std::string& label, const std::string& time_limit) {
  const std::string& dir = runs.dir;
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# A " << runs.what << " plan as a Slurm job array: each task runs the runs on its line\n"
    << "# of tasks.txt (the runs not yet complete when this was written). Submit with:\n"
    << "# sbatch " << dir << "/plan.sbatch; run the command that wrote it again to follow it\n"
    << "# and gather. Each run writes its output whole or not at all.\n"
    << "#SBATCH --job-name=planter-" << job_name(label) << "\n"
    << "#SBATCH --array=0-" << tasks - 1 << (o.throttle > 0 ? "%" : "")
    << (o.throttle > 0 ? std::to_string(o.throttle) : "") << "\n"
    << "#SBATCH --output=" << dir << "/logs/task-%5a.slurm.log\n"
    << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
  if (!o.partition.empty()) s << "#SBATCH --partition=" << o.partition << "\n";
  if (!o.account.empty()) s << "#SBATCH --account=" << o.account << "\n";
  if (!time_limit.empty()) s << "#SBATCH --time=" << time_limit << "\n";
  s << "status=0\n"
    << "for index in $(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" "
    << shell_quoted(dir + "/tasks.txt") << "); do\n"
    << "  " << runs.task_command << " \"$index\" || status=1\n"
    << "done\n"
    << "exit $status\n";
  return s.str();
}

std::string executor_refusal(const ExecutorOptions& o) {
  if (o.kind != "local" && o.kind != "slurm") return "--executor '" + o.kind + "': local or slurm";
  for (const auto& [option, value] :
       {std::pair<const char*, const std::string&>{"--partition", o.partition},
        {"--account", o.account},
        {"--time-limit", o.time_limit},
        {"--sbatch-args", o.sbatch_args}})
    if (std::string why = control_character_refusal(option, value); !why.empty()) return why;
  if (o.kind == "slurm" && !o.plan_only && capture("command -v sbatch squeue").second != 0)
    return "--executor slurm: sbatch and squeue are not on PATH (Debian: slurm-client; "
           "--plan-only writes the plan and its sbatch script without them)";
  return "";
}

std::string task_program(const ExecutorOptions& o) {
  if (!o.program.empty()) return o.program;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find this program (/proc/self/exe): " + ec.message());
  return self.string();
}

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void execute(const PlanRuns& runs, const ExecutorOptions& o, const std::string& label) {
  config::make_directories(runs.dir + "/logs");
  const std::vector<std::size_t> todo = missing_runs(runs);
  const std::size_t done = runs.count - todo.size();
  Progress progress(label, runs.count);
  progress.start(done);
  if (o.kind == "slurm")
    run_slurm(runs, todo, o, label, progress, done);
  else if (o.plan_only)
    throw PlanWritten{runs.dir, runs.by_hand};
  else if (!todo.empty())
    run_local(runs, todo, o, progress, done);
}

}  // namespace planter::plan
