#include "dem/calibration_runs.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "config/config_error.h"
#include "config/content_hash.h"
#include "config/durable_file.h"
#include "config/input_file.h"
#include "config/output_set.h"
#include "dem/dem_params.h"
#include "dem/result_json.h"

namespace planter::dem {
namespace {

// The DEM's physics revision, part of every run's key: a run kept from older physics is not a
// result of this code. Raise it whenever a law of dem/ changes what a run computes.
// 2: the Hertz contact acts in parallel with a bond.
// 3: the same laws stepped one pair per vector lane (the normal from one division, the rolling
// torque's factors grouped): results differ from revision 2's in their last bits.
constexpr int kPhysicsRevision = 3;

std::string key_of_text(const std::string& toml) {
  // Over the parameters as written: the same text is the same run.
  return config::content_hash("physics " + std::to_string(kPhysicsRevision) + "\n" + toml);
}

nlohmann::json result_to_json(const CompressionResult& r) {
  nlohmann::json j;
  put_result_figures(j, r);
  j["peak_displacement_m"] = r.peak_displacement_m;
  std::vector<double> x, f;
  std::vector<int> b;
  for (const auto& p : r.curve) {
    x.push_back(p.displacement_m);
    f.push_back(p.force_N);
    b.push_back(p.broken_bonds);
  }
  j["displacement_m"] = x;
  j["force_N"] = f;
  j["broken"] = b;
  return j;
}

bool result_from_json(const nlohmann::json& j, CompressionResult& r) {
  try {
    r.peak_force_N = j.at("peak_force_N").get<double>();
    r.peak_displacement_m = j.at("peak_displacement_m").get<double>();
    r.first_peak_found = j.at("first_peak_found").get<bool>();
    r.broken_bonds = j.at("broken_bonds").get<int>();
    r.particles = j.at("particles").get<int>();
    r.bonds = j.at("bonds").get<int>();
    r.steps = j.at("steps").get<long>();
    r.max_kinetic_to_work = j.at("max_kinetic_to_work").get<double>();
    const auto x = j.at("displacement_m").get<std::vector<double>>();
    const auto f = j.at("force_N").get<std::vector<double>>();
    const auto b = j.at("broken").get<std::vector<int>>();
    if (x.size() != f.size() || x.size() != b.size()) return false;
    r.curve.clear();
    for (std::size_t k = 0; k < x.size(); ++k) r.curve.push_back({x[k], f[k], b[k]});
    find_collapse(r);
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

// A kept file's text, "" when it cannot be read. One that is not a regular file (a directory
// where KEY.json should be) reads as missing: the run is run again, and writing its result
// says what is in the way.
std::string read_text(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::string();
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return in ? text.str() : std::string();
}

// The result kept for the parameters `toml`; none when it is not there, torn, or from other
// parameters (then the run is run again).
std::optional<CompressionResult> kept_for_text(const std::string& runs_dir,
                                               const std::string& toml) {
  const nlohmann::json j = nlohmann::json::parse(
      read_text(runs_dir + "/" + key_of_text(toml) + ".json"), nullptr, false);
  if (j.is_discarded() || !j.contains("params") || j["params"] != toml) return std::nullopt;
  CompressionResult r;
  if (!result_from_json(j, r)) return std::nullopt;
  return r;
}

// The run `key`'s parameters, read from its KEY.toml, and their text.
struct KeyedRun {
  CompressionSetup setup;
  std::string toml;
};
KeyedRun read_keyed(const std::string& runs_dir, const std::string& key) {
  const std::string path = runs_dir + "/" + key + ".toml";
  KeyedRun run{load_compression_setup(path), ""};
  // The parameters as read must write back to the same text, or the run is not the key's.
  run.toml = compression_setup_toml(run.setup);
  if (key_of_text(run.toml) != key)
    throw std::runtime_error(path + ": its parameters are not those of the run " + key +
                             " (edited, or written by another version of planter-dem)");
  return run;
}

CompressionResult run_and_keep(const std::string& runs_dir, const std::string& key,
                               const KeyedRun& run) {
  const CompressionResult r = run_compression(run.setup);
  nlohmann::json j = result_to_json(r);
  j["params"] = run.toml;
  const std::string out = runs_dir + "/" + key + ".json";
  if (!config::write_file_atomic(out, j.dump() + "\n"))
    throw std::runtime_error(out + ": cannot be written");
  return r;
}

}  // namespace

std::string run_key(const CompressionSetup& s) { return key_of_text(compression_setup_toml(s)); }

std::optional<CompressionResult> kept_result(const std::string& runs_dir,
                                             const CompressionSetup& s) {
  return kept_for_text(runs_dir, compression_setup_toml(s));
}

std::string place_run(const std::string& runs_dir, const CompressionSetup& s) {
  const std::string toml = compression_setup_toml(s), key = key_of_text(toml);
  const std::string path = runs_dir + "/" + key + ".toml";
  if (read_text(path) != toml && !config::write_file_atomic(path, toml))
    throw std::runtime_error(path + ": cannot be written");
  return key;
}

CompressionResult run_kept(const std::string& runs_dir, const std::string& key) {
  return run_and_keep(runs_dir, key, read_keyed(runs_dir, key));
}

void write_stage_plan(const std::string& path, const std::string& runs_dir,
                      const std::vector<std::string>& keys) {
  nlohmann::json j;
  j["planter-dem calibration stage"] = 1;
  j["runs_dir"] = std::filesystem::absolute(runs_dir).lexically_normal().string();
  j["keys"] = keys;
  config::make_directories(std::filesystem::path(path).parent_path().string());
  config::write_output_file(path, j.dump(2) + "\n");
}

void execute_stage_run(const std::string& plan_path, std::size_t index) {
  const nlohmann::json j =
      nlohmann::json::parse(config::read_input_file(plan_path), nullptr, false);
  if (j.is_discarded() || !j.contains("planter-dem calibration stage") || !j.contains("runs_dir") ||
      !j["runs_dir"].is_string() || !j.contains("keys") || !j["keys"].is_array())
    throw config::ConfigError(plan_path, 0, "", "not a plan of planter-dem's calibration");
  const auto& keys = j["keys"];
  if (index >= keys.size())
    throw config::ConfigError(plan_path, 0, "keys",
                              "no run " + std::to_string(index) + " (the plan has " +
                                  std::to_string(keys.size()) + ", from 0)");
  if (!keys[index].is_string())
    throw config::ConfigError(plan_path, 0, "keys", "run " + std::to_string(index) + " has no key");
  const std::string runs_dir = j["runs_dir"].get<std::string>();
  const std::string key = keys[index].get<std::string>();
  if (key.empty() || key.find_first_of("/.") != std::string::npos)
    throw config::ConfigError(plan_path, 0, "keys",
                              "run " + std::to_string(index) + "'s key '" + key + "' is not a key");
  const KeyedRun run = read_keyed(runs_dir, key);
  if (kept_for_text(runs_dir, run.toml)) return;  // a resumed plan runs only what is missing
  run_and_keep(runs_dir, key, run);
}

}  // namespace planter::dem
