#!/usr/bin/env bash
# A wrong-way include fails the build: cmake/layers.cmake gives every target only its own
# folders and those of what it links. Builds targets kept out of `all`, in pairs: one that
# includes a layer above its own (must fail, on that include) and its control (must build).
set -u
build=$1
# pair RIGHT_TARGET WRONG_TARGET WRONG_HEADER WHAT
pair() {
  local out
  out=$(cmake --build "$build" --target "$1" 2>&1)
  if [ $? -ne 0 ]; then
    echo "layering test: the control target $1 did not build:"; echo "$out" | tail -20; exit 1
  fi
  out=$(cmake --build "$build" --target "$2" 2>&1)
  if [ $? -eq 0 ]; then
    echo "layering test: $4 BUILT; the layers are not enforced"; exit 1
  fi
  if ! echo "$out" | grep -qE "$3('? file not found|: No such file or directory)"; then
    echo "layering test: $2 failed, but not on its wrong-way include:"
    echo "$out" | tail -20; exit 1
  fi
}
pair planter_layering_right_way planter_layering_wrong_way sim/runner/scenario.h \
  "config/ including sim/"
# planter-fit's engine is a room of its own (issue 29): the simulator may not include it.
pair planter_layering_sim_right_way planter_layering_sim_wrong_way analysis/recording.h \
  "sim/ including analysis/"
echo "layering test: config/ including sim/, and sim/ including analysis/, are refused by the build; the controls build"
