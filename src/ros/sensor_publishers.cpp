// SensorPublishers: the topics of the simulated sensors (sensor_publishers.hpp).
#include "ros/sensor_publishers.hpp"

#include <time.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <variant>

#include <boost/make_shared.hpp>

#include <pr2_msgs/PressureState.h>
#include <std_msgs/Empty.h>
#include <std_srvs/Empty.h>

#include "ros/publish_helpers.hpp"
#include "ros/sensor_messages.hpp"
#include "sensors/pr2_fingertip_pressure.hpp"

namespace mechsim::ros {

namespace {

enum class Kind { Laser, Range, BlockCloud, Imu, Contacts, Wrench, Odometry, Camera };

// CPU time of the calling thread (s): on a loaded machine wall time would count the other
// processes' turns.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

bool any_subscribed(const std::vector<::ros::Publisher>& publishers) {
  for (const ::ros::Publisher& p : publishers)
    if (p && p.getNumSubscribers() > 0) return true;
  return false;
}

}  // namespace

struct SensorPublishers::Output {
  std::size_t sensor = 0;
  Kind kind = Kind::Laser;
  std::string name;
  std::string frame;        // header.frame_id
  std::string child_frame;  // Odometry: the body
  int row = 0;              // Laser: the published row of a multi-row scan
  // The publishers whose subscribers make the sensor sample (a camera's images, depth, points).
  std::vector<::ros::Publisher> triggers;
  // Set by roscpp's connect/disconnect callbacks (spinner threads), read by the tick.
  std::atomic<bool> wanted{false};
  bool enabled = false;         // as the sensor set has it
  std::uint64_t published = 0;  // reading count last published (or skipped as stale)
  bool error_logged = false;

  // Cameras: per lens an image and an info publisher; depth sensors also depth, depth_info, points.
  std::string encoding;
  std::vector<::ros::Publisher> images, infos;
  ::ros::Publisher depth, depth_info, points;
  // Only camera_info subscribed (rostest's hztest on a camera_info topic): the plugins publish it
  // at the camera's rate; mechsim does without rendering, from the intrinsics.
  std::atomic<bool> info_wanted{false};
  // gazebo_ros_triggered_camera: frames owed (one per message on its trigger topic, counted by the
  // subscriber's callback), and whether the one asked for has come.
  ::ros::Subscriber trigger;
  std::atomic<int> trigger_count{0};
  bool awaiting_frame = false;
  std::vector<sensors::CameraInfo> lens_infos;
  double period = 0.0;    // s of sim time between camera_info messages
  double next_info = 0.0;  // s of sim time

  // Under a lock so that the last recount sees the last connection change (a recount that read
  // the counts before a connection cannot overwrite the one its callback made after it).
  void recount() {
    std::lock_guard<std::mutex> lock(recount_mutex);
    wanted.store(any_subscribed(triggers), std::memory_order_relaxed);
    info_wanted.store(any_subscribed(infos) || (depth_info && depth_info.getNumSubscribers() > 0), std::memory_order_relaxed);
  }
  std::mutex recount_mutex;
};

// /pressure/<side>_gripper_motor from the side's two fingertip contact sensors.
struct SensorPublishers::Pressure {
  std::string topic;
  Output* left = nullptr;   // <side>_gripper_l_finger_tip_contact_sensor
  Output* right = nullptr;  // <side>_gripper_r_finger_tip_contact_sensor
  ::ros::Publisher publisher;
  std::atomic<int> subscribers{0};  // kept by the connect/disconnect callbacks
  double next_due = 0.0;            // s of sim time
};

namespace {

constexpr double kPressurePeriod = 1.0 / 25.0;  // s of sim time: the real PR2's 25 Hz

// advertise() with callbacks that recount the output's subscribers.
template <class M>
::ros::Publisher advertise(::ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue,
                           SensorPublishers::Output& o) {
  auto status = [&o](const ::ros::SingleSubscriberPublisher&) { o.recount(); };
  return nh.advertise<M>(topic, queue, status, status);
}

}  // namespace

// The thread that hands messages to roscpp. roscpp's publish() serialises the message and writes
// it to each connection under its locks (a camera frame: ~1 ms CPU for 2.7 MB, a point cloud
// ~25 ms), so the tick only fills a message and queues it here. A full queue drops the newest
// message (counted) rather than wait: the tick never waits on a subscriber or on roscpp.
class SensorPublishers::Sender {
 public:
  Sender() : thread_([this] { run(); }) {}
  ~Sender() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  bool push(std::function<void()> job) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (jobs_.size() >= kMaxJobs) return false;
      jobs_.push_back(std::move(job));
    }
    return true;
  }
  // Once per tick after the pushes: one wake-up (and context switch) per tick, not per message.
  void wake() { wake_.notify_one(); }
  double cpu_seconds() {
    std::lock_guard<std::mutex> lock(mutex_);
    return cpu_;
  }

 private:
  static constexpr std::size_t kMaxJobs = 256;
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
      if (jobs_.empty()) return;  // stopping, everything sent
      std::function<void()> job = std::move(jobs_.front());
      jobs_.pop_front();
      lock.unlock();
      const double start = thread_cpu_seconds();
      job();
      const double spent = thread_cpu_seconds() - start;
      lock.lock();
      cpu_ += spent;
    }
  }
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stop_ = false;
  double cpu_ = 0.0;
  std::thread thread_;  // last: starts once the rest exists
};

