// The Fast DDS participant behind mechsim's ROS 2 nodes (dds_participant.hpp).
#include "ros2/dds_participant.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <stdexcept>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastdds/rtps/common/WriteParams.h>
#include <fastdds/rtps/participant/ParticipantDiscoveryInfo.h>
#include <fastdds/rtps/reader/ReaderDiscoveryInfo.h>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/writer/WriterDiscoveryInfo.h>

#include <mechsim_ros2_msgs/humble/rmw_dds_common.hpp>
#include <mechsim_ros2_msgs/jazzy/rmw_dds_common.hpp>

#include "ros2/fastdds_types.hpp"
#include "ros2/message_codec.hpp"

namespace mechsim::ros2 {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;
using eprosima::fastrtps::types::ReturnCode_t;

using fastdds_types::CdrType;
using fastdds_types::from_guid;
using fastdds_types::InSample;
using fastdds_types::policy_name;
using fastdds_types::to_guid;
using fastdds_types::to_identity;

namespace {

// Reliable writers announce what they hold this often (Fast DDS's default: 3 s). A peer that
// matched the writer after its first heartbeat (discovery is not symmetric: one side may match
// before the other) asks for a transient-local sample (/tf_static, /robot_description, the graph)
// at the next one; 3 s made a late joiner wait that long.
const eprosima::fastrtps::Duration_t kHeartbeatPeriod{0, 200000000};

std::vector<rtps::octet> user_data_of(const std::string& text) { return {text.begin(), text.end()}; }

// At most one line a second per caller (a flood of bad samples must not flood the log).
struct Throttle {
  std::chrono::steady_clock::time_point last{};
  std::uint64_t suppressed = 0;
  bool allow() {
    const auto now = std::chrono::steady_clock::now();
    if (last != std::chrono::steady_clock::time_point{} && now - last < std::chrono::seconds(1)) {
      ++suppressed;
      return false;
    }
    last = now;
    return true;
  }
};

}  // namespace

struct Participant::Impl : dds::DomainParticipantListener {
  ParticipantOptions options;
  dds::DomainParticipant* participant = nullptr;
  dds::Publisher* publisher = nullptr;
  dds::Subscriber* subscriber = nullptr;
  Guid guid{};

  struct TopicEntry {
    dds::Topic* topic = nullptr;
    std::string type_name;
    int users = 0;
  };
  struct NodeEntry {
    std::string ns, name;
    std::vector<Guid> readers, writers;
    int users = 1;  // Node objects of this name (a controller's topics and its parameters share it)
  };

  // Types, topics, nodes, graph writes. Held over Fast DDS calls (entity creation), so no Fast DDS
  // callback may take it: Fast DDS calls the discovery listener with its own discovery lock held,
  // and creating a writer takes that lock (a lock-order deadlock, seen once in 6 runs).
  mutable std::mutex mutex;
  std::map<std::string, dds::TypeSupport> types;
  std::map<std::string, TopicEntry> topics;  // by DDS topic name
  // What the discovery callbacks read: each topic's type (a copy of `topics`' types), under a lock
  // of its own that is never held over a Fast DDS call.
  mutable std::mutex topic_types_mutex;
  std::map<std::string, std::string> topic_types;
  std::map<int, NodeEntry> nodes;
  int next_node = 1;
  dds::DataWriter* graph_writer = nullptr;
  std::atomic<std::uint64_t> graph_write_count{0};
  // Peers' endpoints' USER_DATA, as discovered (services pair clients' endpoints by it).
  mutable std::mutex remote_mutex;
  std::map<Guid, std::string> remote_writers, remote_readers;

  void note_remote(std::map<Guid, std::string>& table, const rtps::GUID_t& g, const std::vector<rtps::octet>& data,
                   bool removed) {
    std::lock_guard<std::mutex> lock(remote_mutex);
    if (removed) table.erase(to_guid(g));
    else table[to_guid(g)] = std::string(data.begin(), data.end());
  }

  void log(const std::string& line) const {
    if (options.log) options.log(line);
    else std::fprintf(stderr, "mechsim ros2: %s\n", line.c_str());
  }

