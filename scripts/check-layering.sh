#!/usr/bin/env bash
# The house's layers, from the ground up: each may include only itself and the layers below.
#   hal/include <- hal/sim, hal/linux <- firmware <- config <- console, report, plan (the run
#   executors) <- sim <- doe, dem (the seedling's DEM), analysis (planter-fit's engine) <- apps
# dem and analysis see of sim only the models they share with the plant: sim/seedling (the
# reduced force model) and sim/soil (the draft law).
# firmware/ also sees no OS header: only the C++ standard library. The build enforces the same
# through each target's own include tree (cmake/layers.cmake); this check names the file.
set -u
root=${1:-$(dirname "$0")/..}
status=0

# layer folder | allowed project include prefixes (extended regex)
rules=(
  "hal/include|planter/hal/"
  "hal/sim|planter/hal/|hal/sim/"
  "hal/linux|planter/hal/|hal/linux/"
  "firmware|planter/hal/|firmware/"
  "config|planter/hal/|firmware/|config/"
  "console|planter/hal/|firmware/|config/|console/"
  "report|report/"
  "plan|config/|plan/"
  "sim|planter/hal/|hal/sim/|hal/linux/|firmware/|config/|console/|report/|plan/|sim/"
  "doe|report/|doe/"
  "dem|config/|report/|plan/|doe/|sim/seedling/|dem/"
  "analysis|planter/hal/|firmware/|config/|report/|sim/soil/|analysis/"
  "apps|planter/hal/|hal/sim/|hal/linux/|firmware/|config/|console/|report/|plan/|sim/|doe/|dem/|analysis/|apps/"
)
for rule in "${rules[@]}"; do
  layer=${rule%%|*}
  allowed=${rule#*|}
  bad=$(grep -rnE '^\s*#\s*include\s*"' "$root/$layer" --include='*.h' --include='*.cpp' |
    grep -vE "#\s*include\s*\"($allowed)" || true)
  if [ -n "$bad" ]; then
    echo "layering: $layer/ includes a layer above it (allowed: ${allowed//|/ }):"
    echo "$bad"
    status=1
  fi
done

bad=$(grep -rnE '^\s*#\s*include\s*<' "$root/firmware" |
  grep -vE '#\s*include\s*<(algorithm|array|cmath|cstddef|cstdint|cstdio|limits|span|string|string_view|vector|utility|type_traits)>' || true)
if [ -n "$bad" ]; then
  echo "layering: firmware/ includes a header outside the C++ standard library:"
  echo "$bad"
  status=1
fi
[ $status -eq 0 ] && echo "layering ok: every layer includes only itself and the layers below"
exit $status