template <class M, class Fill>
void SensorPublishers::send(const ::ros::Publisher& publisher, const ::ros::Time& stamp, const std::string& frame,
                            Fill&& fill) {
  auto message = boost::make_shared<M>();
  message->header.stamp = stamp;
  message->header.frame_id = frame;
  fill(*message);
  if (sender_->push([publisher, message] { publisher.publish(message); })) ++stats_.messages;
  else ++stats_.dropped;
  pushed_ = true;
}

SensorPublishers::SensorPublishers(::ros::NodeHandle root, SimBridge& bridge)
    : root_(std::move(root)), bridge_(bridge), sender_(std::make_unique<Sender>()) {
  for (const std::string& s : bridge.skipped_sensors()) ROS_WARN_STREAM("mechsim: sensor not simulated: " << s);
  for (std::size_t i = 0; i < bridge.sensor_count(); ++i) {
    // Nothing in the node reads a sensor but its publisher: off until a subscriber comes.
    bridge.set_sensor_enabled(i, false);
    const description::SensorSpec& spec = bridge.sensor_spec(i);
    if (!spec.plugin) {
      ROS_INFO_STREAM("mechsim: " << spec.where() << " has no ROS plugin: not published");
      continue;
    }
    if (!spec.plugin->unsupported.empty()) {
      ROS_WARN_STREAM("mechsim: " << spec.where() << ": " << spec.plugin->unsupported << ": not published");
      continue;
    }
    const std::string frame = tf_frame(spec.plugin->frame);
    const std::string kind = spec.kind_name();
    if (kind == "camera") {
      add_camera(i, spec, frame);
      continue;
    }
    auto out = std::make_unique<Output>();
    Output& o = *out;
    o.sensor = i;
    o.name = spec.name;
    o.frame = frame;
    const std::string topic = spec.plugin->full_topic();
    std::string type;
    const auto* ray = std::get_if<description::RaySpec>(&spec.details);
    if (ray != nullptr && ray->output == description::RayOutput::Range) {
      o.kind = Kind::Range;
      o.triggers.push_back(advertise<sensor_msgs::Range>(root_, topic, 1, o));
      type = "sensor_msgs/Range";
    } else if (ray != nullptr && ray->output == description::RayOutput::PointCloud) {
      o.kind = Kind::BlockCloud;
      o.triggers.push_back(advertise<sensor_msgs::PointCloud>(root_, topic, 1, o));
      type = "sensor_msgs/PointCloud";
    } else if (ray != nullptr) {
      o.kind = Kind::Laser;
      o.triggers.push_back(advertise<sensor_msgs::LaserScan>(root_, topic, 10, o));
      type = "sensor_msgs/LaserScan";
      if (ray->vertical.count() > 1) {
        o.row = ray->vertical.count() / 2;
        ROS_WARN_STREAM("mechsim: " << spec.where() << " scans " << ray->vertical.count()
                                    << " rows: LaserScan is planar, its middle row is published");
      }
    } else if (kind == "imu") {
      o.kind = Kind::Imu;
      // A second of a 100 Hz IMU: roscpp drops what its queue cannot hold while the sender
      // thread waits for a core, and a filter (robot_pose_ekf) wants every sample.
      o.triggers.push_back(advertise<sensor_msgs::Imu>(root_, topic, 100, o));
      type = "sensor_msgs/Imu";
      // gazebo_ros_imu's and hector's calibration service (<serviceName>): a simulated IMU has
      // no bias to learn, so, as theirs, it answers at once.
      if (const auto* imu = std::get_if<description::ImuSpec>(&spec.details); imu && !imu->service_name.empty())
        services_.push_back(root_.advertiseService<std_srvs::Empty::Request, std_srvs::Empty::Response>(
            imu->service_name, +[](std_srvs::Empty::Request&, std_srvs::Empty::Response&) { return true; }));
    } else if (kind == "contact") {
      o.kind = Kind::Contacts;
      o.triggers.push_back(advertise<gazebo_msgs::ContactsState>(root_, topic, 10, o));
      type = "gazebo_msgs/ContactsState";
    } else if (kind == "force_torque") {
      o.kind = Kind::Wrench;
      o.triggers.push_back(advertise<geometry_msgs::WrenchStamped>(root_, topic, 10, o));
      type = "geometry_msgs/WrenchStamped";
    } else if (kind == "ground_truth") {
      o.kind = Kind::Odometry;
      o.triggers.push_back(advertise<nav_msgs::Odometry>(root_, topic, 10, o));
      o.child_frame = tf_frame(spec.link);
      type = "nav_msgs/Odometry";
    } else {
      ROS_WARN_STREAM("mechsim: " << spec.where() << ": no ROS output for sensors of kind " << kind);
      continue;
    }
    topics_.push_back(spec.name + " -> " + topic + " (" + type + ", frame " + o.frame + ")");
    outputs_.push_back(std::move(out));
  }
  add_pressure("l");
  add_pressure("r");
  for (const std::string& t : topics_) ROS_INFO_STREAM("mechsim: sensor " << t);
}