  // Under `mutex`.
  dds::Topic* acquire_topic(const std::string& dds_topic, const std::string& type_name) {
    if (auto it = topics.find(dds_topic); it != topics.end()) {
      if (it->second.type_name != type_name) {
        throw std::runtime_error("topic '" + dds_topic + "' is already used by mechsim with type " +
                                 it->second.type_name + ", not " + type_name);
      }
      ++it->second.users;
      return it->second.topic;
    }
    if (types.find(type_name) == types.end()) {
      dds::TypeSupport support(new CdrType(type_name));
      if (support.register_type(participant) != ReturnCode_t::RETCODE_OK) {
        throw std::runtime_error("Fast DDS refused to register type " + type_name);
      }
      types.emplace(type_name, support);
    }
    dds::Topic* topic = participant->create_topic(dds_topic, type_name, dds::TOPIC_QOS_DEFAULT);
    if (topic == nullptr) throw std::runtime_error("Fast DDS refused topic '" + dds_topic + "'");
    topics[dds_topic] = {topic, type_name, 1};
    {
      std::lock_guard<std::mutex> lock(topic_types_mutex);
      topic_types[dds_topic] = type_name;
    }
    return topic;
  }

  void release_topic(const std::string& dds_topic) {
    auto it = topics.find(dds_topic);
    if (it == topics.end()) return;
    if (--it->second.users > 0) return;
    {
      std::lock_guard<std::mutex> lock(topic_types_mutex);
      topic_types.erase(dds_topic);
    }
    participant->delete_topic(it->second.topic);
    topics.erase(it);
  }

  template <class Msg>
  void fill_graph(Msg& msg) {
    std::memcpy(msg.gid.data.data(), guid.data(), guid.size());
    for (const auto& [id, node] : nodes) {
      auto& info = msg.node_entities_info_seq.emplace_back();
      info.node_namespace = node.ns;
      info.node_name = node.name;
      for (const Guid& g : node.readers) std::memcpy(info.reader_gid_seq.emplace_back().data.data(), g.data(), g.size());
      for (const Guid& g : node.writers) std::memcpy(info.writer_gid_seq.emplace_back().data.data(), g.data(), g.size());
    }
  }

  // Under `mutex`: the graph message as it stands now (Gid zero-padded to 24 bytes in Humble).
  void publish_graph() {
    if (graph_writer == nullptr) return;
    auto write = [&](auto& msg) {
      fill_graph(msg);
      using M = std::decay_t<decltype(msg)>;
      OutMessage out{&msg, [](const void* m) { return serialized_size(*static_cast<const M*>(m)); },
                     [](const void* m, char* b, std::size_t c) { return serialize_into(*static_cast<const M*>(m), b, c); }};
      if (graph_writer->write(&out)) graph_write_count.fetch_add(1, std::memory_order_relaxed);
      else log("ros_discovery_info: Fast DDS refused the graph message");
    };
    if (options.distro == Distro::Humble) {
      humble::rmw_dds_common::msg::ParticipantEntitiesInfo msg;
      write(msg);
    } else {
      jazzy::rmw_dds_common::msg::ParticipantEntitiesInfo msg;
      write(msg);
    }
  }

  std::string topic_of(const std::string& dds_name) const {
    const std::string ros = ros_topic_of_dds(dds_name);
    return ros.empty() ? dds_name : ros;
  }
  static std::string ros_topic_of_dds(const std::string& dds_name) {
    if (dds_name.size() > 2 && (dds_name.rfind("rt/", 0) == 0)) return dds_name.substr(2);
    return "";
  }

  // A peer's endpoint on one of mechsim's topics with another type never matches: say so.
  void check_peer_type(const rtps::GUID_t& remote, const std::string& topic, const std::string& type,
                       const char* what) {
    if (remote.guidPrefix == participant->guid().guidPrefix) return;
    std::string ours;
    {
      std::lock_guard<std::mutex> lock(topic_types_mutex);
      auto it = topic_types.find(topic);
      if (it == topic_types.end() || it->second == type) return;
      ours = it->second;
    }
    log(topic_of(topic) + ": a peer's " + what + " (" + guid_string(to_guid(remote)) + ") uses type " + type +
        ", mechsim's is " + ours + ": they do not match, nothing passes between them");
  }

