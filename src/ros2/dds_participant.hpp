#pragma once
// mechsim's DDS participant as a ROS 2 process presents it (eProsima Fast DDS underneath; only
// dds_participant.cpp includes its headers): one participant per process, the ROS 2 nodes of the
// process as entries of the `ros_discovery_info` graph message, and one DDS writer or reader per
// publisher or subscription.
//
// What makes it a ROS 2 process on the wire (../../../shared/ros2/README.md has the sources):
//   - participant USER_DATA "enclave=/;";
//   - endpoints' USER_DATA "typehash=RIHS01_<hex>;" (Jazzy only; Humble has no type hashes);
//   - `ros_discovery_info` (rmw_dds_common/msg/ParticipantEntitiesInfo: reliable, transient
//     local, keep last 1) listing each node's namespace, name and reader/writer GIDs (readers
//     first), republished on every change; its Gid is 24 bytes in Humble and 16 from Iron on, so
//     the distro is a setting;
//   - UDP only: Fast DDS's shared-memory transport is off, since its segments are not guaranteed
//     compatible across Fast DDS versions (Humble's rmw_fastrtps ships 2.6, Jazzy's 2.14, Debian
//     2.9); peers on the same machine then talk UDP over loopback.
//
// Bad input never stops the world: a malformed sample is dropped with a log line naming the topic
// and the writer; a peer's endpoint on one of mechsim's topics with another type, a QoS that does
// not match, a peer that leaves or vanishes (its lease expired) are log lines naming the topic.
//
// Threads: every call may come from any thread. Sample callbacks run on Fast DDS's receive
// threads; a callback must not block for long (it holds that reader's delivery). A Writer or
// Reader must be destroyed before the Participant that made it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ros2/qos.hpp"

namespace mechsim::ros2 {

enum class Distro : std::uint8_t { Humble, Jazzy };
const char* distro_name(Distro distro);                    // "humble", "jazzy"
std::optional<Distro> parse_distro(const std::string& name);  // humble | jazzy

using Guid = std::array<std::uint8_t, 16>;  // a DDS GUID: 12-byte prefix, 4-byte entity id
std::string guid_string(const Guid& guid);   // "010f4a1b.00000001.00000000:00000103"-like, for logs

// A log line's sink; the default prints "mechsim ros2: LINE" on stderr.
using LogFn = std::function<void(const std::string& line)>;

struct ParticipantOptions {
  int domain_id = 0;  // ROS_DOMAIN_ID
  Distro distro = Distro::Jazzy;
  std::string enclave = "/";
  // ROS_LOCALHOST_ONLY=1 (Humble) or ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST (Jazzy): loopback only.
  bool localhost_only = false;
  LogFn log;
};
// ROS_DOMAIN_ID (unset or empty: 0; else 0..232 as rmw accepts for UDP ports), ROS_LOCALHOST_ONLY,
// ROS_AUTOMATIC_DISCOVERY_RANGE, as rcl reads them. Throws std::runtime_error naming a bad value.
ParticipantOptions options_from_environment(Distro distro);

// A message to write, type-erased: `size` gives its serialized size (encapsulation included),
// `write` serializes it into a buffer of that many bytes and returns the bytes written.
struct OutMessage {
  const void* message = nullptr;
  std::size_t (*size)(const void* message) = nullptr;
  std::size_t (*write)(const void* message, char* buffer, std::size_t capacity) = nullptr;
};

// A sample's identity as RTPS carries it: its writer's GUID and sequence number.
// rmw_fastrtps matches a service reply to its request through it (issue 37).
struct SampleIdentity {
  Guid writer{};
  std::int64_t sequence = 0;
  bool valid() const { return sequence > 0; }
};

struct SampleInfo {
  SampleIdentity identity;  // of this sample
  SampleIdentity related;   // its related_sample_identity (unset: !valid())
};

// Called with a sample's serialized bytes (encapsulation header included).
using SampleCallback = std::function<void(const std::uint8_t* data, std::size_t size, const SampleInfo& info)>;

struct EndpointSpec {
  std::string dds_topic;   // "rt/clock"
  std::string ros_topic;   // "/clock": what log lines name
  std::string type_name;   // the DDS type name, "rosgraph_msgs::msg::dds_::Clock_"
  std::string type_hash;   // "RIHS01_...": Jazzy's USER_DATA (ignored for Humble)
  Qos qos;
  // Writers: Fast DDS's own thread sends the sample (write() only serializes it): for samples
  // of megabytes (images, clouds), written from the simulation's loop thread.
  bool asynchronous = false;
  // More USER_DATA ("serviceid=...;": what rmw_cyclonedds pairs a service's reader and writer by).
  std::string user_data;
};

class Participant;

class Writer {
 public:
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
  // False when Fast DDS refused the sample (logged, at most once a second per writer).
  bool write(const OutMessage& message);
  // A reply of a service (issue 37): `related` goes out as the sample's related_sample_identity;
  // `written` (may be null) receives the sample's own identity.
  bool write(const OutMessage& message, const SampleIdentity& related, SampleIdentity* written);
  int matched() const;  // readers matched now
  // Whether the reader `reader` is matched now (a service's reply goes to a client's reader only
  // once it is: a reliable writer does not keep a sample for a reader it has not matched yet).
  bool has_matched(const Guid& reader) const;
  const Guid& guid() const;
  const EndpointSpec& spec() const;

  struct Impl;

 private:
  friend class Participant;
  explicit Writer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

class Reader {
 public:
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;
  int matched() const;  // writers matched now
  const Guid& guid() const;
  const EndpointSpec& spec() const;

  struct Impl;

 private:
  friend class Participant;
  explicit Reader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

class Participant {
 public:
  // Creates the DDS participant and its ros_discovery_info writer. Throws std::runtime_error
  // (the domain id, or why Fast DDS refused).
  explicit Participant(ParticipantOptions options);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  // A ROS 2 node of this process (namespace absolute, name a valid token); returns its id. The
  // graph message lists it from now on. A node of the same namespace and name that exists is
  // shared (its id returned; remove_node removes it once every adder removed it).
  int add_node(const std::string& ns, const std::string& name);
  void remove_node(int node);
  // Endpoints of node `node`. Throws std::runtime_error when the topic is already used by this
  // participant with another type, or Fast DDS refuses the endpoint.
  std::unique_ptr<Writer> create_writer(int node, const EndpointSpec& spec);
  std::unique_ptr<Reader> create_reader(int node, const EndpointSpec& spec, SampleCallback callback);

  Distro distro() const;
  int domain_id() const;
  const Guid& guid() const;
  void log(const std::string& line) const;
  // The nodes as the graph message announces them ("/ns/name"), in creation order.
  std::vector<std::string> node_names() const;
  // Times the graph message was written (tests).
  std::uint64_t graph_writes() const;
  // The USER_DATA of a peer's reader or writer as discovered ("" when unknown or none).
  std::string remote_user_data(const Guid& endpoint) const;
  // The remote readers whose USER_DATA holds `text` (e.g. "clientid=X;").
  std::vector<Guid> remote_readers_with(const std::string& text) const;

  struct Impl;

 private:
  std::shared_ptr<Impl> impl_;
};

}  // namespace mechsim::ros2
