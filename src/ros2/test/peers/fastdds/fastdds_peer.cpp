// A ROS 2 peer on eProsima Fast DDS (Debian's libfastrtps-dev: the library under
// rmw_fastrtps_cpp) for mechsim's ROS 2 wire tests. Its messages are Fast DDS's own DynamicData,
// built at run time from the official ROS 2 field lists (fast_types.hpp) and serialized by Fast
// DDS: nothing of mechsim's generated message code. Same command line and JSON-lines output as
// the Cyclone peer (../cyclone/cyclone_peer.c):
//
//   fastdds_peer --domain D --seconds S [--distro humble|jazzy]
//       [--sub TOPIC=KIND[:QOS]]...   KIND: clock tf tf_static joint_state laser image camera_info
//                                           odometry imu string graph;  QOS: be rel tl
//       [--pub TOPIC=KIND:VALUES]...  twist twist_stamped float64_array string trajectory
//       [--rate HZ]
//       [--request SERVICE=PKG/srv/TYPE=JSON[@N]]...  call any service of the definitions below
//                                     with that request (N times at once: every reply matched by
//                                     its related_sample_identity), in order, before --call;
//                                     prints {"service","form","available","replies","sent",
//                                     "response" (the first reply, decoded),"ms"}
//       [--script JSON]               a scripted client (../common/script.hpp: service calls, action
//                                     goals, cancels, results, topics), first of all
//       [--lease S]                   the participant's lease (Fast DDS's default: 20 s)
//       [--call SERVICE=empty]...     call a std_srvs/srv/Empty service first, as an rmw_fastrtps_cpp
//                                     client does (reply reader GUID as the request's
//                                     related_sample_identity; the reply matched by its
//                                     related_sample_identity); then subscribe and publish
//
// Like rmw_fastrtps_cpp, the peer uses Fast DDS's default transports (UDP and shared memory; with
// mechsim, which offers UDP only, UDP is what they share) and announces no type information.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/rtps/common/WriteParams.h>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>
#include <fastrtps/types/DynamicTypeBuilderFactory.h>
#include <fastrtps/types/DynamicTypeBuilderPtr.h>
#include <nlohmann/json.hpp>

#include "../common/ros2_definitions.hpp"
#include "../common/script.hpp"
#include "fast_backend.hpp"
#include "fast_types.hpp"

namespace fdds = eprosima::fastdds::dds;
namespace types = eprosima::fastrtps::types;
using nlohmann::json;

