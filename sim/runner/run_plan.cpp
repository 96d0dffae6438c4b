#include "sim/runner/run_plan.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "config/content_hash.h"
#include "config/durable_file.h"
#include "config/output_set.h"
#include "sim/runner/lockstep_runner.h"

namespace planter::sim {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

constexpr const char* kPlanTool = "planter-sim plan-run";

}  // namespace

std::string plan_json(const RunPlan& plan) {
  nlohmann::ordered_json j;
  j["kind"] = "planter-sim run plan";
  j["version"] = 1;
  j["scenario"] = plan.scenario;
  j["scenario_hash"] = plan.scenario_hash;
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
    runs.push_back(one);
  }
  j["runs"] = runs;
  return j.dump(1) + "\n";
}

RunPlan read_plan(const std::string& path) {
  RunPlan plan;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_text(path));
    if (j.at("kind") != "planter-sim run plan" || j.at("version") != 1)
      throw std::runtime_error("not a planter-sim run plan of version 1");
    plan.scenario = j.at("scenario").get<std::string>();
    plan.scenario_hash = j.at("scenario_hash").get<std::string>();
    for (const auto& one : j.at("runs")) {
      PlannedRun r;
      r.seed = one.at("seed").get<std::uint64_t>();
      r.distance_m = one.at("distance_m").get<double>();
      if (one.contains("operating_point")) {
        const auto& op = one.at("operating_point");
        r.operating_point =
            OperatingPoint{op.at("sigma").get<double>(), op.at("depth_mm").get<double>(),
                           op.at("contact_area_mm2").get<double>()};
      }
      if (one.contains("clamp_setpoint_N"))
        r.clamp_setpoint_N = one.at("clamp_setpoint_N").get<double>();
      plan.runs.push_back(r);
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not a run plan: " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return plan;
}

Scenario planned_scenario(const Scenario& base, const PlannedRun& run) {
  Scenario s = base;
  s.seed = run.seed;
  s.plant.route.distance_m = run.distance_m;
  s.plant.route.stops.clear();
  if (run.operating_point)
    set_operating_point(s, run.operating_point->sigma, run.operating_point->depth_mm,
                        run.operating_point->contact_area_mm2);
  if (run.clamp_setpoint_N) {
    s.board.controller.clamp.setpoint_N = *run.clamp_setpoint_N;
    s.board.controller.clamp.ceiling_N =
        std::max(s.board.controller.clamp.ceiling_N, *run.clamp_setpoint_N + 20.0);
  }
  return s;
}

std::string run_dir(const std::string& plan_dir, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "/runs/%05zu", index);
  return plan_dir + name;
}

bool run_complete(const std::string& plan_dir, std::size_t index) {
  std::error_code ec;
  return std::filesystem::is_regular_file(run_dir(plan_dir, index) + "/" + config::kRunManifest,
                                          ec) &&
         std::filesystem::is_regular_file(run_dir(plan_dir, index) + "/summary.json", ec);
}

void execute_planned_run(const std::string& plan_path, std::size_t index) {
  const RunPlan plan = read_plan(plan_path);
  if (index >= plan.runs.size())
    throw std::runtime_error(plan_path + ": run " + std::to_string(index) +
                             " is not in the plan (" + std::to_string(plan.runs.size()) +
                             " runs, 0-" + std::to_string(plan.runs.size() - 1) + ")");
  const std::string dir = std::filesystem::path(plan_path).parent_path().string();
  if (run_complete(dir, index)) return;
  if (config::content_hash(read_text(plan.scenario)) != plan.scenario_hash)
    throw std::runtime_error(plan.scenario + ": changed since the plan " + plan_path +
                             " was made; make the plan again");
  const Scenario s = planned_scenario(load_scenario(plan.scenario), plan.runs[index]);
  LockstepRunner runner(s);
  const Summary summary = runner.run();
  std::filesystem::create_directories(dir + "/runs");
  config::OutputSet out(run_dir(dir, index), kPlanTool, false);
  out.write("summary.json", summary.to_json() + "\n");
  out.commit();
}

Summary read_run_summary(const std::string& plan_dir, std::size_t index) {
  const std::string path = run_dir(plan_dir, index) + "/summary.json";
  Summary s;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_text(path));
    s.scenario = j.at("scenario").get<std::string>();
    s.uprightness_pct = j.at("uprightness_pct").get<double>();
    s.damage_pct = j.at("damage_pct").get<double>();
    s.seedlings_lodged = j.at("seedlings_lodged").get<int>();
    s.seedlings_fell_in_carry = j.at("seedlings_fell_in_carry").get<int>();
    s.seedlings_slid_in_clamp = j.at("seedlings_slid_in_clamp").get<int>();
    s.seedlings_turned_in_clamp = j.at("seedlings_turned_in_clamp").get<int>();
    s.clamp_force_mean_N = j.at("clamp_force_mean_N").get<double>();
    s.clamp_force_max_N = j.at("clamp_force_max_N").get<double>();
    s.clamp_ceiling_N = j.at("clamp_ceiling_N").get<double>();
    s.seedling_peak_force_mean_N = j.at("seedling_peak_force_mean_N").get<double>();
    s.seedlings_planted = j.at("seedlings_planted").get<int>();
    s.seedlings_damaged = j.at("seedlings_damaged").get<int>();
    s.spacing_mean_mm = j.at("spacing_mean_mm").get<double>();
    s.spacing_cv_pct = j.at("spacing_cv_pct").get<double>();
    s.distance_m = j.at("distance_m").get<double>();
    s.route_complete = j.at("route_complete").get<bool>();
    s.sim_seconds = j.at("sim_seconds").get<double>();
    s.wall_seconds = j.at("wall_seconds").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not a run's summary: " + e.what());
  }
  return s;
}

void place_plan(const std::string& plan_dir, const RunPlan& plan) {
  std::filesystem::create_directories(plan_dir);
  const std::string path = plan_dir + "/plan.json";
  const std::string text = plan_json(plan);
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    if (read_text(path) == text) return;
    throw std::runtime_error(
        plan_dir + " holds another plan (another scenario or other " +
        "settings): its runs are not these; remove it or choose another --out");
  }
  config::write_output_file(path, text);
}

}  // namespace planter::sim
