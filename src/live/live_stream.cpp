#include "live/live_stream.hpp"

#include <algorithm>
#include <cmath>

#include "live/stream_messages.hpp"
#include "sim/simulation.hpp"

namespace mechsim::live {

namespace {

std::uint64_t nanoseconds(double t) { return static_cast<std::uint64_t>(std::llround(std::max(0.0, t) * 1e9)); }

}  // namespace

LiveStream::LiveStream(std::unique_ptr<FoxgloveServer> server, sim::Simulation& sim, std::string urdf,
                       std::vector<std::array<double, 2>> waypoints, StreamRates rates)
    : rates_(rates),
      layout_(make_stream_layout(sim, std::move(urdf), std::move(waypoints))),
      buffer_(make_snapshot(layout_)),
      server_(std::move(server)) {
  auto add = [&](std::string topic, std::string schema_name, const std::string& schema, Kind kind, double rate,
                 std::size_t laser = 0) {
    Channel c;
    c.id = static_cast<std::uint32_t>(channels_.size() + 1);
    c.topic = std::move(topic);
    c.schema_name = std::move(schema_name);
    c.schema = schema;
    channels_.push_back(std::move(c));
    ChannelState st;
    st.kind = kind;
    st.laser = laser;
    st.period = rate > 0.0 ? 1.0 / rate : 0.0;
    state_.push_back(std::move(st));
  };
  add("/tf", "foxglove.FrameTransforms", frame_transforms_schema(), Kind::Tf, rates_.tf);
  add("/joint_states", "sensor_msgs/JointState", joint_state_schema(), Kind::JointStates, rates_.joint_states);
  if (layout_.odometry != nullptr) add("/odom", "nav_msgs/Odometry", odometry_schema(), Kind::Odometry, rates_.odometry);
  for (std::size_t k = 0; k < layout_.lasers.size(); ++k) {
    add(layout_.lasers[k].topic, "foxglove.LaserScan", laser_scan_schema(), Kind::Scan, rates_.scans, k);
  }
  const double start = sim.time();
  if (!layout_.robot_description.empty()) {
    add("/robot_description", "std_msgs/String", string_schema(), Kind::RobotDescription, 0.0);
    server_->set_latched(channels_.back().id, nanoseconds(start),
                         std::make_shared<const std::string>(encode_robot_description(layout_.robot_description)));
  }
  if (!layout_.waypoints.empty()) {
    add("/markers", "foxglove.SceneUpdate", scene_update_schema(), Kind::Markers, 0.0);
    server_->set_latched(channels_.back().id, nanoseconds(start),
                         std::make_shared<const std::string>(encode_waypoint_markers(layout_, start)));
  }
  const double fastest = std::max({rates_.tf, rates_.joint_states, rates_.odometry, rates_.scans, 1.0});
  snapshot_every_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(1.0 / (fastest * sim.period()))));
  snapshot_period_ = static_cast<double>(snapshot_every_) * sim.period();
  // The first snapshot before the first tick, so that a client connecting to a paused
  // simulation sees the robot.
  capture_snapshot(layout_, sim, buffer_.write_buffer());
  buffer_.publish();
  sim.add_observer([this](const sim::Simulation& at) {
    if (at.ticks() % snapshot_every_ != 0) return;
    capture_snapshot(layout_, at, buffer_.write_buffer());
    buffer_.publish();
  });
  server_->set_channels(channels_);
  // Poll four times per snapshot period of wall time at real-time pace (at least every 10 ms).
  const auto poll_us = static_cast<long>(std::clamp(snapshot_period_ / 4.0, 0.001, 0.01) * 1e6);
  server_->start([this] { poll(); }, std::chrono::microseconds(poll_us));
}

LiveStream::~LiveStream() { stop(); }

void LiveStream::stop() { server_->stop(); }

StreamStats LiveStream::stats() const {
  StreamStats s;
  s.server = server_->stats();
  s.snapshots_published = buffer_.published();
  s.snapshots_taken = buffer_.taken();
  return s;
}

void LiveStream::poll() {
  const Snapshot* s = buffer_.take();
  if (s == nullptr) return;
  const std::uint64_t stamp = nanoseconds(s->time);
  server_->broadcast_time(stamp);
  const double slack = 0.5 * snapshot_period_;
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    ChannelState& st = state_[c];
    if (st.kind == Kind::RobotDescription || st.kind == Kind::Markers) continue;
    // Due a period after the last one, within half a snapshot period (rates that do not divide
    // the snapshot rate neither drift nor skip).
    if (s->time - st.last_sent < st.period - slack) continue;
    if (st.kind == Kind::Scan && s->lasers[st.laser].count == st.last_scan) continue;
    st.last_sent = s->time;
    if (!server_->has_subscribers(channels_[c].id)) continue;
    switch (st.kind) {
      case Kind::Tf: encode_frame_transforms(layout_, *s, st.text); break;
      case Kind::JointStates: encode_joint_states(layout_, *s, st.text); break;
      case Kind::Odometry:
        if (!s->has_odometry) continue;
        encode_odometry(layout_, *s, st.text);
        break;
      case Kind::Scan:
        st.last_scan = s->lasers[st.laser].count;
        encode_laser_scan(layout_, st.laser, *s, st.text);
        break;
      case Kind::RobotDescription:
      case Kind::Markers: continue;
    }
    server_->publish(channels_[c].id, stamp, std::make_shared<const std::string>(st.text));
  }
}

std::string live_url(const FoxgloveServer& server) {
  const std::string host = server.address() == "0.0.0.0" ? "localhost" : server.address();
  return "ws://" + host + ":" + std::to_string(server.port());
}

}  // namespace mechsim::live
