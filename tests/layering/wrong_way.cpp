// Deliberately wrong: a target of the config layer (it links planter_config only) includes the
// simulator, a layer above it. The build must refuse it (tests/layering/layering_test.sh).
#include "config/board_config.h"
#include "sim/runner/scenario.h"

int planter_wrong_way() { return 0; }
