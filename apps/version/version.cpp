#include "apps/version/version.h"

namespace planter::apps {

// Defined for this file alone, so a new commit recompiles one line, not the five mains.
const char* version() { return PLANTER_VERSION; }

}  // namespace planter::apps