void SensorPublishers::add_pressure(const std::string& side) {
  auto p = std::make_unique<Pressure>();
  for (const std::unique_ptr<Output>& o : outputs_) {
    if (o->kind != Kind::Contacts) continue;
    if (o->name == side + "_gripper_l_finger_tip_contact_sensor") p->left = o.get();
    if (o->name == side + "_gripper_r_finger_tip_contact_sensor") p->right = o.get();
  }
  if (!p->left || !p->right) return;
  // The pads' geometry is in the fingertip link's frame: the bumpers must report in it.
  for (Output* o : {p->left, p->right}) {
    const std::string link = tf_frame(bridge_.sensor_spec(o->sensor).link);
    if (o->frame != link) {
      ROS_WARN_STREAM("mechsim: " << o->name << " reports contacts in '" << o->frame << "', not in its link '" << link
                                  << "': no /pressure/" << side << "_gripper_motor");
      return;
    }
  }
  p->topic = "/pressure/" + side + "_gripper_motor";
  Pressure& ref = *p;
  // A pressure subscriber makes both fingertip sensors sample.
  auto count = [&ref](int change) {
    ref.subscribers.fetch_add(change, std::memory_order_relaxed);
    ref.left->recount();
    ref.right->recount();
  };
  p->publisher = root_.advertise<pr2_msgs::PressureState>(
      p->topic, 10, [count](const ::ros::SingleSubscriberPublisher&) { count(1); },
      [count](const ::ros::SingleSubscriberPublisher&) { count(-1); });
  p->left->triggers.push_back(p->publisher);
  p->right->triggers.push_back(p->publisher);
  topics_.push_back(p->left->name + " + " + p->right->name + " -> " + p->topic + " (pr2_msgs/PressureState, 25 Hz)");
  pressures_.push_back(std::move(p));
}

