// Fuzz target: the Slurm job array's script (plan/executor.h) from the values a user gives
// (--partition, --account, --time-limit, --sbatch-args, --out, the work's label, the throttle).
// Issue 53, item 1: a newline in a value became a shell line and dropped the directives after
// it. Either the values are refused, or the script has the template's lines and no others:
// each directive once, in order, with its value whole, and nothing after the directives but
// the loop.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "plan/executor.h"

namespace {
std::vector<std::string> parts_of(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> parts(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0xff)
      parts.emplace_back();
    else
      parts.back() += static_cast<char>(data[i]);
  }
  parts.resize(7);
  return parts;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace planter::plan;
  const std::vector<std::string> p = parts_of(data, size);
  ExecutorOptions o;
  o.kind = "slurm";
  o.plan_only = true;  // no sbatch looked for on PATH
  o.partition = p[0], o.account = p[1], o.time_limit = p[2], o.sbatch_args = p[3];
  o.throttle = p[6].empty() ? 0 : static_cast<unsigned char>(p[6][0]) % 8;
  PlanRuns runs;
  runs.dir = p[4].empty() ? "out" : p[4];
  runs.task_command = "planter-sim plan-run out/plan.json";
  if (!executor_refusal(o).empty() || !control_character_refusal("dir", runs.dir).empty()) return 0;
  const std::string script = sbatch_script(runs, 3, o, p[5], o.time_limit);
  std::vector<std::string> want = {"#SBATCH --job-name=", "#SBATCH --array=0-2",
                                   "#SBATCH --output=" + runs.dir + "/logs/task-%5a.slurm.log",
                                   "#SBATCH --ntasks=1", "#SBATCH --cpus-per-task=1"};
  if (!o.partition.empty()) want.push_back("#SBATCH --partition=" + o.partition);
  if (!o.account.empty()) want.push_back("#SBATCH --account=" + o.account);
  if (!o.time_limit.empty()) want.push_back("#SBATCH --time=" + o.time_limit);
  std::vector<std::string> directives;
  std::size_t after = 0;  // lines after the last directive
  for (const std::string& l : lines_of(script)) {
    if (l.rfind("#SBATCH", 0) == 0) {
      if (after > 0) std::abort();  // a directive after a shell line: sbatch ignores it
      directives.push_back(l);
    } else if (!directives.empty()) {
      ++after;
    }
  }
  if (directives.size() != want.size() || after != 5) std::abort();
  for (std::size_t i = 0; i < want.size(); ++i) {
    const bool prefix_only = i < 2;  // the job name is cleaned; the array's throttle may follow
    if (prefix_only ? directives[i].rfind(want[i], 0) != 0 : directives[i] != want[i]) std::abort();
  }
  return 0;
}
