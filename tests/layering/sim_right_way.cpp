// The control for sim_wrong_way.cpp: the same target kind includes its own layer and the
// reports below it, and must build.
#include "report/html_text.h"
#include "sim/runner/scenario.h"

int planter_sim_right_way() { return 0; }
