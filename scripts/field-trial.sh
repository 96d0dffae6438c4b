#!/usr/bin/env bash
# The main job: set up, build, and run the simulated Zhangqiu field trial.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
log="$root/build/field-trial-setup.log"
mkdir -p "$root/build"
echo "field-trial: installing what is missing and building planter-sim in build/ (the first" \
  "time takes a few minutes; log: build/field-trial-setup.log)" >&2
# Only the program this job runs is built, and its man page; its steps are counted on the
# terminal as they go.
# Read line by line in bash: Debian's awk (mawk) reads a pipe in blocks, which froze the count
# for most of a minute at a time.
progress() {
  local line step n total
  while IFS= read -r line; do
    [[ $line =~ ^\[([0-9]+)/([0-9]+)\] ]] || continue
    step=${BASH_REMATCH[0]} n=${BASH_REMATCH[1]} total=${BASH_REMATCH[2]}
    if [ -t 2 ]; then
      printf '\rfield-trial: build step %s' "$step" >&2
    elif ((n % 20 == 0 || n == total)); then
      echo "field-trial: build step $step" >&2
    fi
  done
  if [ -t 2 ]; then printf '\n' >&2; fi
}
if ! PLANTER_BUILD_TARGETS="planter-sim planter-sim-man" "$root/scripts/setup.sh" "$root/build" 2>&1 | tee "$log" |
  progress; then
  echo "field-trial: the setup or the build failed; the end of $log:" >&2
  tail -n 30 "$log" >&2
  exit 1
fi
echo "field-trial: running the simulated Zhangqiu field trial (30 m)" >&2
"$root/build/apps/planter-sim/planter-sim" run "$root/scenarios/zhangqiu-field.toml" --out "${1:-$root/out/zhangqiu-field}"
