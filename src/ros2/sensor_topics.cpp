// The sensors' ROS 2 topics (sensor_topics.hpp).
#include "ros2/sensor_topics.hpp"

#include <map>
#include <variant>

#include <mechsim_ros2_msgs/geometry_msgs.hpp>
#include <mechsim_ros2_msgs/nav_msgs.hpp>
#include <mechsim_ros2_msgs/sensor_msgs.hpp>

#include "ros2/conversions.hpp"
#include "ros2/node.hpp"
#include "ros2/plugin_names.hpp"

namespace mechsim::ros2 {

namespace {

enum class Kind { Laser, Imu, Wrench, GroundTruth, Camera };

}  // namespace

struct SensorTopics::Output {
  std::size_t sensor = 0;
  Kind kind = Kind::Laser;
  std::string frame, child_frame;
  int row = 0;  // Laser: the published row of a multi-row scan
  std::unique_ptr<Node> node;
  // Whichever applies to the kind (shared with the outbox's jobs).
  std::shared_ptr<Publisher<sensor_msgs::msg::LaserScan>> laser;
  std::shared_ptr<Publisher<sensor_msgs::msg::Imu>> imu;
  std::shared_ptr<Publisher<geometry_msgs::msg::WrenchStamped>> wrench;
  std::shared_ptr<Publisher<nav_msgs::msg::Odometry>> odometry;
  std::vector<std::shared_ptr<Publisher<sensor_msgs::msg::Image>>> images;
  std::vector<std::shared_ptr<Publisher<sensor_msgs::msg::CameraInfo>>> infos;
  std::shared_ptr<Publisher<sensor_msgs::msg::Image>> depth;
  std::shared_ptr<Publisher<sensor_msgs::msg::CameraInfo>> depth_info;
  std::shared_ptr<Publisher<sensor_msgs::msg::PointCloud2>> points;
  std::string encoding;
  bool enabled = false;
  std::uint64_t published = 0;  // reading count last published (or skipped as stale)
  bool error_logged = false;