  void on_participant_discovery(dds::DomainParticipant*, rtps::ParticipantDiscoveryInfo&& info) override {
    const std::string who = "peer participant '" + std::string(info.info.m_participantName.c_str()) + "' (" +
                            guid_string(to_guid(info.info.m_guid)) + ")";
    switch (info.status) {
      case rtps::ParticipantDiscoveryInfo::DISCOVERED_PARTICIPANT: log(who + " joined domain " + std::to_string(options.domain_id)); break;
      case rtps::ParticipantDiscoveryInfo::REMOVED_PARTICIPANT: log(who + " left"); break;
      case rtps::ParticipantDiscoveryInfo::DROPPED_PARTICIPANT: log(who + " vanished (its lease expired)"); break;
      default: break;
    }
  }
  void on_subscriber_discovery(dds::DomainParticipant*, rtps::ReaderDiscoveryInfo&& info) override {
    note_remote(remote_readers, info.info.guid(), info.info.m_qos.m_userData.data_vec(),
                info.status == rtps::ReaderDiscoveryInfo::REMOVED_READER);
    if (info.status == rtps::ReaderDiscoveryInfo::DISCOVERED_READER)
      check_peer_type(info.info.guid(), info.info.topicName().to_string(), info.info.typeName().to_string(), "subscription");
  }
  void on_publisher_discovery(dds::DomainParticipant*, rtps::WriterDiscoveryInfo&& info) override {
    note_remote(remote_writers, info.info.guid(), info.info.m_qos.m_userData.data_vec(),
                info.status == rtps::WriterDiscoveryInfo::REMOVED_WRITER);
    if (info.status == rtps::WriterDiscoveryInfo::DISCOVERED_WRITER)
      check_peer_type(info.info.guid(), info.info.topicName().to_string(), info.info.typeName().to_string(), "publisher");
  }

  void add_endpoint(int node, const Guid& g, bool writer) {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = nodes.find(node);
    if (it == nodes.end()) return;
    (writer ? it->second.writers : it->second.readers).push_back(g);
    publish_graph();
  }
  void remove_endpoint(int node, const Guid& g) {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = nodes.find(node);
    if (it == nodes.end()) return;
    for (auto* list : {&it->second.writers, &it->second.readers}) {
      for (auto e = list->begin(); e != list->end(); ++e) {
        if (*e == g) {
          list->erase(e);
          break;
        }
      }
    }
    publish_graph();
  }

  void endpoint_qos(const EndpointSpec& spec, dds::RTPSEndpointQos& endpoint, dds::UserDataQosPolicy& user_data,
                    dds::ReliabilityQosPolicy& reliability, dds::DurabilityQosPolicy& durability,
                    dds::HistoryQosPolicy& history) const {
    reliability.kind = spec.qos.reliability == Reliability::Reliable ? dds::RELIABLE_RELIABILITY_QOS
                                                                     : dds::BEST_EFFORT_RELIABILITY_QOS;
    durability.kind = spec.qos.durability == Durability::TransientLocal ? dds::TRANSIENT_LOCAL_DURABILITY_QOS
                                                                        : dds::VOLATILE_DURABILITY_QOS;
    history.kind = dds::KEEP_LAST_HISTORY_QOS;
    history.depth = spec.qos.depth > 0 ? spec.qos.depth : 1;
    // Samples of every size (images of megabytes) in pools that grow as needed, as rmw_fastrtps.
    endpoint.history_memory_policy = rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
    std::string text = spec.user_data;
    if (options.distro == Distro::Jazzy && !spec.type_hash.empty()) text = "typehash=" + spec.type_hash + ";" + text;
    if (!text.empty()) user_data.data_vec(user_data_of(text));
  }
};

// ---- writers

struct Writer::Impl : dds::DataWriterListener {
  std::shared_ptr<Participant::Impl> owner;
  int node = 0;
  EndpointSpec spec;
  dds::DataWriter* writer = nullptr;
  Guid guid{};
  std::atomic<int> matched{0};
  std::mutex throttle_mutex;
  Throttle refused;
  mutable std::mutex readers_mutex;
  std::vector<Guid> readers;  // matched now (Fast DDS 2.9 cannot list them: kept from the callbacks)

