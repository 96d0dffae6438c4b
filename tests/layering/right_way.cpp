// The control for wrong_way.cpp: the same target kind includes its own layer and the one below
// (firmware), and must build; so wrong_way's failure is the layer's doing, nothing else.
#include "config/board_config.h"
#include "firmware/io/signal_table.h"

int planter_right_way() { return static_cast<int>(planter::kSignals.size()); }
