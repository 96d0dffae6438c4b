#include "sim/runner/run_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "config/config_error.h"
#include "config/content_hash.h"
#include "config/durable_file.h"
#include "config/input_file.h"
#include "config/output_set.h"
#include "sim/plant/model_values.h"
#include "sim/runner/disturbance_keys.h"
#include "sim/runner/lockstep_runner.h"
#include "sim/runner/scenario_keys.h"

namespace planter::sim {
namespace {

constexpr const char* kPlanTool = "planter-sim plan-run";

std::string inputs_hash(const std::string& scenario_path, const Scenario& s,
                        const std::string& made_by) {
  std::string all = "made by " + made_by + "\n";
  for (const std::string& f :
       {scenario_path, s.board.file, s.board.machine_file, s.board.calibration_file}) {
    if (f.empty()) continue;
    all += "file " + f + "\n" + config::read_input_file(f) + "\n";
  }
  return config::content_hash(all);
}

}  // namespace

std::string plan_json(const RunPlan& plan) {
  nlohmann::ordered_json j;
  j["kind"] = "planter-sim run plan";
  j["version"] = 1;
  j["scenario"] = plan.scenario;
  j["inputs_hash"] = plan.inputs_hash;
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const PlannedRun& r : plan.runs) {
    nlohmann::ordered_json one;
    one["seed"] = r.seed;
    one["distance_m"] = r.distance_m;
    if (r.operating_point)
      one["operating_point"] = {{"sigma", r.operating_point->sigma},
                                {"depth_mm", r.operating_point->depth_mm},
                                {"contact_area_mm2", r.operating_point->contact_area_mm2}};
    if (r.clamp_setpoint_N) one["clamp_setpoint_N"] = *r.clamp_setpoint_N;
    if (r.per_stem_grip) one["per_stem_grip"] = *r.per_stem_grip;
    if (r.clamp_told_each_stem) one["clamp_told_each_stem"] = true;
    if (!r.values.empty()) {
      nlohmann::ordered_json values;
      for (const auto& [key, value] : r.values) values[key] = value;
      one["values"] = values;
    }
    if (!r.disturbances.empty()) {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const auto& [key, value] : r.disturbances) list.push_back({key, value});
      one["disturbances"] = list;
    }
    runs.push_back(one);
  }
  j["runs"] = runs;
  return j.dump(1) + "\n";
}

namespace {

// A plan's values go through the scenario's key table and its ranges (issue 53, item 3): one
// message naming the plan, the run and the key, and exit 2, as a scenario's would.
class PlanReader {
 public:
  explicit PlanReader(const std::string& path) : path_(path) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw config::ConfigError(path_, 0, where, what);
  }
  const nlohmann::json& field(const nlohmann::json& obj, const char* name,
                              const std::string& where) const {
    if (!obj.is_object() || !obj.contains(name)) fail(where + name, "is missing");
    return obj.at(name);
  }
  double number(const nlohmann::json& v, const std::string& where, double lo, double hi,
                std::string_view unit) const {
    if (!v.is_number()) fail(where, "is not a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%g is outside %g to %g%s%.*s", x, lo, hi,
                    unit.empty() ? "" : " ", static_cast<int>(unit.size()), unit.data());
      fail(where, buf);
    }
    return x;
  }
  // A number by the scenario key it stands for (its range and unit).
  double keyed(const nlohmann::json& v, const std::string& where, std::string_view dotted) const {
    const config::ConfigKey* k = scenario_key(dotted);
    if (k == nullptr) fail(where, "is no scenario key");
    return number(v, where, k->min, k->max, k->unit);
  }
  static const config::ConfigKey* scenario_key(std::string_view dotted) {
    const std::size_t dot = dotted.rfind('.');
    if (dot == std::string_view::npos) return nullptr;
    return config::find_key(kScenarioKeys, dotted.substr(0, dot), dotted.substr(dot + 1));
  }

 private:
  const std::string& path_;
};