  void on_publication_matched(dds::DataWriter*, const dds::PublicationMatchedStatus& s) override {
    matched.store(s.current_count, std::memory_order_relaxed);
    {
      const Guid reader = to_guid(rtps::iHandle2GUID(s.last_subscription_handle));
      std::lock_guard<std::mutex> lock(readers_mutex);
      std::erase(readers, reader);
      if (s.current_count_change > 0) readers.push_back(reader);
    }
    if (s.current_count_change < 0) {
      owner->log(spec.ros_topic + ": a subscriber left (" + std::to_string(s.current_count) + " matched now)");
    }
  }
  void on_offered_incompatible_qos(dds::DataWriter*, const dds::OfferedIncompatibleQosStatus& s) override {
    owner->log(spec.ros_topic + ": a subscriber asks for a " + policy_name(s.last_policy_id) +
               " this publisher does not offer (it offers " + spec.qos.describe() + "): not matched");
  }
  bool write(const OutMessage& m, rtps::WriteParams* params) {
    OutMessage copy = m;
    const bool ok = params != nullptr ? writer->write(&copy, *params) : writer->write(&copy);
    if (!ok) {
      std::lock_guard<std::mutex> lock(throttle_mutex);
      if (refused.allow()) owner->log(spec.ros_topic + ": Fast DDS refused a sample; it is dropped");
    }
    return ok;
  }
};

Writer::Writer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Writer::~Writer() {
  auto& o = *impl_->owner;
  o.remove_endpoint(impl_->node, impl_->guid);
  impl_->writer->set_listener(nullptr);
  std::lock_guard<std::mutex> lock(o.mutex);
  o.publisher->delete_datawriter(impl_->writer);
  o.release_topic(impl_->spec.dds_topic);
}

bool Writer::write(const OutMessage& message) { return impl_->write(message, nullptr); }

bool Writer::write(const OutMessage& message, const SampleIdentity& related, SampleIdentity* written) {
  rtps::WriteParams params;
  if (related.valid()) {
    rtps::SampleIdentity id;
    id.writer_guid(from_guid(related.writer));
    id.sequence_number(rtps::SequenceNumber_t(static_cast<std::int32_t>(related.sequence >> 32),
                                              static_cast<std::uint32_t>(related.sequence & 0xffffffffu)));
    params.related_sample_identity(id);
  }
  const bool ok = impl_->write(message, &params);
  if (ok && written != nullptr) *written = to_identity(params.sample_identity());
  return ok;
}

int Writer::matched() const { return impl_->matched.load(std::memory_order_relaxed); }

bool Writer::has_matched(const Guid& reader) const {
  std::lock_guard<std::mutex> lock(impl_->readers_mutex);
  return std::find(impl_->readers.begin(), impl_->readers.end(), reader) != impl_->readers.end();
}
const Guid& Writer::guid() const { return impl_->guid; }
const EndpointSpec& Writer::spec() const { return impl_->spec; }

// ---- readers

struct Reader::Impl : dds::DataReaderListener {
  std::shared_ptr<Participant::Impl> owner;
  int node = 0;
  EndpointSpec spec;
  dds::DataReader* reader = nullptr;
  Guid guid{};
  SampleCallback callback;
  std::atomic<int> matched{0};
  std::mutex mutex;  // held while a callback runs; `alive` false once the reader goes
  bool alive = true;
  InSample sample;

  void on_data_available(dds::DataReader* r) override {
    std::lock_guard<std::mutex> lock(mutex);
    dds::SampleInfo info;
    while (alive && r->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data) continue;
      SampleInfo meta;
      meta.identity = to_identity(info.sample_identity);
      meta.related = to_identity(info.related_sample_identity);
      try {
        callback(sample.bytes.data(), sample.bytes.size(), meta);
      } catch (const std::exception& e) {
        owner->log(spec.ros_topic + ": a sample's handler failed: " + e.what());
      }
    }
  }
  void on_subscription_matched(dds::DataReader*, const dds::SubscriptionMatchedStatus& s) override {
    matched.store(s.current_count, std::memory_order_relaxed);
    if (s.current_count_change < 0) {
      owner->log(spec.ros_topic + ": a publisher left (" + std::to_string(s.current_count) + " matched now)");
    }
  }
  void on_requested_incompatible_qos(dds::DataReader*, const dds::RequestedIncompatibleQosStatus& s) override {
    owner->log(spec.ros_topic + ": a publisher offers a " + policy_name(s.last_policy_id) +
               " that this subscription (" + spec.qos.describe() + ") cannot take: not matched");
  }
};

Reader::Reader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Reader::~Reader() {
  auto& o = *impl_->owner;
  o.remove_endpoint(impl_->node, impl_->guid);
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->alive = false;
  }
  impl_->reader->set_listener(nullptr);
  std::lock_guard<std::mutex> lock(o.mutex);
  o.subscriber->delete_datareader(impl_->reader);
  o.release_topic(impl_->spec.dds_topic);
}

