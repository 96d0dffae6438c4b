#!/usr/bin/env bash
# A wrong-way include fails the build: cmake/layers.cmake gives every target only its own
# folders and those of what it links. Builds two targets kept out of `all`: one of the config
# layer that includes sim/ (must fail, on that include) and its control (must build); the same
# for a sim target that includes planter-fit's engine (analysis/).
set -u
build=$1
out=$(cmake --build "$build" --target planter_layering_right_way 2>&1)
if [ $? -ne 0 ]; then
  echo "layering test: the control target did not build:"; echo "$out" | tail -20; exit 1
fi
out=$(cmake --build "$build" --target planter_layering_wrong_way 2>&1)
if [ $? -eq 0 ]; then
  echo "layering test: config/ including sim/ BUILT; the layers are not enforced"; exit 1
fi
if ! echo "$out" | grep -qE "sim/runner/scenario.h('? file not found|: No such file or directory)"; then
  echo "layering test: the wrong-way target failed, but not on its wrong-way include:"
  echo "$out" | tail -20; exit 1
fi
out=$(cmake --build "$build" --target planter_layering_sim_right_way 2>&1)
if [ $? -ne 0 ]; then
  echo "layering test: the sim control target did not build:"; echo "$out" | tail -20; exit 1
fi
out=$(cmake --build "$build" --target planter_layering_sim_wrong_way 2>&1)
if [ $? -eq 0 ]; then
  echo "layering test: sim/ including analysis/ BUILT; planter-fit's engine is not its own room"; exit 1
fi
if ! echo "$out" | grep -qE "analysis/recording.h('? file not found|: No such file or directory)"; then
  echo "layering test: the sim wrong-way target failed, but not on its wrong-way include:"
  echo "$out" | tail -20; exit 1
fi
echo "layering test: config/ including sim/, and sim/ including analysis/, are refused by the build; the controls build"