PlannedRun read_run(const PlanReader& p, const nlohmann::json& one, std::size_t index) {
  const std::string at = "runs[" + std::to_string(index) + "].";
  PlannedRun r;
  const nlohmann::json& seed = p.field(one, "seed", at);
  if (!seed.is_number_unsigned()) p.fail(at + "seed", "is not a whole number of at least 0");
  r.seed = seed.get<std::uint64_t>();
  r.distance_m = p.keyed(p.field(one, "distance_m", at), at + "distance_m", "route.distance_m");
  if (one.contains("operating_point")) {
    const auto& op = one.at("operating_point");
    const std::string o = at + "operating_point.";
    r.operating_point =
        OperatingPoint{p.keyed(p.field(op, "sigma", o), o + "sigma", "controller.sigma"),
                       p.keyed(p.field(op, "depth_mm", o), o + "depth_mm", "controller.depth_mm"),
                       p.keyed(p.field(op, "contact_area_mm2", o), o + "contact_area_mm2",
                               "mechanism.contact_area_mm2")};
  }
  if (one.contains("clamp_setpoint_N"))
    r.clamp_setpoint_N =
        p.keyed(one.at("clamp_setpoint_N"), at + "clamp_setpoint_N", "controller.clamp_force_N");
  if (one.contains("per_stem_grip")) {
    if (!one.at("per_stem_grip").is_boolean()) p.fail(at + "per_stem_grip", "is not true or false");
    r.per_stem_grip = one.at("per_stem_grip").get<bool>();
  }
  if (one.contains("clamp_told_each_stem")) {
    if (!one.at("clamp_told_each_stem").is_boolean())
      p.fail(at + "clamp_told_each_stem", "is not true or false");
    r.clamp_told_each_stem = one.at("clamp_told_each_stem").get<bool>();
  }
  if (one.contains("values")) {
    if (!one.at("values").is_object()) p.fail(at + "values", "is not an object of numbers");
    for (const auto& item : one.at("values").items()) {
      // Named copies, not a structured binding: clang 14 does not let a lambda capture one.
      const std::string key = item.key();
      const nlohmann::json& value = item.value();
      const auto values = model_values();
      const auto it = std::find_if(values.begin(), values.end(),
                                   [&](const ModelValue& v) { return key == v.key; });
      if (it == values.end()) p.fail(at + "values." + key, "is no model value");
      const config::ConfigKey* k = PlanReader::scenario_key(key);
      r.values.emplace_back(key,
                            k ? p.keyed(value, at + "values." + key, key)
                              : p.number(value, at + "values." + key, it->low, it->high, it->unit));
    }
  }
  if (one.contains("disturbances")) {
    if (!one.at("disturbances").is_array()) p.fail(at + "disturbances", "is not a list");
    for (const auto& pair : one.at("disturbances")) {
      if (!pair.is_array() || pair.size() != 2 || !pair.at(0).is_string() ||
          !pair.at(1).is_number())
        p.fail(at + "disturbances", "holds an entry that is not [\"key\", number]");
      const std::string key = pair.at(0).get<std::string>();
      const auto keys = disturbance_keys();
      const auto it = std::find_if(keys.begin(), keys.end(),
                                   [&](const DisturbanceKey& k) { return k.key == key; });
      if (it == keys.end()) p.fail(at + "disturbances", "'" + key + "' is no disturbance key");
      r.disturbances.emplace_back(
          key, p.number(pair.at(1), at + "disturbances." + key, it->low, it->high, it->unit));
    }
  }
  return r;
}

// The line a JSON parse error's byte falls on.
int line_of(const std::string& text, std::size_t byte) {
  return 1 + static_cast<int>(std::count(
                 text.begin(),
                 text.begin() + static_cast<std::ptrdiff_t>(std::min(byte, text.size())), '\n'));
}

}  // namespace

RunPlan read_plan(const std::string& path) {
  RunPlan plan;
  const std::string text = config::read_input_file(path);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw config::ConfigError(path, line_of(text, e.byte), "",
                              "is not JSON (a run plan is what planter-sim writes as plan.json)");
  } catch (const nlohmann::json::exception&) {  // a number beyond a double (2e+308), ...
    throw config::ConfigError(path, 0, "", "holds a number no double can hold, or is not JSON");
  }
  const PlanReader p(path);
  if (!j.is_object() || !j.contains("kind") || j.at("kind") != "planter-sim run plan" ||
      !j.contains("version") || j.at("version") != 1)
    p.fail("kind", "not a planter-sim run plan of version 1");
  if (!p.field(j, "scenario", "").is_string()) p.fail("scenario", "is not a path");
  if (!p.field(j, "inputs_hash", "").is_string()) p.fail("inputs_hash", "is not a string");
  plan.scenario = j.at("scenario").get<std::string>();
  plan.inputs_hash = j.at("inputs_hash").get<std::string>();
  const nlohmann::json& runs = p.field(j, "runs", "");
  if (!runs.is_array()) p.fail("runs", "is not a list");
  for (std::size_t i = 0; i < runs.size(); ++i) plan.runs.push_back(read_run(p, runs[i], i));
  return plan;
}

