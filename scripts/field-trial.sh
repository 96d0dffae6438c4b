#!/usr/bin/env bash
# The main job: set up, build, and run the simulated Zhangqiu field trial.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
log="$root/build/field-trial-setup.log"
mkdir -p "$root/build"
echo "field-trial: installing what is missing and building planter-sim in build/ (the first" \
  "time takes a few minutes; log: build/field-trial-setup.log)" >&2
# Only the program this job runs is built; its steps are counted on the terminal as they go.
progress() {
  if [ -t 2 ]; then
    awk '/^\[[0-9]+\/[0-9]+\]/ { printf "\rfield-trial: build step %s", $1 > "/dev/stderr"; fflush("/dev/stderr") }
         END { printf "\n" > "/dev/stderr" }'
  else
    awk '/^\[[0-9]+\/[0-9]+\]/ { s = $1; gsub(/[][]/, "", s); split(s, n, "/")
         if (n[1] % 20 == 0 || n[1] == n[2]) print "field-trial: build step " $1 > "/dev/stderr" }'
  fi
}
if ! PLANTER_BUILD_TARGETS=planter-sim "$root/scripts/setup.sh" "$root/build" 2>&1 | tee "$log" |
  progress; then
  echo "field-trial: the setup or the build failed; the end of $log:" >&2
  tail -n 30 "$log" >&2
  exit 1
fi
echo "field-trial: running the simulated Zhangqiu field trial (30 m)" >&2
"$root/build/apps/planter-sim/planter-sim" run "$root/scenarios/zhangqiu-field.toml" --out "${1:-$root/out/zhangqiu-field}"