int Reader::matched() const { return impl_->matched.load(std::memory_order_relaxed); }
const Guid& Reader::guid() const { return impl_->guid; }
const EndpointSpec& Reader::spec() const { return impl_->spec; }

// ---- participant

Participant::Participant(ParticipantOptions options) : impl_(std::make_shared<Impl>()) {
  Impl& p = *impl_;
  p.options = std::move(options);
  if (p.options.domain_id < 0 || p.options.domain_id > 232) {
    throw std::runtime_error("domain id " + std::to_string(p.options.domain_id) + " is outside 0..232");
  }
  dds::DomainParticipantQos qos = dds::PARTICIPANT_QOS_DEFAULT;
  qos.name("mechsim");
  qos.user_data().data_vec(user_data_of("enclave=" + p.options.enclave + ";"));
  // UDP only: no shared memory (see the header).
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  if (p.options.localhost_only) udp->interfaceWhiteList.emplace_back("127.0.0.1");
  qos.transport().use_builtin_transports = false;
  qos.transport().user_transports.push_back(udp);
  // Both mask and listener: peers joining and leaving, peers' endpoints (type check). Data and
  // matching go to each endpoint's own listener.
  dds::StatusMask mask = dds::StatusMask::none();
  p.participant = dds::DomainParticipantFactory::get_instance()->create_participant(
      static_cast<dds::DomainId_t>(p.options.domain_id), qos, &p, mask);
  if (p.participant == nullptr) {
    throw std::runtime_error("Fast DDS could not create a participant on domain " +
                             std::to_string(p.options.domain_id));
  }
  p.guid = to_guid(p.participant->guid());
  p.publisher = p.participant->create_publisher(dds::PUBLISHER_QOS_DEFAULT);
  p.subscriber = p.participant->create_subscriber(dds::SUBSCRIBER_QOS_DEFAULT);
  if (p.publisher == nullptr || p.subscriber == nullptr) throw std::runtime_error("Fast DDS refused a publisher or subscriber");
  // The graph topic: no "rt" prefix (avoid_ros_namespace_conventions), reliable, transient local,
  // keep last 1, as rmw's context creates it.
  EndpointSpec graph;
  graph.dds_topic = "ros_discovery_info";
  graph.ros_topic = "ros_discovery_info";
  graph.type_name = "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_";
  graph.type_hash = p.options.distro == Distro::Jazzy
                        ? MessageTraits<jazzy::rmw_dds_common::msg::ParticipantEntitiesInfo>::type_hash
                        : "";
  graph.qos = Qos::latched();
  std::lock_guard<std::mutex> lock(p.mutex);
  dds::Topic* topic = p.acquire_topic(graph.dds_topic, graph.type_name);
  dds::DataWriterQos wq = dds::DATAWRITER_QOS_DEFAULT;
  p.endpoint_qos(graph, wq.endpoint(), wq.user_data(), wq.reliability(), wq.durability(), wq.history());
  wq.data_sharing().off();
  wq.reliable_writer_qos().times.heartbeatPeriod = kHeartbeatPeriod;
  p.graph_writer = p.publisher->create_datawriter(topic, wq);
  if (p.graph_writer == nullptr) throw std::runtime_error("Fast DDS refused the ros_discovery_info writer");
  p.publish_graph();
}

Participant::~Participant() {
  Impl& p = *impl_;
  if (p.participant == nullptr) return;
  p.participant->set_listener(nullptr);
  p.participant->delete_contained_entities();
  dds::DomainParticipantFactory::get_instance()->delete_participant(p.participant);
  p.participant = nullptr;
}

int Participant::add_node(const std::string& ns, const std::string& name) {
  Impl& p = *impl_;
  std::lock_guard<std::mutex> lock(p.mutex);
  // One ROS 2 node of one name: a second Node object of it shares its graph entry.
  for (auto& [id, node] : p.nodes) {
    if (node.ns == ns && node.name == name) {
      ++node.users;
      return id;
    }
  }
  const int id = p.next_node++;
  p.nodes[id] = {ns, name, {}, {}, 1};
  p.publish_graph();
  return id;
}

void Participant::remove_node(int node) {
  Impl& p = *impl_;
  std::lock_guard<std::mutex> lock(p.mutex);
  const auto it = p.nodes.find(node);
  if (it == p.nodes.end() || --it->second.users > 0) return;
  p.nodes.erase(it);
  p.publish_graph();
}

