// GazeboWorld: /gazebo/model_states, /gazebo/link_states (gazebo_msgs, as gazebo_ros publishes
// them: every model / every link, world frame) and /gazebo/performance_metrics (the measured
// real-time factor, once a second).
#include <gazebo_msgs/PerformanceMetrics.h>

#include "ros/gazebo_topics.hpp"

namespace mechsim::ros {

namespace {

void fill(const EntityState& s, geometry_msgs::Pose& pose, geometry_msgs::Twist& twist) {
  pose.position.x = s.pose.position.x;
  pose.position.y = s.pose.position.y;
  pose.position.z = s.pose.position.z;
  pose.orientation.w = s.pose.orientation.w;
  pose.orientation.x = s.pose.orientation.x;
  pose.orientation.y = s.pose.orientation.y;
  pose.orientation.z = s.pose.orientation.z;
  twist.linear.x = s.linear.x;
  twist.linear.y = s.linear.y;
  twist.linear.z = s.linear.z;
  twist.angular.x = s.angular.x;
  twist.angular.y = s.angular.y;
  twist.angular.z = s.angular.z;
}

}  // namespace

void GazeboWorld::advertise_topics() {
  topics_ = std::make_unique<Topics>();
  Topics& t = *topics_;
  auto counter = [](std::atomic<int>& count, int delta) {
    return [&count, delta](const ::ros::SingleSubscriberPublisher&) { count.fetch_add(delta); };
  };
  t.model_states = root_nh_.advertise<gazebo_msgs::ModelStates>(
      "/gazebo/model_states", 1, counter(t.model_subscribers, 1), counter(t.model_subscribers, -1));
  t.link_states = root_nh_.advertise<gazebo_msgs::LinkStates>(
      "/gazebo/link_states", 1, counter(t.link_subscribers, 1), counter(t.link_subscribers, -1));
  t.performance = root_nh_.advertise<gazebo_msgs::PerformanceMetrics>("/gazebo/performance_metrics", 10);
  t.performance_timer = root_nh_.createWallTimer(::ros::WallDuration(1.0), [this](const ::ros::WallTimerEvent&) {
    publish_performance();
  });
}

void GazeboWorld::publish_states(double time) {
  Topics& t = *topics_;
  const bool models = t.model_subscribers.load(std::memory_order_relaxed) > 0;
  const bool links = t.link_subscribers.load(std::memory_order_relaxed) > 0;
  if ((!models && !links) || time + 1e-9 < t.next_states) return;
  t.next_states = time + (options_.model_states_rate > 0.0 ? 1.0 / options_.model_states_rate : 0.0);
  // The world's loop thread: robots_ changes only under robots_mutex_ (spawn, delete); it may be
  // empty (a model on its way in or out).
  std::lock_guard<std::mutex> lock(robots_mutex_);
  t.robot_links.resize(robots_.size());
  for (std::size_t r = 0; r < robots_.size(); ++r) robots_[r].node->bridge().link_states_now(t.robot_links[r]);
  if (models) {
    gazebo_msgs::ModelStates& m = t.model_msg;
    const std::size_t n = world_models_.size() + robots_.size();
    m.name.resize(n);
    m.pose.resize(n);
    m.twist.resize(n);
    // The world's own SimNode runs this loop: it stays until the loop has stopped.
    world_->bridge().world_model_states_now(t.world_models);
    for (std::size_t i = 0; i < world_models_.size(); ++i) {
      m.name[i] = world_models_[i];
      // An SDF world's models where the physics has them; the ground plane of mechsim's own
      // worlds at the origin.
      fill(i < t.world_models.size() ? t.world_models[i] : EntityState{}, m.pose[i], m.twist[i]);
    }
    for (std::size_t r = 0; r < robots_.size(); ++r) {
      const std::size_t k = world_models_.size() + r;
      const SimBridge& bridge = robots_[r].node->bridge();
      const std::vector<std::string>& names = bridge.link_names();
      m.name[k] = robots_[r].name;
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == bridge.robot().root_link) fill(t.robot_links[r][i], m.pose[k], m.twist[k]);
    }
    t.model_states.publish(m);
  }
  if (links) {
    gazebo_msgs::LinkStates& l = t.link_msg;
    std::size_t count = 0;
    for (const auto& links_of : t.robot_links) count += links_of.size();
    l.name.resize(count);
    l.pose.resize(count);
    l.twist.resize(count);
    std::size_t k = 0;
    for (std::size_t r = 0; r < robots_.size(); ++r) {
      const std::vector<std::string>& names = robots_[r].node->bridge().link_names();
      for (std::size_t i = 0; i < names.size(); ++i, ++k) {
        l.name[k] = robots_[r].name + "::" + names[i];
        fill(t.robot_links[r][i], l.pose[k], l.twist[k]);
      }
    }
    t.link_states.publish(l);
  }
}

void GazeboWorld::publish_performance() {
  Topics& t = *topics_;
  const double sim = time();
  const ::ros::WallTime wall = ::ros::WallTime::now();
  if (t.last_sim >= 0.0) {
    const double dwall = (wall - t.last_wall).toSec();
    gazebo_msgs::PerformanceMetrics m;
    m.header.stamp = ::ros::Time(sim);
    m.real_time_factor = dwall > 0.0 ? (sim - t.last_sim) / dwall : 0.0;
    t.performance.publish(m);
  }
  t.last_sim = sim;
  t.last_wall = wall;
}

}  // namespace mechsim::ros
