// GazeboWorld: the world's physics over dynamic_reconfigure, as gazebo_ros serves it under the
// node's namespace (/gazebo/set_parameters, parameter_descriptions, parameter_updates; Debian's
// dynamic_reconfigure::Server with the PhysicsConfig that cfg/Physics.cfg generates). Its first
// configuration is the world's (time step, update rate, gravity); a change of those goes to the
// world as /gazebo/set_physics_properties takes it; the ODE solver fields are kept, with no effect.
#include "ros/gazebo_reconfigure.hpp"

namespace mechsim::ros {

void GazeboWorld::start_reconfigure() {
  reconfigure_ = std::make_unique<Reconfigure>(::ros::NodeHandle("/gazebo"));
  reconfigure_->server.setCallback([this](mechsim_gazebo::PhysicsConfig& config, std::uint32_t) {
    const bridge::PhysicsProperties now = world_.physics_properties();
    if (!reconfigure_->initialised) {
      // What the server starts from is the world as it is, not the file's defaults.
      config.time_step = now.time_step;
      config.max_update_rate = now.max_update_rate;
      config.gravity_x = now.gravity.x;
      config.gravity_y = now.gravity.y;
      config.gravity_z = now.gravity.z;
      reconfigure_->initialised = true;
      return;
    }
    if (config.time_step == now.time_step && config.max_update_rate == now.max_update_rate &&
        config.gravity_x == now.gravity.x && config.gravity_y == now.gravity.y && config.gravity_z == now.gravity.z)
      return;
    bridge::PhysicsProperties wanted = now;
    wanted.time_step = config.time_step;
    wanted.max_update_rate = config.max_update_rate;
    wanted.gravity = {config.gravity_x, config.gravity_y, config.gravity_z};
    const BridgeResult r = world_.set_physics_properties(wanted);
    if (!r.ok) {
      ROS_WARN_STREAM("mechsim: physics reconfigure: " << r.error);
      // The configuration the clients see is what the world has.
      config.time_step = now.time_step;
      config.max_update_rate = now.max_update_rate;
      config.gravity_x = now.gravity.x;
      config.gravity_y = now.gravity.y;
      config.gravity_z = now.gravity.z;
    }
  });
}

}  // namespace mechsim::ros