RunPlan new_plan(const std::string& scenario_path, const std::string& made_by) {
  RunPlan plan;
  plan.scenario = std::filesystem::absolute(scenario_path).lexically_normal().string();
  plan.inputs_hash = inputs_hash(plan.scenario, load_scenario(plan.scenario), made_by);
  return plan;
}

Scenario planned_scenario(const Scenario& base, const PlannedRun& run) {
  Scenario s = base;
  s.seed = run.seed;
  s.plant.route.distance_m = run.distance_m;
  s.plant.route.stops.clear();
  for (const auto& setting : run.values) {
    const auto values = model_values();
    const auto it = std::find_if(values.begin(), values.end(),
                                 [&](const ModelValue& v) { return setting.first == v.key; });
    if (it == values.end())
      throw std::runtime_error("the plan sets '" + setting.first + "', which is no model value");
    it->ref(s.plant) = setting.second;
  }
  if (run.operating_point)
    set_operating_point(s, run.operating_point->sigma, run.operating_point->depth_mm,
                        run.operating_point->contact_area_mm2);
  if (run.per_stem_grip) s.board.controller.clamp.per_stem_grip = *run.per_stem_grip;
  s.clamp_told_each_stem = run.clamp_told_each_stem;
  if (run.clamp_setpoint_N) {
    s.board.controller.clamp.setpoint_N = *run.clamp_setpoint_N;
    s.board.controller.clamp.ceiling_N =
        std::max(s.board.controller.clamp.ceiling_N, *run.clamp_setpoint_N + 20.0);
  }
  for (const auto& [key, value] : run.disturbances) apply_disturbance(s, key, value);
  return s;
}

std::string run_dir(const std::string& plan_dir, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "/runs/%05zu", index);
  return plan_dir + name;
}

// Whole by its manifest (config/output_set.h): a torn summary.json beside a whole run.json is
// run again, as the DEM runs a torn KEY.json again.
bool run_complete(const std::string& plan_dir, std::size_t index) {
  return config::output_set_whole(run_dir(plan_dir, index), kPlanTool);
}

Scenario plan_base(const std::string& plan_path, const RunPlan& plan, const std::string& made_by) {
  Scenario base = load_scenario(plan.scenario);
  if (inputs_hash(plan.scenario, base, made_by) != plan.inputs_hash)
    throw std::runtime_error(plan_path +
                             ": its scenario, board, machine or calibration file, or "
                             "the program (" +
                             made_by +
                             "), changed since the plan was made; "
                             "make the plan again");
  return base;
}

void run_planned(const std::string& plan_dir, const Scenario& base, const PlannedRun& run,
                 std::size_t index) {
  LockstepRunner runner(planned_scenario(base, run));
  const Summary summary = runner.run();
  config::make_directories(plan_dir + "/runs");
  config::OutputSet out(run_dir(plan_dir, index), kPlanTool, false);
  out.write("summary.json", summary.to_json() + "\n");
  out.commit();
}

void execute_planned_run(const std::string& plan_path, std::size_t index,
                         const std::string& made_by) {
  const RunPlan plan = read_plan(plan_path);
  if (index >= plan.runs.size())
    throw std::runtime_error(plan_path + ": run " + std::to_string(index) +
                             " is not in the plan (" +
                             (plan.runs.empty() ? std::string("it has no runs")
                                                : std::to_string(plan.runs.size()) + " runs, 0-" +
                                                      std::to_string(plan.runs.size() - 1)) +
                             ")");
  const std::string dir = std::filesystem::path(plan_path).parent_path().string();
  if (run_complete(dir, index)) return;
  run_planned(dir, plan_base(plan_path, plan, made_by), plan.runs[index], index);
}

Summary read_run_summary(const std::string& plan_dir, std::size_t index) {
  const std::string path = run_dir(plan_dir, index) + "/summary.json";
  try {
    return Summary::from_json(config::read_input_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not a run's summary: " + e.what());
  }
}

void place_plan(const std::string& plan_dir, const RunPlan& plan, bool replace) {
  namespace fs = std::filesystem;
  config::make_directories(plan_dir);
  const std::string path = plan_dir + "/plan.json";
  const std::string text = plan_json(plan);
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (config::read_input_file(path) == text) return;
    if (!replace)
      throw std::runtime_error(plan_dir +
                               " holds another plan (other inputs, another build of "
                               "planter-sim or other settings): its runs are not these; --force "
                               "replaces it");
    // Only what a plan holds: its file, its runs and its logs.
    for (const char* part : {"runs", "logs"}) fs::remove_all(plan_dir + "/" + part);
    fs::remove(plan_dir + "/plan.sbatch", ec);
    fs::remove(path);
  }
  config::write_output_file(path, text);
}

}  // namespace planter::sim
