#include "console/live_sample.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "console/json_number.h"

namespace planter::console {
namespace {

// Faults and warnings in the operator's words, with what to do.
nlohmann::json fault_list(std::uint32_t faults) {
  nlohmann::json list = nlohmann::json::array();
  for (int bit = 0; bit < fault::kCount; ++bit)
    if ((faults >> bit) & 1u) list.push_back(fault::name(bit));
  return list;
}
nlohmann::json warning_list(std::uint32_t warnings) {
  nlohmann::json list = nlohmann::json::array();
  for (int bit = 0; bit < warning::kCount; ++bit)
    if ((warnings >> bit) & 1u) list.push_back(warning::name(bit));
  return list;
}
}  // namespace

LiveSample live_sample(double t_s, const Telemetry& t) {
  LiveSample s;
  s.t_s = t_s;
  s.state = t.state;
  s.faults = t.faults;
  s.warnings = t.warnings;
  s.v_mps = t.v_wheel_mps;
  s.sigma_seen = t.sigma;
  s.omega_radps = t.omega_radps;
  s.clamp_force_N = t.clamp_force_N;
  s.clamp_force_target_N = t.clamp_force_target_N;
  s.depth_mm = t.depth_mm;
  s.depth_target_mm = t.depth_target_mm;
  s.planting = t.planting;
  s.gnss_fitted = t.gnss_fitted;
  s.gnss_use = t.gnss_use;
  s.slip_est = t.slip_est;
  s.v_gnss_mps = t.v_gnss_mps;
  s.gnss_mode = static_cast<int>(t.gnss.mode);
  s.satellites = t.gnss.satellites;
  s.hdop = t.gnss.hdop;
  return s;
}

std::string to_json(const LiveSample& s, const std::string& recording) {
  const PlantingFigures& p = s.planting;
  const bool spaced = p.spacings > 0.0;
  nlohmann::json j = {
      {"t_s", s.t_s},
      {"state", supervisor_state_name(s.state)},
      {"faults", fault_list(s.faults)},
      {"warnings", warning_list(s.warnings)},
      {std::string(signal_key("v_wheel")), json_number(s.v_mps)},
      {std::string(signal_key("sigma")), json_number(s.sigma_seen)},
      {kTrueSigmaKey, json_number(s.sigma_true)},
      {std::string(signal_key("omega")), json_number(s.omega_radps)},
      {std::string(signal_key("clamp_force")), json_number(s.clamp_force_N)},
      {std::string(signal_key("clamp_force_cmd")), json_number(s.clamp_force_target_N)},
      {std::string(signal_key("depth_mm")), json_number(s.depth_mm)},
      {std::string(signal_key("depth_target_mm")), json_number(s.depth_target_mm)},
      {"planting",
       {{std::string(signal_key("seedlings")), p.seedlings},
        {std::string(signal_key("seedlings_per_m")), p.per_m},
        {"spacings", p.spacings},
        {std::string(signal_key("spacing_mean_mm")),
         spaced ? json_number(p.spacing_mean_mm) : nullptr},
        {std::string(signal_key("spacing_cv")), spaced ? json_number(p.spacing_cv) : nullptr},
        {std::string(signal_key("skips")), p.skips},
        {std::string(signal_key("multiples")), p.multiples},
        {std::string(signal_key("singulation_pct")),
         spaced ? json_number(p.singulation_pct) : nullptr},
        {"empty_clamps_in_row", p.empty_clamps_in_row},
        {std::string(signal_key("damage_seen")), p.damage_seen}}},
      {"gnss", s.gnss_fitted
                   ? nlohmann::json{{"use", gnss_use_name(s.gnss_use)},
                                    {"in_use", s.gnss_use == GnssUse::kUsing},
                                    {std::string(signal_key("slip_est")), json_number(s.slip_est)},
                                    {std::string(signal_key("v_gnss")), json_number(s.v_gnss_mps)},
                                    {"mode", s.gnss_mode},
                                    {"satellites", s.satellites},
                                    {"hdop", json_number(s.hdop)}}
                   : nlohmann::json()},
      {"recording", recording.empty() ? nlohmann::json() : nlohmann::json(recording)}};
  return j.dump();
}

}  // namespace planter::console
