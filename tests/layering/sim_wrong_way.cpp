// Deliberately wrong: a target of the simulator's layer (it links planter_sim only) includes
// planter-fit's engine, a component above it since it has its own room (issue 29). The build
// must refuse it (tests/layering/layering_test.sh).
#include "analysis/recording.h"
#include "sim/runner/scenario.h"

int planter_sim_wrong_way() { return 0; }