void SensorPublishers::publish_pressure(Pressure& p, double time) {
  p.next_due = next_due_after(time, kPressurePeriod);
  const auto* l = std::get_if<sensors::ContactsReading>(&bridge_.sensor_reading(p.left->sensor).value);
  const auto* r = std::get_if<sensors::ContactsReading>(&bridge_.sensor_reading(p.right->sensor).value);
  if (!l || !r) return;
  const auto left = sensors::fingertip_pressure(*l, sensors::Fingertip::Left);
  const auto right = sensors::fingertip_pressure(*r, sensors::Fingertip::Right);
  send<pr2_msgs::PressureState>(p.publisher, ::ros::Time(time), "", [&](pr2_msgs::PressureState& m) {
    m.l_finger_tip.assign(left.begin(), left.end());
    m.r_finger_tip.assign(right.begin(), right.end());
  });
}

SensorPublishers::~SensorPublishers() = default;

SensorPublishStats SensorPublishers::stats() const {
  SensorPublishStats s = stats_;
  s.sender_cpu_seconds = sender_->cpu_seconds();
  return s;
}

void SensorPublishers::add_camera(std::size_t sensor, const description::SensorSpec& spec, const std::string& frame) {
  const auto& camera = std::get<description::CameraSpec>(spec.details);
  auto out = std::make_unique<Output>();
  Output& o = *out;
  o.sensor = sensor;
  o.kind = Kind::Camera;
  o.name = spec.name;
  o.frame = frame;
  o.encoding = image_encoding(camera.lenses.empty() ? std::string() : camera.lenses.front().format);
  o.lens_infos = bridge_.camera_infos(sensor);
  o.period = spec.update_rate > 0.0 ? 1.0 / spec.update_rate : 0.0;
  auto note = [&](const std::string& topic, const char* type) {
    topics_.push_back(spec.name + " -> " + topic + " (" + type + ", frame " + frame + ")");
  };
  if (o.encoding == "bgr8" && !camera.lenses.empty() && camera.lenses.front().format != "B8G8R8" &&
      camera.lenses.front().format != "BGR_INT8") {
    ROS_WARN_STREAM("mechsim: " << spec.where() << ": gazebo_ros_camera_utils has no encoding for image format "
                                << camera.lenses.front().format << " and publishes it as bgr8; so does mechsim");
  }
  // Queue 1: a frame is megabytes; a subscriber that cannot keep up gets the newest. A lens
  // without a topic (a multicamera's camera named neither left nor right) publishes nothing.
  for (std::size_t k = 0; k < camera.image_topics.size(); ++k) {
    if (camera.image_topics[k].empty()) {
      o.images.emplace_back();
      continue;
    }
    o.images.push_back(advertise<sensor_msgs::Image>(root_, camera.image_topics[k], 1, o));
    o.triggers.push_back(o.images.back());
    note(camera.image_topics[k], ("sensor_msgs/Image " + o.encoding).c_str());
  }
  for (const std::string& topic : camera.info_topics) {
    if (topic.empty()) {
      o.infos.emplace_back();
      continue;
    }
    o.infos.push_back(advertise<sensor_msgs::CameraInfo>(root_, topic, 1, o));
    note(topic, "sensor_msgs/CameraInfo");
  }
  if (!camera.trigger_topic.empty()) {
    std::atomic<int>& count = o.trigger_count;
    o.trigger = root_.subscribe<std_msgs::Empty>(camera.trigger_topic, 10,
                                                 [&count](const std_msgs::Empty::ConstPtr&) { count.fetch_add(1); });
    topics_.push_back(spec.name + " <- " + camera.trigger_topic + " (std_msgs/Empty: one frame each)");
  }
  if (camera.depth && !camera.depth_topic.empty()) {
    o.depth = advertise<sensor_msgs::Image>(root_, camera.depth_topic, 1, o);
    o.triggers.push_back(o.depth);
    note(camera.depth_topic, "sensor_msgs/Image 32FC1");
    if (!camera.depth_info_topic.empty()) {
      o.depth_info = advertise<sensor_msgs::CameraInfo>(root_, camera.depth_info_topic, 1, o);
      note(camera.depth_info_topic, "sensor_msgs/CameraInfo");
    }
  }
  if (camera.depth && !camera.points_topic.empty()) {
    o.points = advertise<sensor_msgs::PointCloud2>(root_, camera.points_topic, 1, o);
    o.triggers.push_back(o.points);
    note(camera.points_topic, "sensor_msgs/PointCloud2 xyz rgb");
  }
  outputs_.push_back(std::move(out));
}

