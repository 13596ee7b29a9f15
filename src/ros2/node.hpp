#pragma once
// A ROS 2 node of mechsim's participant, with typed publishers and subscriptions of the generated
// message types (<mechsim_ros2_msgs/...>): names resolved as rcl resolves them (names.hpp), DDS
// names and type names as rmw mangles them, the type hash in Jazzy's USER_DATA.
//
//   Node node(participant, "/cc8", "diff_drive_controller");
//   auto odom = node.create_publisher<nav_msgs::msg::Odometry>("~/odom", Qos::defaults());
//   odom->publish(msg);
//   auto cmd = node.create_subscription<geometry_msgs::msg::TwistStamped>(
//       "~/cmd_vel", Qos::command_reader(), [](const geometry_msgs::msg::TwistStamped& m) { ... });
//
// A subscription deserializes each sample itself: a malformed one is dropped with a log line
// naming the topic, the writer and what is wrong (at most one line a second per subscription).

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "ros2/dds_participant.hpp"
#include "ros2/message_codec.hpp"
#include "ros2/names.hpp"

namespace mechsim::ros2 {

template <class M>
class Publisher {
 public:
  using Message = M;
  explicit Publisher(std::unique_ptr<Writer> writer) : writer_(std::move(writer)) {}
  bool publish(const M& message) { return writer_->write(out(message)); }
  // A service reply (issue 37): related_sample_identity set to `related`.
  bool publish(const M& message, const SampleIdentity& related, SampleIdentity* written = nullptr) {
    return writer_->write(out(message), related, written);
  }
  int matched() const { return writer_->matched(); }
  const std::string& topic() const { return writer_->spec().ros_topic; }
  const Writer& writer() const { return *writer_; }

  static OutMessage out(const M& message) {
    return {&message, [](const void* m) { return serialized_size(*static_cast<const M*>(m)); },
            [](const void* m, char* buffer, std::size_t capacity) {
              return serialize_into(*static_cast<const M*>(m), buffer, capacity);
            }};
  }

 private:
  std::unique_ptr<Writer> writer_;
};

// Counts of a subscription's samples (tests, logs).
struct SubscriptionStats {
  std::atomic<std::uint64_t> received{0}, malformed{0};
};

template <class M>
class Subscription {
 public:
  Subscription(std::unique_ptr<Reader> reader, std::shared_ptr<SubscriptionStats> stats)
      : reader_(std::move(reader)), stats_(std::move(stats)) {}
  int matched() const { return reader_->matched(); }
  const std::string& topic() const { return reader_->spec().ros_topic; }
  std::uint64_t received() const { return stats_->received.load(); }
  std::uint64_t malformed() const { return stats_->malformed.load(); }

 private:
  std::unique_ptr<Reader> reader_;
  std::shared_ptr<SubscriptionStats> stats_;
};

class Node {
 public:
  // Throws NameError for a bad namespace or name.
  Node(Participant& participant, const std::string& ns, const std::string& name, std::vector<Remap> remaps = {})
      : participant_(participant), ns_(normalize_namespace(ns)), name_(name), remaps_(std::move(remaps)) {
    check_node_name(name_);
    id_ = participant_.add_node(ns_, name_);
  }
  ~Node() { participant_.remove_node(id_); }
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  const std::string& ns() const { return ns_; }
  const std::string& name() const { return name_; }
  int id() const { return id_; }  // in its participant (Participant::create_writer/create_reader)
  std::string fq_name() const { return (ns_ == "/" ? "" : ns_) + "/" + name_; }
  Participant& participant() { return participant_; }
  // The fully qualified name of `topic` for this node, remappings applied. Throws NameError.
  std::string resolve(const std::string& topic) const { return resolve_topic(topic, ns_, name_, remaps_); }

  template <class M>
  std::unique_ptr<Publisher<M>> create_publisher(const std::string& topic, Qos qos, bool asynchronous = false) {
    EndpointSpec spec = endpoint<M>(topic, qos);
    spec.asynchronous = asynchronous;
    return std::make_unique<Publisher<M>>(participant_.create_writer(id_, spec));
  }

  template <class M>
  std::unique_ptr<Subscription<M>> create_subscription(const std::string& topic, Qos qos,
                                                       std::function<void(const M&, const SampleInfo&)> callback) {
    const EndpointSpec spec = endpoint<M>(topic, qos);
    auto stats = std::make_shared<SubscriptionStats>();
    auto throttle = std::make_shared<std::pair<std::mutex, std::chrono::steady_clock::time_point>>();
    Participant* participant = &participant_;
    const std::string name = spec.ros_topic;
    SampleCallback raw = [callback = std::move(callback), stats, throttle, participant, name](
                             const std::uint8_t* data, std::size_t size, const SampleInfo& info) {
      M message;
      std::string error;
      if (!deserialize(data, size, message, &error)) {
        const std::uint64_t count = stats->malformed.fetch_add(1) + 1;
        std::lock_guard<std::mutex> lock(throttle->first);
        const auto now = std::chrono::steady_clock::now();
        if (throttle->second == std::chrono::steady_clock::time_point{} || now - throttle->second >= std::chrono::seconds(1)) {
          throttle->second = now;
          participant->log(name + ": malformed " + MessageTraits<M>::ros_name + " sample from " +
                           guid_string(info.identity.writer) + " dropped (" + error + "; " + std::to_string(count) +
                           " so far)");
        }
        return;
      }
      stats->received.fetch_add(1);
      callback(message, info);
    };
    return std::make_unique<Subscription<M>>(participant_.create_reader(id_, spec, std::move(raw)), stats);
  }

  template <class M>
  std::unique_ptr<Subscription<M>> create_subscription(const std::string& topic, Qos qos,
                                                       std::function<void(const M&)> callback) {
    return create_subscription<M>(topic, qos, std::function<void(const M&, const SampleInfo&)>(
                                                  [callback = std::move(callback)](const M& m, const SampleInfo&) { callback(m); }));
  }

 private:
  template <class M>
  EndpointSpec endpoint(const std::string& topic, Qos qos) const {
    EndpointSpec spec;
    spec.ros_topic = resolve(topic);
    spec.dds_topic = dds_topic(spec.ros_topic);
    spec.type_name = MessageTraits<M>::dds_name;
    spec.type_hash = MessageTraits<M>::type_hash;
    spec.qos = qos;
    return spec;
  }

  Participant& participant_;
  std::string ns_, name_;
  std::vector<Remap> remaps_;
  int id_ = 0;
};

}  // namespace mechsim::ros2
