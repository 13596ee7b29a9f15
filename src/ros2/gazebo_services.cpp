// gazebo_ros (ROS 2)'s world services, mapped onto bridge::World (world_node.hpp): names, fields
// and answers as gazebo_ros_init.cpp, gazebo_ros_factory.cpp and gazebo_ros_state.cpp give them.
// World does what is asked; these only translate messages and status words.
#include <cmath>

#include <mechsim_ros2_msgs/gazebo_msgs.hpp>
#include <mechsim_ros2_msgs/std_srvs.hpp>

#include "ros2/conversions.hpp"
#include "ros2/service.hpp"
#include "ros2/world_node.hpp"

namespace mechsim::ros2 {

namespace {

using gazebo_msgs::srv::DeleteEntity;
using gazebo_msgs::srv::GetEntityState;
using gazebo_msgs::srv::GetModelList;
using gazebo_msgs::srv::SetEntityState;
using gazebo_msgs::srv::SpawnEntity;
using std_srvs::srv::Empty;

description::Pose pose_of(const geometry_msgs::msg::Pose& p) {
  return {{p.position.x, p.position.y, p.position.z}, {p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z}};
}

void fill_pose(const description::Pose& in, geometry_msgs::msg::Pose& out) {
  out.position.x = in.position.x;
  out.position.y = in.position.y;
  out.position.z = in.position.z;
  out.orientation.w = in.orientation.w;
  out.orientation.x = in.orientation.x;
  out.orientation.y = in.orientation.y;
  out.orientation.z = in.orientation.z;
}

bool is_model(const bridge::World& world, const std::string& name) {
  for (const std::string& m : world.model_names())
    if (m == name) return true;
  return false;
}

// A deferred server whose requests run on `worker` in order; a full queue answers `busy`.
template <class Srv, class Run>
std::shared_ptr<void> serve(Node& node, const std::string& name, Worker& worker, Run run) {
  auto server = std::make_shared<std::weak_ptr<ServiceServer<Srv>>>();  // weak: no cycle through the handler
  auto made = std::make_shared<ServiceServer<Srv>>(
      node, name,
      typename ServiceServer<Srv>::DeferredHandler([server, &worker, run](const typename Srv::Request& request, const ReplyTo& to) {
        std::weak_ptr<ServiceServer<Srv>> weak = *server;
        const bool queued = worker.post([weak, request, to, run] {
          typename Srv::Response response;
          run(request, response);
          if (auto s = weak.lock()) s->reply(to, response);
        });
        if (!queued) {
          typename Srv::Response response;  // success false: the world is busy or stopping
          if (auto s = weak.lock()) s->reply(to, response);
        }
      }));
  *server = made;
  return made;
}

}  // namespace

void WorldNode::advertise_services() {
  services_ = std::make_unique<Services>();
  Services& s = *services_;
  Node& gz = *gazebo_node_;
  Worker& w = *worker_;
  // gazebo_ros_init (std_srvs/srv/Empty). On the worker too, though quick: a handler on Fast DDS's
  // receive thread must not wait for the world's lock, which a delete holds while it removes the
  // model's DDS endpoints (and that waits for the receive thread: a deadlock).
  auto empty = [&](const char* name, std::function<void()> action) {
    s.servers.push_back(serve<Empty>(gz, name, w, [action](const Empty::Request&, Empty::Response&) { action(); }));
  };
  empty("/pause_physics", [this] { world_.set_paused(true); });
  empty("/unpause_physics", [this] { world_.set_paused(false); });
  // Both put every model back at its spawn pose and restart its controllers; time goes on
  // (sim/simulation.hpp says why).
  empty("/reset_simulation", [this] { world_.reset(); });
  empty("/reset_world", [this] { world_.reset(); });

  // gazebo_ros_factory.
  s.servers.push_back(serve<SpawnEntity>(gz, "/spawn_entity", w, [this](const SpawnEntity::Request& req, SpawnEntity::Response& res) {
    bridge::SpawnRequest spawn;
    spawn.name = req.name;
    spawn.xml = req.xml;
    spawn.robot_namespace = req.robot_namespace;
    spawn.reference_frame = req.reference_frame;
    spawn.pose = pose_of(req.initial_pose);
    spawn.name_from_description = true;
    // gazebo_ros' factory multiplies the quaternion in as given: a zero one is the identity there
    // (ignition's Quaternion of (0,0,0,0) normalises to it): taken so, with a warning.
    const auto& q = spawn.pose.orientation;
    if (q.w == 0.0 && q.x == 0.0 && q.y == 0.0 && q.z == 0.0) {
      participant_->log("/spawn_entity: initial_pose has a zero quaternion: taken as the identity, as gazebo_ros does");
      spawn.pose.orientation = {1.0, 0.0, 0.0, 0.0};
    }
    if (spawn.reference_frame == "/map") spawn.reference_frame = "map";
    std::string status;
    const bridge::BridgeResult r = world_.spawn(spawn, &status);
    res.success = r.ok;
    res.status_message = r.ok ? "SpawnEntity: Successfully spawned entity [" + last_added_ + "]" : r.error;
  }));
  s.servers.push_back(serve<DeleteEntity>(gz, "/delete_entity", w, [this](const DeleteEntity::Request& req, DeleteEntity::Response& res) {
    // A light too, as EntityByName finds one.
    for (const std::string& l : world_.light_names()) {
      if (l == req.name) {
        const bridge::BridgeResult r = world_.delete_light(req.name);
        res.success = r.ok;
        res.status_message = r.ok ? "Successfully deleted entity [" + req.name + "]" : r.error;
        return;
      }
    }
    if (!is_model(world_, req.name)) {
      res.success = false;
      res.status_message = "Entity [" + req.name + "] does not exist";
      return;
    }
    std::string status;
    const bridge::BridgeResult r = world_.remove(req.name, &status);
    res.success = r.ok;
    res.status_message = r.ok ? "Successfully deleted entity [" + req.name + "]" : r.error;
  }));
  s.servers.push_back(serve<GetModelList>(gz, "/get_model_list", w, [this](const GetModelList::Request&, GetModelList::Response& res) {
    res.header.stamp = to_time(world_.time());
    res.model_names = world_.model_names();
    res.success = true;
  }));

  // gazebo_ros_state (a world plugin in gazebo_ros; its node named after the plugin).
  s.state_node = std::make_unique<Node>(*participant_, "/", "gazebo_ros_state");
  Node& st = *s.state_node;
  s.servers.push_back(serve<GetEntityState>(st, "/get_entity_state", w, [this](const GetEntityState::Request& req, GetEntityState::Response& res) {
    bridge::EntityState state;
    const bridge::BridgeResult r = is_model(world_, req.name) ? world_.model_state(req.name, req.reference_frame, state)
                                                              : world_.link_state(req.name, req.reference_frame, state);
    if (!r.ok) {
      participant_->log("GetEntityState: entity [" + req.name + "] in frame [" + req.reference_frame + "]: " + r.error);
      res.success = false;
      return;
    }
    res.header.stamp = to_time(world_.time());
    res.header.frame_id = req.reference_frame;
    fill_pose(state.pose, res.state.pose);
    res.state.twist.linear.x = state.linear.x;
    res.state.twist.linear.y = state.linear.y;
    res.state.twist.linear.z = state.linear.z;
    res.state.twist.angular.x = state.angular.x;
    res.state.twist.angular.y = state.angular.y;
    res.state.twist.angular.z = state.angular.z;
    res.success = true;
  }));
  s.servers.push_back(serve<SetEntityState>(st, "/set_entity_state", w, [this](const SetEntityState::Request& req, SetEntityState::Response& res) {
    bridge::EntityState state;
    state.pose = pose_of(req.state.pose);
    // gazebo_ros normalises the rotation; a zero quaternion becomes the identity.
    auto& q = state.pose.orientation;
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (n < 1e-12) q = {1.0, 0.0, 0.0, 0.0};
    const auto& t = req.state.twist;
    state.linear = {t.linear.x, t.linear.y, t.linear.z};
    state.angular = {t.angular.x, t.angular.y, t.angular.z};
    const std::string& name = req.state.name;
    const bridge::BridgeResult r = is_model(world_, name) ? world_.set_model_state(name, req.state.reference_frame, state)
                                                          : world_.set_link_state(name, req.state.reference_frame, state);
    if (!r.ok) participant_->log("SetEntityState: entity [" + name + "]: " + r.error);
    res.success = r.ok;
  }));
}

}  // namespace mechsim::ros2