void SensorPublishers::publish() {
  // Wall time (a vDSO read, ~25 ns) around the whole call; the thread's CPU clock (a system
  // call, ~1 us) only around what is published.
  const auto wall_start = std::chrono::steady_clock::now();
  double cpu_start = -1.0;
  ++stats_.calls;
  for (const std::unique_ptr<Output>& op : outputs_) {
    Output& o = *op;
    if (o.trigger) {
      if (cpu_start < 0.0) cpu_start = thread_cpu_seconds();
      publish_triggered(o);
      continue;
    }
    const bool wanted = o.wanted.load(std::memory_order_relaxed);
    if (wanted != o.enabled) {
      bridge_.set_sensor_enabled(o.sensor, wanted);
      o.enabled = wanted;
      // What the sensor read before it was switched off is stale: wait for a fresh sample.
      o.published = bridge_.sensor_reading(o.sensor).count;
    }
    if (!wanted) {
      if (o.kind == Kind::Camera && o.info_wanted.load(std::memory_order_relaxed)) {
        if (cpu_start < 0.0) cpu_start = thread_cpu_seconds();
        publish_camera_info_only(o);
      }
      continue;
    }
    const sensors::SensorReading& r = bridge_.sensor_reading(o.sensor);
    if (r.count == o.published) continue;
    o.published = r.count;
    // roscpp may call a disconnect callback before it drops the connection: the count it then
    // saw is corrected here, at the sensor's rate.
    o.recount();
    if (!o.wanted.load(std::memory_order_relaxed)) continue;
    if (cpu_start < 0.0) cpu_start = thread_cpu_seconds();
    const ::ros::Time stamp(r.stamp);
    const ::ros::Publisher& pub = o.triggers[0];
    switch (o.kind) {
      case Kind::Laser:
        if (const auto* v = std::get_if<sensors::LaserScan>(&r.value))
          send<sensor_msgs::LaserScan>(pub, stamp, o.frame, [&](auto& m) { fill_laser_scan(*v, o.row, m); });
        break;
      case Kind::Range:
        if (const auto* v = std::get_if<sensors::RangeReading>(&r.value))
          send<sensor_msgs::Range>(pub, stamp, o.frame, [&](auto& m) { fill_range(*v, m); });
        break;
      case Kind::BlockCloud:
        if (const auto* v = std::get_if<sensors::PointCloudReading>(&r.value))
          send<sensor_msgs::PointCloud>(pub, stamp, o.frame, [&](auto& m) { fill_block_cloud(*v, m); });
        break;
      case Kind::Imu:
        if (const auto* v = std::get_if<sensors::ImuReading>(&r.value))
          send<sensor_msgs::Imu>(pub, stamp, o.frame, [&](auto& m) { fill_imu(*v, m); });
        break;
      case Kind::Contacts:
        // A fingertip's sensor may sample for /pressure only.
        if (pub.getNumSubscribers() == 0) break;
        if (const auto* v = std::get_if<sensors::ContactsReading>(&r.value))
          send<gazebo_msgs::ContactsState>(pub, stamp, o.frame, [&](auto& m) { fill_contacts(*v, r.stamp, m); });
        break;
      case Kind::Wrench:
        if (const auto* v = std::get_if<sensors::WrenchReading>(&r.value))
          send<geometry_msgs::WrenchStamped>(pub, stamp, o.frame, [&](auto& m) { fill_wrench(*v, m); });
        break;
      case Kind::Odometry:
        if (const auto* v = std::get_if<sensors::GroundTruthReading>(&r.value)) {
          send<nav_msgs::Odometry>(pub, stamp, o.frame, [&](auto& m) {
            fill_odometry(*v, m);
            m.child_frame_id = o.child_frame;
          });
        }
        break;
      case Kind::Camera: publish_camera(o, r); break;
    }
  }
  for (const std::unique_ptr<Pressure>& p : pressures_) {
    if (p->subscribers.load(std::memory_order_relaxed) <= 0) continue;
    const double time = bridge_.time();
    if (time + 1e-9 < p->next_due) continue;
    if (cpu_start < 0.0) cpu_start = thread_cpu_seconds();
    publish_pressure(*p, time);
  }
  if (pushed_) sender_->wake();
  pushed_ = false;
  if (cpu_start >= 0.0) stats_.publish_cpu_seconds += thread_cpu_seconds() - cpu_start;
  stats_.wall_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
}