namespace {

using mechsim::ros2::peers::Fields;
using mechsim::ros2::peers::definitions;
using namespace mechsim::ros2::peers::fast;  // Types, DynamicData <-> JSON, FastBackend
namespace peers = mechsim::ros2::peers;

// ---- what a test checks, in the Cyclone peer's form
json time_of(const json& t) { return {{"sec", t["sec"]}, {"nanosec", t["nanosec"]}}; }
json header_of(const json& h) { return {{"stamp", time_of(h["stamp"])}, {"frame_id", h["frame_id"]}}; }
json xyz(const json& v) { return json::array({v["x"], v["y"], v["z"]}); }
json xyzw(const json& v) { return json::array({v["x"], v["y"], v["z"], v["w"]}); }

json describe(const std::string& kind, const json& m) {
  auto with_header = [&](json out) {
    const json h = header_of(m["header"]);
    out["stamp"] = h["stamp"];
    out["frame_id"] = h["frame_id"];
    return out;
  };
  if (kind == "clock") return {{"clock", time_of(m["clock"])}};
  if (kind == "tf" || kind == "tf_static") {
    json transforms = json::array();
    for (const json& t : m["transforms"]) {
      json one = header_of(t["header"]);
      one["child"] = t["child_frame_id"];
      one["t"] = xyz(t["transform"]["translation"]);
      one["q"] = xyzw(t["transform"]["rotation"]);
      transforms.push_back(one);
    }
    return {{"count", m["transforms"].size()}, {"transforms", transforms}};
  }
  if (kind == "joint_state") return with_header({{"name", m["name"]}, {"position", m["position"]}, {"velocity", m["velocity"]}});
  if (kind == "laser") {
    double lo = 1e30, hi = -1e30;
    int finite = 0;
    for (const json& r : m["ranges"]) {
      const double v = r.get<double>();
      if (std::isfinite(v)) {
        ++finite;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    return with_header({{"angle_min", m["angle_min"]}, {"angle_max", m["angle_max"]}, {"angle_increment", m["angle_increment"]},
                        {"range_min", m["range_min"]}, {"range_max", m["range_max"]}, {"ranges", m["ranges"].size()},
                        {"finite", finite}, {"nearest", finite ? lo : -1.0}, {"farthest", finite ? hi : -1.0}});
  }
  if (kind == "image") {
    double sum = 0;
    for (const json& b : m["data"]) sum += b.get<double>();
    const std::size_t n = m["data"].size();
    return with_header({{"height", m["height"]}, {"width", m["width"]}, {"encoding", m["encoding"]}, {"step", m["step"]},
                        {"bytes", n}, {"mean", n ? sum / static_cast<double>(n) : 0.0}});
  }
  if (kind == "camera_info") {
    return with_header({{"height", m["height"]}, {"width", m["width"]}, {"distortion_model", m["distortion_model"]},
                        {"d", m["d"]}, {"k", m["k"]}, {"p", m["p"]}});
  }
  if (kind == "odometry") {
    return with_header({{"child_frame_id", m["child_frame_id"]}, {"position", xyz(m["pose"]["pose"]["position"])},
                        {"orientation", xyzw(m["pose"]["pose"]["orientation"])}, {"linear", xyz(m["twist"]["twist"]["linear"])},
                        {"angular", xyz(m["twist"]["twist"]["angular"])}});
  }
  if (kind == "imu") return with_header({{"orientation", xyzw(m["orientation"])}, {"linear_acceleration", xyz(m["linear_acceleration"])}});
  if (kind == "string") {
    const std::string s = m["data"];
    return {{"length", s.size()}, {"head", s.substr(0, 80)}};
  }
  if (kind == "graph") {
    std::string gid;
    char hex[3];
    for (const json& b : m["gid"]["data"]) {
      std::snprintf(hex, sizeof hex, "%02x", b.get<unsigned>());
      gid += hex;
    }
    json nodes = json::array();
    for (const json& n : m["node_entities_info_seq"]) {
      nodes.push_back({{"namespace", n["node_namespace"]}, {"name", n["node_name"]}, {"readers", n["reader_gid_seq"].size()},
                       {"writers", n["writer_gid_seq"].size()}});
    }
    return {{"gid_size", m["gid"]["data"].size()}, {"gid", gid}, {"nodes", nodes}};
  }
  return json::object();
}

struct Kind {
  std::string type;  // "sensor_msgs/Image"
  char reliability;  // 'r' reliable, 'b' best effort
  bool transient_local;
  int depth;
};
const std::map<std::string, Kind> kKinds = {
    {"clock", {"rosgraph_msgs/Clock", 'b', false, 1}},        {"tf", {"tf2_msgs/TFMessage", 'r', false, 100}},
    {"tf_static", {"tf2_msgs/TFMessage", 'r', true, 100}},    {"joint_state", {"sensor_msgs/JointState", 'r', false, 10}},
    {"laser", {"sensor_msgs/LaserScan", 'b', false, 5}},      {"image", {"sensor_msgs/Image", 'b', false, 5}},
    {"camera_info", {"sensor_msgs/CameraInfo", 'b', false, 5}}, {"odometry", {"nav_msgs/Odometry", 'r', false, 10}},
    {"imu", {"sensor_msgs/Imu", 'b', false, 5}},              {"string", {"std_msgs/String", 'r', true, 1}},
    {"graph", {"rmw_dds_common/ParticipantEntitiesInfo", 'r', true, 1}},
    {"twist", {"geometry_msgs/Twist", 'r', false, 10}},       {"twist_stamped", {"geometry_msgs/TwistStamped", 'r', false, 10}},
    {"float64_array", {"std_msgs/Float64MultiArray", 'r', false, 10}},
    {"trajectory", {"trajectory_msgs/JointTrajectory", 'r', false, 10}},
};

std::vector<double> doubles(const std::string& text) {
  std::vector<double> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) out.push_back(std::stod(item));
  return out;
}

// The command a --pub VALUES string stands for.
json command(const std::string& kind, const std::string& values) {
  if (kind == "twist" || kind == "twist_stamped") {
    std::vector<double> v = doubles(values);
    v.resize(6, 0.0);
    const json twist = {{"linear", {{"x", v[0]}, {"y", v[1]}, {"z", v[2]}}}, {"angular", {{"x", v[3]}, {"y", v[4]}, {"z", v[5]}}}};
    if (kind == "twist") return twist;
    return {{"header", {{"stamp", {{"sec", 0}, {"nanosec", 0}}}, {"frame_id", "base_link"}}}, {"twist", twist}};
  }
  if (kind == "float64_array") return {{"data", doubles(values)}};
  if (kind == "string") return {{"data", values}};
  if (kind == "trajectory") {  // joints:positions:seconds
    const auto a = values.find(':'), b = values.rfind(':');
    std::vector<std::string> names;
    std::stringstream s(values.substr(0, a));
    std::string n;
    while (std::getline(s, n, ',')) names.push_back(n);
    const double t = std::stod(values.substr(b + 1));
    const json point = {{"positions", doubles(values.substr(a + 1, b - a - 1))},
                        {"time_from_start", {{"sec", static_cast<int>(t)}, {"nanosec", static_cast<unsigned>((t - std::floor(t)) * 1e9)}}}};
    return {{"header", {{"stamp", {{"sec", 0}, {"nanosec", 0}}}, {"frame_id", ""}}}, {"joint_names", names}, {"points", {point}}};
  }
  return json::object();
}



}  // namespace

int main(int argc, char** argv) {
  int domain = 0;
  double seconds = 5, rate = 20;
  std::string distro = "jazzy";
  struct Sub {
    std::string topic, kind, qos;
    fdds::DataReader* reader = nullptr;
    types::DynamicData_ptr data;
    long count = 0;
    double first = 0, last = 0;
    json last_sample;
    std::vector<std::string> children;  // tf: every child frame seen
  };
  struct Pub {
    std::string topic, kind, values;
    fdds::DataWriter* writer = nullptr;
    types::DynamicData_ptr data;
    long sent = 0;
  };
  std::vector<Sub> subs;
  std::vector<Pub> pubs;
  std::vector<std::string> calls;
  struct Request {
    std::string service, type;
    json body;
    int count = 1;
  };
  std::vector<Request> requests;
  std::string script;
  double lease = 0.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--domain" && more) domain = std::atoi(argv[++i]);
    else if (a == "--seconds" && more) seconds = std::atof(argv[++i]);
    else if (a == "--rate" && more) rate = std::atof(argv[++i]);
    else if (a == "--distro" && more) distro = argv[++i];
    else if (a == "--script" && more) script = argv[++i];
    else if (a == "--lease" && more) lease = std::atof(argv[++i]);
    else if (a == "--request" && more) {
      const std::string spec = argv[++i];
      const auto eq1 = spec.find('=');
      const auto eq2 = spec.find('=', eq1 + 1);
      if (eq1 == std::string::npos || eq2 == std::string::npos) {
        std::fprintf(stderr, "fastdds_peer: --request SERVICE=PKG/srv/TYPE=JSON[@N]\n");
        return 2;
      }
      Request r;
      r.service = spec.substr(0, eq1);
      r.type = spec.substr(eq1 + 1, eq2 - eq1 - 1);
      std::string body = spec.substr(eq2 + 1);
      if (const auto at = body.rfind('@'); at != std::string::npos && body.find('}', at) == std::string::npos) {
        r.count = std::atoi(body.c_str() + at + 1);
        body = body.substr(0, at);
      }
      r.body = json::parse(body);
      requests.push_back(r);
    }
    else if (a == "--call" && more) {
      const std::string spec = argv[++i];
      if (spec.size() < 7 || spec.substr(spec.size() - 6) != "=empty") {
        std::fprintf(stderr, "fastdds_peer: --call SERVICE=empty\n");
        return 2;
      }
      calls.push_back(spec.substr(0, spec.size() - 6));
    }
    else if ((a == "--sub" || a == "--pub") && more) {
      const std::string spec = argv[++i];
      const auto eq = spec.find('=');
      const auto colon = spec.find(':', eq);
      const std::string topic = spec.substr(0, eq);
      const std::string kind = spec.substr(eq + 1, colon == std::string::npos ? std::string::npos : colon - eq - 1);
      const std::string rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
      if (eq == std::string::npos || kKinds.count(kind) == 0) {
        std::fprintf(stderr, "fastdds_peer: bad %s '%s'\n", a.c_str(), spec.c_str());
        return 2;
      }
      if (a == "--sub") subs.push_back({topic, kind, rest});
      else pubs.push_back({topic, kind, rest});
    } else {
      std::fprintf(stderr, "fastdds_peer: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  Types types_(distro);
  fdds::DomainParticipantQos pq = fdds::PARTICIPANT_QOS_DEFAULT;
  pq.name("fastdds_peer");
  const std::string enclave = "enclave=/;";
  pq.user_data().data_vec(std::vector<eprosima::fastrtps::rtps::octet>(enclave.begin(), enclave.end()));
  if (lease > 0.0) {
    // A short lease: a peer that vanishes (the tests' crash) is noticed in `lease` seconds, not
    // Fast DDS's default 20.
    auto& discovery = pq.wire_protocol().builtin.discovery_config;
    discovery.leaseDuration = eprosima::fastrtps::Duration_t(lease);
    discovery.leaseDuration_announcementperiod = eprosima::fastrtps::Duration_t(lease / 4.0);
  }
  fdds::DomainParticipant* pp = fdds::DomainParticipantFactory::get_instance()->create_participant(domain, pq);
  if (pp == nullptr) {
    std::fprintf(stderr, "fastdds_peer: no participant\n");
    return 1;
  }
  fdds::Subscriber* subscriber = pp->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  fdds::Publisher* publisher = pp->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  std::map<std::string, fdds::Topic*> topics;
  auto topic_for = [&](const std::string& ros_topic, const std::string& type) {
    const std::string name = ros_topic[0] == '/' ? "rt" + ros_topic : ros_topic;
    if (auto it = topics.find(name); it != topics.end()) return it->second;
    types::DynamicType_ptr dt = types_.get(type);
    fdds::TypeSupport support(type_support(dt));
    support->auto_fill_type_object(false);
    support->auto_fill_type_information(false);
    support.register_type(pp);
    return topics[name] = pp->create_topic(name, support.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  };
  auto since = [](auto t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  // The script's client lives to the end (its writers keep their samples), and goes before the
  // participant's entities.
  auto backend = std::make_unique<FastBackend>(pp, publisher, subscriber, types_);
  auto runner = std::make_unique<peers::Script>(*backend);
  if (!script.empty()) {
    peers::json steps;
    try {
      steps = peers::json::parse(script);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fastdds_peer: --script: %s\n", e.what());
      return 2;
    }
    if (const int rc = runner->run(steps); rc != 0) return rc;
  }
  for (const Request& rq_spec : requests) {
    // As rmw_fastrtps_cpp's client: request writer and reply reader (services' default QoS); the
    // reply reader's GUID in each request's related_sample_identity; replies matched by theirs.
    fdds::DataWriterQos wq = fdds::DATAWRITER_QOS_DEFAULT;
    wq.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
    wq.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
    wq.history().depth = std::max(10, rq_spec.count);
    wq.endpoint().history_memory_policy = eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
    fdds::DataReaderQos rq = fdds::DATAREADER_QOS_DEFAULT;
    rq.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
    rq.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
    rq.history().depth = std::max(10, rq_spec.count);
    rq.endpoint().history_memory_policy = eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
    const std::string req_type = rq_spec.type + "_Request", rep_type = rq_spec.type + "_Response";
    fdds::DataWriter* w = publisher->create_datawriter(topic_for("rq" + rq_spec.service + "Request", req_type), wq);
    fdds::DataReader* r = subscriber->create_datareader(topic_for("rr" + rq_spec.service + "Reply", rep_type), rq);
    const auto t0 = std::chrono::steady_clock::now();
    bool available = false;
    while (!available && since(t0) < 8.0) {
      fdds::PublicationMatchedStatus pm;
      fdds::SubscriptionMatchedStatus sm;
      w->get_publication_matched_status(pm);
      r->get_subscription_matched_status(sm);
      available = pm.current_count > 0 && sm.current_count > 0;
      if (!available) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    types::DynamicData_ptr request(types::DynamicDataFactory::get_instance()->create_data(types_.get(req_type)));
    types::DynamicData_ptr reply(types::DynamicDataFactory::get_instance()->create_data(types_.get(rep_type)));
    write_message(types_, request.get(), req_type, rq_spec.body);
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<eprosima::fastrtps::rtps::SampleIdentity> sent;
    for (int k = 0; available && k < rq_spec.count; ++k) {
      eprosima::fastrtps::rtps::WriteParams params;
      params.related_sample_identity().writer_guid(r->guid());
      if (w->write(request.get(), params)) sent.push_back(params.sample_identity());
    }
    int replies = 0, foreign = 0;
    json first;
    std::vector<bool> got(sent.size(), false);
    while (replies < static_cast<int>(sent.size()) && since(t1) < 30.0) {
      fdds::SampleInfo info;
      while (r->take_next_sample(reply.get(), &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data) continue;
        const auto it = std::find(sent.begin(), sent.end(), info.related_sample_identity);
        if (it == sent.end() || got[it - sent.begin()]) {
          ++foreign;
          continue;
        }
        got[it - sent.begin()] = true;
        if (replies++ == 0) first = read_message(types_, reply.get(), rep_type);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    std::printf("%s\n", json{{"service", rq_spec.service}, {"form", "rmw_fastrtps"}, {"available", available},
                             {"sent", sent.size()}, {"replies", replies}, {"foreign", foreign}, {"response", first},
                             {"ms", 1e3 * since(t1)}}.dump().c_str());
    publisher->delete_datawriter(w);
    subscriber->delete_datareader(r);
  }
  for (const std::string& service : calls) {
    fdds::DataWriterQos wq = fdds::DATAWRITER_QOS_DEFAULT;  // rmw_qos_profile_services_default
    wq.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
    wq.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
    wq.history().depth = 10;
    fdds::DataReaderQos rq = fdds::DATAREADER_QOS_DEFAULT;
    rq.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
    rq.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
    rq.history().depth = 10;
    fdds::DataWriter* w = publisher->create_datawriter(topic_for("rq" + service + "Request", "std_srvs/srv/Empty_Request"), wq);
    fdds::DataReader* r = subscriber->create_datareader(topic_for("rr" + service + "Reply", "std_srvs/srv/Empty_Response"), rq);
    auto t0 = std::chrono::steady_clock::now();
    bool available = false;
    while (!available && since(t0) < 5.0) {
      fdds::PublicationMatchedStatus pm;
      fdds::SubscriptionMatchedStatus sm;
      w->get_publication_matched_status(pm);
      r->get_subscription_matched_status(sm);
      available = pm.current_count > 0 && sm.current_count > 0;
      if (!available) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    types::DynamicData_ptr request(types::DynamicDataFactory::get_instance()->create_data(types_.get("std_srvs/srv/Empty_Request")));
    types::DynamicData_ptr reply(types::DynamicDataFactory::get_instance()->create_data(types_.get("std_srvs/srv/Empty_Response")));
    eprosima::fastrtps::rtps::WriteParams params;
    params.related_sample_identity().writer_guid(r->guid());
    const auto t1 = std::chrono::steady_clock::now();
    bool replied = false;
    if (available && w->write(request.get(), params)) {
      const eprosima::fastrtps::rtps::SampleIdentity id = params.sample_identity();
      while (!replied && since(t1) < 3.0) {
        fdds::SampleInfo info;
        while (r->take_next_sample(reply.get(), &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
          if (info.valid_data && info.related_sample_identity == id) replied = true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }
    std::printf("%s\n", json{{"service", service}, {"form", "rmw_fastrtps"}, {"available", available}, {"reply", replied},
                             {"ms", 1e3 * since(t1)}}.dump().c_str());
  }
  for (Sub& s : subs) {
    const Kind& k = kKinds.at(s.kind);
    fdds::DataReaderQos q = fdds::DATAREADER_QOS_DEFAULT;
    char rel = k.reliability;
    bool tl = k.transient_local;
    if (s.qos == "be") rel = 'b';
    if (s.qos == "rel") rel = 'r';
    if (s.qos == "tl") rel = 'r', tl = true;
    q.reliability().kind = rel == 'r' ? fdds::RELIABLE_RELIABILITY_QOS : fdds::BEST_EFFORT_RELIABILITY_QOS;
    q.durability().kind = tl ? fdds::TRANSIENT_LOCAL_DURABILITY_QOS : fdds::VOLATILE_DURABILITY_QOS;
    q.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
    q.history().depth = k.depth;
    q.endpoint().history_memory_policy = eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
    s.reader = subscriber->create_datareader(topic_for(s.topic, k.type), q);
    s.data = types::DynamicDataFactory::get_instance()->create_data(types_.get(k.type));
  }
  for (Pub& p : pubs) {
    const Kind& k = kKinds.at(p.kind);
    fdds::DataWriterQos q = fdds::DATAWRITER_QOS_DEFAULT;  // rclcpp's default: reliable, volatile, keep last 10
    q.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
    q.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
    q.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
    q.history().depth = 10;
    q.endpoint().history_memory_policy = eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
    p.writer = publisher->create_datawriter(topic_for(p.topic, k.type), q);
    p.data = types::DynamicDataFactory::get_instance()->create_data(types_.get(k.type));
    write_message(types_, p.data.get(), k.type, command(p.kind, p.values));
  }
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto next_pub = start;
  auto wall = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  while (wall() < seconds) {
    if (clock::now() >= next_pub) {
      for (Pub& p : pubs) {
        fdds::PublicationMatchedStatus st;
        p.writer->get_publication_matched_status(st);
        if (st.current_count > 0 && p.writer->write(p.data.get())) ++p.sent;
      }
      next_pub = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(1.0 / rate));
    }
    for (Sub& s : subs) {
      fdds::SampleInfo info;
      while (s.reader->take_next_sample(s.data.get(), &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data) continue;
        const double t = wall();
        if (s.count == 0) s.first = t;
        s.last = t;
        ++s.count;
        const json message = read_message(types_, s.data.get(), kKinds.at(s.kind).type);
        if (s.kind == "tf" || s.kind == "tf_static") {
          for (const json& t : message["transforms"]) {
            const std::string child = t["child_frame_id"];
            if (std::find(s.children.begin(), s.children.end(), child) == s.children.end()) s.children.push_back(child);
          }
        }
        s.last_sample = describe(s.kind, message);
        if (s.count <= 3) std::printf("%s\n", json{{"topic", s.topic}, {"n", s.count}, {"sample", s.last_sample}}.dump().c_str());
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  for (const Sub& s : subs) {
    std::printf("%s\n", json{{"topic", s.topic}, {"summary", true}, {"count", s.count}, {"span", s.count > 1 ? s.last - s.first : 0.0}, {"children", s.children},
                             {"last", s.count ? s.last_sample : json(nullptr)}}.dump().c_str());
  }
  for (const Pub& p : pubs) std::printf("%s\n", json{{"topic", p.topic}, {"published", p.sent}}.dump().c_str());
  runner.reset();
  backend.reset();
  pp->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(pp);
  return 0;
}
