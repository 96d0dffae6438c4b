#include "firmware/io/io_config.h"

namespace planter {

const char* node_role_name(NodeRole role) {
  switch (role) {
    case NodeRole::kDiscDrive:
      return "disc_drive";
    case NodeRole::kRollerActuator:
      return "roller_actuator";
    case NodeRole::kDepthActuator:
      return "depth_actuator";
    case NodeRole::kForceSensor:
      return "force_sensor";
  }
  return "?";
}

}  // namespace planter