void SensorPublishers::publish_camera_info_only(Output& o) {
  const double time = bridge_.time();
  // Not due yet (unless the clock went back, a reset of the world).
  if (time + 1e-9 < o.next_info && o.next_info - time <= o.period + 1e-9) return;
  o.next_info = o.period > 0.0 ? next_due_after(time, o.period) : time;
  const ::ros::Time stamp(time);
  for (std::size_t k = 0; k < o.infos.size() && k < o.lens_infos.size(); ++k) {
    if (o.infos[k] && o.infos[k].getNumSubscribers() > 0)
      send<sensor_msgs::CameraInfo>(o.infos[k], stamp, o.frame, [&](auto& m) { fill_camera_info(o.lens_infos[k], m); });
  }
  if (o.depth_info && o.depth_info.getNumSubscribers() > 0 && !o.lens_infos.empty())
    send<sensor_msgs::CameraInfo>(o.depth_info, stamp, o.frame, [&](auto& m) { fill_camera_info(o.lens_infos.front(), m); });
}

// gazebo_ros_triggered_camera: the camera renders only for a trigger (the plugin turns it on for
// one frame per trigger), and that frame, with its camera_info, goes to the subscribers there are.
// A trigger with nobody subscribed is spent without a frame (the plugin renders one and drops it).
void SensorPublishers::publish_triggered(Output& o) {
  const sensors::SensorReading& r = bridge_.sensor_reading(o.sensor);
  if (o.awaiting_frame && r.count != o.published) {
    o.published = r.count;
    o.awaiting_frame = false;
    o.recount();
    publish_camera(o, r);
  }
  if (o.awaiting_frame || o.trigger_count.load() <= 0) return;
  o.trigger_count.fetch_sub(1);
  o.recount();
  if (!o.wanted.load(std::memory_order_relaxed) && !o.info_wanted.load(std::memory_order_relaxed)) return;
  bridge_.request_sensor_sample(o.sensor);
  o.published = r.count;
  o.awaiting_frame = true;
}

void SensorPublishers::publish_camera(Output& o, const sensors::SensorReading& r) {
  const auto* reading = std::get_if<sensors::CameraReading>(&r.value);
  if (reading == nullptr) return;
  if (!reading->error.empty()) {
    if (!o.error_logged) ROS_ERROR_STREAM("mechsim: camera '" << o.name << "' renders nothing: " << reading->error);
    o.error_logged = true;
    return;
  }
  const double start = thread_cpu_seconds();
  const ::ros::Time stamp(r.stamp);
  // Each topic only for its own subscribers: a depth-only subscriber costs no colour copy.
  for (std::size_t k = 0; k < reading->images.size(); ++k) {
    const sensors::CameraImage& image = reading->images[k];
    if (k < o.images.size() && o.images[k] && o.images[k].getNumSubscribers() > 0)
      send<sensor_msgs::Image>(o.images[k], stamp, o.frame, [&](auto& m) { fill_image(image, o.encoding, m); });
    // camera_info goes with every frame, as the plugins publish it with the image.
    if (k < o.infos.size() && o.infos[k] && o.infos[k].getNumSubscribers() > 0)
      send<sensor_msgs::CameraInfo>(o.infos[k], stamp, o.frame, [&](auto& m) { fill_camera_info(image.info, m); });
  }
  if (!reading->images.empty()) {
    const sensors::CameraImage& image = reading->images.front();
    if (o.depth && o.depth.getNumSubscribers() > 0)
      send<sensor_msgs::Image>(o.depth, stamp, o.frame, [&](auto& m) { fill_depth_image(image, m); });
    if (o.depth_info && o.depth_info.getNumSubscribers() > 0)
      send<sensor_msgs::CameraInfo>(o.depth_info, stamp, o.frame, [&](auto& m) { fill_camera_info(image.info, m); });
    if (o.points && o.points.getNumSubscribers() > 0)
      send<sensor_msgs::PointCloud2>(o.points, stamp, o.frame, [&](auto& m) { fill_point_cloud(image, o.encoding, m); });
  }
  ++stats_.camera_frames;
  stats_.camera_seconds += thread_cpu_seconds() - start;
}

}  // namespace mechsim::ros
