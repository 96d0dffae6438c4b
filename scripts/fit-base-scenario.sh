#!/usr/bin/env bash
# Sourced by scripts/fit-proof.sh and scripts/fit-bench.sh.
# The base: the field scenario on 15 m, with perturbed nominal values (the tool must calibrate
# them, not report them as missing physics). Clean means the nominal structures and noise:
# no terrain, no random slip, seedlings of the reference diameter (whose thickness in the nip
# is a load the clamp's nominal law does not have), the soil wheel as the board calibrated
# it; the terrain case puts the terrain back.
base() {  # base NOISE_N (uses $root)
  sed -e "s|\.\./boards|$root/boards|; s|\.\./models|$root/models|" \
      -e "s|^distance_m = .*|distance_m = 15.0|" -e "s|^stops = .*|stops = [{ at_m = 5.0, duration_s = 12.0, planting_off = true }, { at_m = 12.5, duration_s = 12.0, planting_off = true }]|" \
      -e "s|^name = .*|name = \"fit-proof\"|" -e "s|^roughness_mm = .*|roughness_mm = 0.0|" \
      -e "s|^wheel_radius_m = .*|wheel_radius_m = 0.15464|" -e "s|^slip_mean_pct = .*|slip_mean_pct = 0.0|" -e "s|^slip_variation_pct = .*|slip_variation_pct = 0.0|" \
      -e "s|^diameter_min_mm = .*|diameter_min_mm = 10.0|" -e "s|^diameter_max_mm = .*|diameter_max_mm = 10.0|" \
      -e "s|^\[effects\]$|[plant]\nforce_noise_N = $1\ndisc_time_constant_s = 0.06\nclamp_k_N = 21.0\n\n[effects]|" \
      "$root/scenarios/zhangqiu-field.toml"
}