std::unique_ptr<Writer> Participant::create_writer(int node, const EndpointSpec& spec) {
  Impl& p = *impl_;
  auto impl = std::make_unique<Writer::Impl>();
  impl->owner = impl_;
  impl->node = node;
  impl->spec = spec;
  {
    std::lock_guard<std::mutex> lock(p.mutex);
    dds::Topic* topic = p.acquire_topic(spec.dds_topic, spec.type_name);
    dds::DataWriterQos qos = dds::DATAWRITER_QOS_DEFAULT;
    p.endpoint_qos(spec, qos.endpoint(), qos.user_data(), qos.reliability(), qos.durability(), qos.history());
    qos.data_sharing().off();
    qos.publish_mode().kind = spec.asynchronous ? dds::ASYNCHRONOUS_PUBLISH_MODE : dds::SYNCHRONOUS_PUBLISH_MODE;
    qos.reliable_writer_qos().times.heartbeatPeriod = kHeartbeatPeriod;
    impl->writer = p.publisher->create_datawriter(topic, qos, impl.get(), dds::StatusMask::publication_matched() <<
                                                                            dds::StatusMask::offered_incompatible_qos());
    if (impl->writer == nullptr) {
      p.release_topic(spec.dds_topic);
      throw std::runtime_error(spec.ros_topic + ": Fast DDS refused the publisher (" + spec.qos.describe() + ")");
    }
    impl->guid = to_guid(impl->writer->guid());
  }
  p.add_endpoint(node, impl->guid, true);
  return std::unique_ptr<Writer>(new Writer(std::move(impl)));
}

std::unique_ptr<Reader> Participant::create_reader(int node, const EndpointSpec& spec, SampleCallback callback) {
  Impl& p = *impl_;
  auto impl = std::make_unique<Reader::Impl>();
  impl->owner = impl_;
  impl->node = node;
  impl->spec = spec;
  impl->callback = std::move(callback);
  {
    std::lock_guard<std::mutex> lock(p.mutex);
    dds::Topic* topic = p.acquire_topic(spec.dds_topic, spec.type_name);
    dds::DataReaderQos qos = dds::DATAREADER_QOS_DEFAULT;
    p.endpoint_qos(spec, qos.endpoint(), qos.user_data(), qos.reliability(), qos.durability(), qos.history());
    qos.data_sharing().off();
    impl->reader = p.subscriber->create_datareader(
        topic, qos, impl.get(),
        dds::StatusMask::data_available() << dds::StatusMask::subscription_matched()
                                          << dds::StatusMask::requested_incompatible_qos());
    if (impl->reader == nullptr) {
      p.release_topic(spec.dds_topic);
      throw std::runtime_error(spec.ros_topic + ": Fast DDS refused the subscription (" + spec.qos.describe() + ")");
    }
    impl->guid = to_guid(impl->reader->guid());
  }
  p.add_endpoint(node, impl->guid, false);
  return std::unique_ptr<Reader>(new Reader(std::move(impl)));
}

Distro Participant::distro() const { return impl_->options.distro; }
int Participant::domain_id() const { return impl_->options.domain_id; }
const Guid& Participant::guid() const { return impl_->guid; }
void Participant::log(const std::string& line) const { impl_->log(line); }

std::vector<std::string> Participant::node_names() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  std::vector<std::string> out;
  for (const auto& [id, node] : impl_->nodes) out.push_back((node.ns == "/" ? "" : node.ns) + "/" + node.name);
  return out;
}

std::uint64_t Participant::graph_writes() const { return impl_->graph_write_count.load(std::memory_order_relaxed); }

std::string Participant::remote_user_data(const Guid& endpoint) const {
  std::lock_guard<std::mutex> lock(impl_->remote_mutex);
  if (auto it = impl_->remote_writers.find(endpoint); it != impl_->remote_writers.end()) return it->second;
  if (auto it = impl_->remote_readers.find(endpoint); it != impl_->remote_readers.end()) return it->second;
  return "";
}

std::vector<Guid> Participant::remote_readers_with(const std::string& text) const {
  std::lock_guard<std::mutex> lock(impl_->remote_mutex);
  std::vector<Guid> out;
  for (const auto& [guid, data] : impl_->remote_readers)
    if (data.find(text) != std::string::npos) out.push_back(guid);
  return out;
}

}  // namespace mechsim::ros2
