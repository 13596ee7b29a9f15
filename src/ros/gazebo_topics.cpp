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

// Fills a ModelStates or LinkStates message from the world's named states.
template <class Message>
void fill_states(const std::vector<bridge::NamedState>& states, Message& m) {
  m.name.resize(states.size());
  m.pose.resize(states.size());
  m.twist.resize(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    m.name[i] = states[i].name;
    fill(states[i].state, m.pose[i], m.twist[i]);
  }
}

void GazeboWorld::publish_states(double time) {
  Topics& t = *topics_;
  const bool models = t.model_subscribers.load(std::memory_order_relaxed) > 0;
  const bool links = t.link_subscribers.load(std::memory_order_relaxed) > 0;
  if ((!models && !links) || time + 1e-9 < t.next_states) return;
  t.next_states = time + (options_.model_states_rate > 0.0 ? 1.0 / options_.model_states_rate : 0.0);
  if (models) {
    world_.model_states_now(t.models);
    fill_states(t.models, t.model_msg);
    t.model_states.publish(t.model_msg);
  }
  if (links) {
    world_.link_states_now(t.links);
    fill_states(t.links, t.link_msg);
    t.link_states.publish(t.link_msg);
  }
}

void GazeboWorld::publish_performance() {
  Topics& t = *topics_;
  const double sim = world_.time();
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