  bool wanted() const {
    auto any = [](const auto& p) { return p && p->matched() > 0; };
    if (any(laser) || any(imu) || any(wrench) || any(odometry) || any(depth) || any(points)) return true;
    for (const auto& p : images)
      if (any(p)) return true;
    for (const auto& p : infos)
      if (any(p)) return true;
    return any(depth_info);
  }
};

SensorTopics::SensorTopics(Participant& participant, bridge::SimBridge& bridge, Outbox& outbox)
    : participant_(participant), bridge_(bridge), outbox_(outbox) {
  for (const std::string& s : bridge.skipped_sensors()) participant_.log("sensor not simulated: " + s);
  for (std::size_t i = 0; i < bridge.sensor_count(); ++i) {
    bridge.set_sensor_enabled(i, false);  // nothing reads a sensor but its publishers
    try {
      add(i);
    } catch (const std::exception& e) {
      participant_.log(bridge.sensor_spec(i).where() + ": not published: " + e.what());
    }
  }
  for (const std::string& t : topics_) participant_.log("sensor " + t);
}

SensorTopics::~SensorTopics() = default;

void SensorTopics::add(std::size_t i) {
  const description::SensorSpec& spec = bridge_.sensor_spec(i);
  if (!spec.plugin) {
    participant_.log(spec.where() + " has no ROS plugin: not published");
    return;
  }
  const SensorNames names = sensor_names(spec);
  if (!names.unsupported.empty()) {
    participant_.log(spec.where() + ": " + names.unsupported + ": not published");
    return;
  }
  auto out = std::make_unique<Output>();
  Output& o = *out;
  o.sensor = i;
  o.frame = tf_frame(names.frame);
  o.node = std::make_unique<Node>(participant_, names.node_namespace, names.node_name, names.remaps);
  const Qos qos = Qos::sensor_data();
  auto note = [&](const std::string& topic, const std::string& type) {
    topics_.push_back(spec.name + " -> " + o.node->resolve(topic) + " (" + type + ", frame " + o.frame + ")");
  };
  const std::string kind = spec.kind_name();
  if (kind == "ray") {
    o.kind = Kind::Laser;
    o.laser = o.node->create_publisher<sensor_msgs::msg::LaserScan>(names.output, qos);
    note(names.output, "sensor_msgs/msg/LaserScan");
    const auto& ray = std::get<description::RaySpec>(spec.details);
    if (ray.vertical.count() > 1) {
      o.row = ray.vertical.count() / 2;
      participant_.log(spec.where() + " scans " + std::to_string(ray.vertical.count()) +
                       " rows: LaserScan is planar, its middle row is published");
    }
  } else if (kind == "imu") {
    o.kind = Kind::Imu;
    o.imu = o.node->create_publisher<sensor_msgs::msg::Imu>(names.output, qos);
    note(names.output, "sensor_msgs/msg/Imu");
  } else if (kind == "force_torque") {
    o.kind = Kind::Wrench;
    o.wrench = o.node->create_publisher<geometry_msgs::msg::WrenchStamped>(names.output, qos);
    note(names.output, "geometry_msgs/msg/WrenchStamped");
  } else if (kind == "ground_truth") {
    o.kind = Kind::GroundTruth;
    o.child_frame = tf_frame(spec.link);
    o.odometry = o.node->create_publisher<nav_msgs::msg::Odometry>(names.output, qos);
    note(names.output, "nav_msgs/msg/Odometry");
  } else if (kind == "camera") {
    o.kind = Kind::Camera;
    const auto& camera = std::get<description::CameraSpec>(spec.details);
    o.encoding = image_encoding(camera.lenses.empty() ? std::string() : camera.lenses.front().format);
    // Megabytes a frame: Fast DDS's own thread sends them.
    for (const std::string& t : names.images) {
      o.images.push_back(o.node->create_publisher<sensor_msgs::msg::Image>(t, qos, true));
      note(t, "sensor_msgs/msg/Image " + o.encoding);
    }
    for (const std::string& t : names.infos) {
      o.infos.push_back(o.node->create_publisher<sensor_msgs::msg::CameraInfo>(t, qos));
      note(t, "sensor_msgs/msg/CameraInfo");
    }
    if (!names.depth.empty()) {
      o.depth = o.node->create_publisher<sensor_msgs::msg::Image>(names.depth, qos, true);
      note(names.depth, "sensor_msgs/msg/Image 32FC1");
    }
    if (!names.depth_info.empty()) {
      o.depth_info = o.node->create_publisher<sensor_msgs::msg::CameraInfo>(names.depth_info, qos);
      note(names.depth_info, "sensor_msgs/msg/CameraInfo");
    }
    if (!names.points.empty()) {
      o.points = o.node->create_publisher<sensor_msgs::msg::PointCloud2>(names.points, qos, true);
      note(names.points, "sensor_msgs/msg/PointCloud2 xyz rgb");
    }
  } else {
    participant_.log(spec.where() + ": no ROS 2 output for sensors of kind " + kind + " (contact sensors publish "
                                    "gazebo_msgs/ContactsState, which mechsim's ROS 2 layer does not have yet)");
    return;
  }
  outputs_.push_back(std::move(out));
}

void SensorTopics::disable_all() {
  for (const std::unique_ptr<Output>& o : outputs_) {
    if (!o->enabled) continue;
    bridge_.set_sensor_enabled(o->sensor, false);
    o->enabled = false;
  }
}

void SensorTopics::publish() {
  for (const std::unique_ptr<Output>& op : outputs_) {
    Output& o = *op;
    const bool wanted = o.wanted();
    if (wanted != o.enabled) {
      bridge_.set_sensor_enabled(o.sensor, wanted);
      o.enabled = wanted;
      // What the sensor read before it was switched off is stale: wait for a fresh sample.
      o.published = bridge_.sensor_reading(o.sensor).count;
    }
    if (!wanted) continue;
    const sensors::SensorReading& r = bridge_.sensor_reading(o.sensor);
    if (r.count == o.published) continue;
    o.published = r.count;
    const auto stamp = to_time(r.stamp);
    // A new message, stamped and framed, filled here and written by the outbox thread.
    auto send = [&](const auto& publisher, auto fill) {
      using M = typename std::decay_t<decltype(*publisher)>::Message;
      auto message = std::make_shared<M>();
      message->header.stamp = stamp;
      message->header.frame_id = o.frame;
      fill(*message);
      auto pub = publisher;
      if (outbox_.post([pub, message] { pub->publish(*message); })) ++stats_.messages;
    };
    switch (o.kind) {
      case Kind::Laser:
        if (const auto* v = std::get_if<sensors::LaserScan>(&r.value))
          send(o.laser, [&](sensor_msgs::msg::LaserScan& m) { fill_laser_scan(*v, o.row, m); });
        break;
      case Kind::Imu:
        if (const auto* v = std::get_if<sensors::ImuReading>(&r.value))
          send(o.imu, [&](sensor_msgs::msg::Imu& m) { fill_imu(*v, m); });
        break;
      case Kind::Wrench:
        if (const auto* v = std::get_if<sensors::WrenchReading>(&r.value))
          send(o.wrench, [&](geometry_msgs::msg::WrenchStamped& m) { fill_wrench(*v, m); });
        break;
      case Kind::GroundTruth:
        if (const auto* v = std::get_if<sensors::GroundTruthReading>(&r.value)) {
          send(o.odometry, [&](nav_msgs::msg::Odometry& m) {
            fill_ground_truth(*v, m);
            m.child_frame_id = o.child_frame;
          });
        }
        break;
      case Kind::Camera: {
        const auto* reading = std::get_if<sensors::CameraReading>(&r.value);
        if (reading == nullptr) break;
        if (!reading->error.empty()) {
          if (!o.error_logged) participant_.log(bridge_.sensor_spec(o.sensor).where() + ": " + reading->error);
          o.error_logged = true;
          break;
        }
        ++stats_.camera_frames;
        for (std::size_t k = 0; k < reading->images.size(); ++k) {
          const sensors::CameraImage& image = reading->images[k];
          if (k < o.images.size() && o.images[k]->matched() > 0)
            send(o.images[k], [&](sensor_msgs::msg::Image& m) { fill_image(image, o.encoding, m); });
          if (k < o.infos.size() && o.infos[k]->matched() > 0)
            send(o.infos[k], [&](sensor_msgs::msg::CameraInfo& m) { fill_camera_info(image.info, m); });
          if (k > 0) continue;
          if (o.depth && o.depth->matched() > 0) send(o.depth, [&](sensor_msgs::msg::Image& m) { fill_depth_image(image, m); });
          if (o.depth_info && o.depth_info->matched() > 0)
            send(o.depth_info, [&](sensor_msgs::msg::CameraInfo& m) { fill_camera_info(image.info, m); });
          if (o.points && o.points->matched() > 0)
            send(o.points, [&](sensor_msgs::msg::PointCloud2& m) { fill_point_cloud(image, m); });
        }
        break;
      }
    }
  }
}

}  // namespace mechsim::ros2
