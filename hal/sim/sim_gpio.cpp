#include "hal/sim/sim_gpio.h"

namespace planter::hal::sim {

void SimEdgeSource::push(const GpioEdge& edge) {
  if (!edges_.push(edge)) ++overflow_;
}

}  // namespace planter::hal::sim
