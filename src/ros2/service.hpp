#pragma once
// A ROS 2 service server that answers the clients of both default middlewares (the service side
// of issue 37's controller-manager, gazebo and parameter services builds on it):
//
//   rmw_fastrtps_cpp (Humble's and Jazzy's default)
//     request: the .srv request fields; the sample's related_sample_identity carries the client's
//              reply reader GUID
//     reply:   the response fields, written with related_sample_identity = the request's own
//              identity (its writer's GUID and sequence number): the client matches replies by it
//   rmw_cyclonedds_cpp
//     request: uint64 client_id, int64 seq (cdds_request_header_t), then the request fields, in one
//              CDR body; the client's endpoints carry USER_DATA "clientid=<id>;"
//     reply:   the same 16-byte header echoed, then the response fields
//   Both expect the reply only once the server's reply writer has matched the client's reply
//   reader (otherwise a reliable writer does not keep the sample for it): the server waits for
//   that, at most 100 ms per request, as rmw_cyclonedds' server does.
// The request reader and the reply writer carry USER_DATA "serviceid=<id>;": rmw_cyclonedds clients
// take a service as available when both ends they matched share it. Which form a request has:
// a related_sample_identity (rmw_fastrtps), else a writer whose USER_DATA holds "clientid="
// (rmw_cyclonedds), else a writer of Cyclone's vendor id (0x0110), else rmw_fastrtps' form.
//
// A request that does not deserialize is dropped with a log line naming the service and the
// client; the handler's exception is logged, no reply. Handlers run on Fast DDS's receive thread
// of the request reader: they must be quick (a slow one delays every sample that thread
// delivers). A slow one (a spawn, a controller switch, an action's result) takes the deferred
// form: the handler gets a ReplyTo and the request, and replies later from any thread with
// reply(); a reply whose client is gone (its reply reader no longer matched: the client process
// ended mid-call) is dropped and counted, so nothing is left behind for it.

#include <atomic>
#include <chrono>
#include <cstring>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "ros2/node.hpp"

namespace mechsim::ros2 {

// How a client framed its request (see the header).
enum class ClientForm : std::uint8_t { FastRtps, CycloneDds };

// Which form a request has: `related` its related_sample_identity, `user_data` its writer's.
ClientForm client_form(const SampleInfo& info, const std::string& user_data);
// "clientid=<id>;" of a USER_DATA string ("" when none).
std::string user_data_value(const std::string& user_data, const std::string& key);

// Where a request's reply goes: its client's form and identity (service.hpp's header).
struct ReplyTo {
  ClientForm form = ClientForm::FastRtps;
  SampleIdentity request;      // the request sample's identity (rmw_fastrtps' reply carries it)
  Guid reply_reader{};         // rmw_fastrtps: the client's reply reader (zero: unknown)
  std::string client;          // rmw_cyclonedds: the client's "clientid" value
  std::uint64_t client_id = 0;  // rmw_cyclonedds' header, echoed
  std::int64_t seq = 0;
  // The client as log lines name it.
  std::string who() const { return guid_string(request.writer); }
};

template <class Srv>
class ServiceServer {
 public:
  using Request = typename Srv::Request;
  using Response = typename Srv::Response;
  // Fills the response; false: no reply (logged by the caller).
  using Handler = std::function<bool(const Request&, Response&)>;
  // The deferred form: reply(to, response) later, from any thread (or never: no reply).
  using DeferredHandler = std::function<void(const Request&, const ReplyTo&)>;

  // Throws NameError for a bad name, std::runtime_error when the endpoints cannot be made.
  ServiceServer(Node& node, const std::string& name, Handler handler)
      : ServiceServer(node, name, DeferredHandler{}) {
    handler_ = std::move(handler);
  }
  ServiceServer(Node& node, const std::string& name, DeferredHandler deferred)
      : participant_(node.participant()), deferred_(std::move(deferred)), name_(node.resolve(name)) {
    const std::string id = "serviceid=" + guid_string(participant_.guid()) + "/" + name_ + ";";
    EndpointSpec reply;
    reply.ros_topic = name_ + " (reply)";
    reply.dds_topic = dds_reply_topic(name_);
    reply.type_name = MessageTraits<Response>::dds_name;
    reply.type_hash = MessageTraits<Response>::type_hash;
    reply.qos = Qos::defaults();  // rmw_qos_profile_services_default: reliable, volatile, keep last 10
    reply.user_data = id;
    writer_ = participant_.create_writer(node_id(node), reply);
    EndpointSpec request = reply;
    request.ros_topic = name_ + " (request)";
    request.dds_topic = dds_request_topic(name_);
    request.type_name = MessageTraits<Request>::dds_name;
    request.type_hash = MessageTraits<Request>::type_hash;
    reader_ = participant_.create_reader(node_id(node), request,
                                         [this](const std::uint8_t* data, std::size_t size, const SampleInfo& info) {
                                           on_request(data, size, info);
                                         });
  }
  ~ServiceServer() {
    reader_.reset();  // no request is being handled once it is gone
    writer_.reset();
  }
  ServiceServer(const ServiceServer&) = delete;
  ServiceServer& operator=(const ServiceServer&) = delete;

  const std::string& name() const { return name_; }
  std::uint64_t served(ClientForm form) const { return served_[static_cast<int>(form)].load(); }
  // Replies whose client was gone (see the header).
  std::uint64_t dropped() const { return dropped_.load(); }

  // Whether the client of `to` is still there: its reply reader matched (rmw_fastrtps: the
  // reader in the request's related_sample_identity; rmw_cyclonedds: a reader carrying its
  // clientid). A client that named no reader counts as there.
  bool client_alive(const ReplyTo& to) const {
    if (to.form == ClientForm::FastRtps) return to.reply_reader == Guid{} || writer_->has_matched(to.reply_reader);
    if (to.client.empty()) return true;
    for (const Guid& r : participant_.remote_readers_with("clientid=" + to.client + ";"))
      if (writer_->has_matched(r)) return true;
    return false;
  }

  // Sends `response` to the client of `to` (any thread). Waits at most 100 ms for the client's
  // reply reader to be matched (a reply to a reader not matched yet is lost); a client that is
  // gone gets nothing: false, counted in dropped().
  bool reply(const ReplyTo& to, const Response& response) {
    // A client not matched yet gets 100 ms (its reader may still be being discovered); one known
    // to be gone (matched before and not now, or already waited for in vain) gets no wait, so a
    // vanished client's queued requests cost nothing.
    const std::string key = to.form == ClientForm::FastRtps ? guid_string(to.reply_reader) : "cyclone:" + to.client;
    bool matched = client_alive(to);
    if (!matched && !known(gone_, key) && !known(seen_, key)) {
      for (int i = 0; i < 10 && !matched; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        matched = client_alive(to);
      }
    }
    remember(matched ? seen_ : gone_, key);
    if (!matched) {
      const std::uint64_t n = dropped_.fetch_add(1) + 1;
      // At most one line a second: a vanished client may have left many requests queued.
      const auto now = std::chrono::steady_clock::now();
      std::lock_guard<std::mutex> lock(clients_mutex_);
      if (now - last_drop_log_ >= std::chrono::seconds(1)) {
        last_drop_log_ = now;
        participant_.log(name_ + ": the reply to " + to.who() + " was dropped: the client is gone (" + std::to_string(n) +
                         " dropped so far)");
      }
      return false;
    }
    if (to.form == ClientForm::FastRtps) {
      writer_->write(Publisher<Response>::out(response), to.request, nullptr);
    } else {
      struct Framed {
        std::uint64_t client_id;
        std::int64_t seq;
        const Response* response;
      } framed{to.client_id, to.seq, &response};
      OutMessage out{&framed, [](const void* m) { return serialized_size(*static_cast<const Framed*>(m)->response) + 16; },
                     [](const void* m, char* buffer, std::size_t capacity) -> std::size_t {
                       const auto* f = static_cast<const Framed*>(m);
                       if (capacity < 20) return 0;
                       const std::size_t n = serialize_into(*f->response, buffer + 16, capacity - 16);
                       std::memmove(buffer, buffer + 16, 4);  // the encapsulation header first
                       std::memcpy(buffer + 4, &f->client_id, 8);
                       std::memcpy(buffer + 12, &f->seq, 8);
                       return n + 16;
                     }};
      writer_->write(out);
    }
    served_[static_cast<int>(to.form)].fetch_add(1);
    return true;
  }

 private:
  static int node_id(Node& node) { return node.id(); }

  void on_request(const std::uint8_t* data, std::size_t size, const SampleInfo& info) {
    const std::string user_data = participant_.remote_user_data(info.identity.writer);
    const ClientForm form = client_form(info, user_data);
    std::vector<std::uint8_t> body;
    std::uint64_t client_id = 0;
    std::int64_t seq = 0;
    const std::uint8_t* fields = data;
    std::size_t fields_size = size;
    if (form == ClientForm::CycloneDds) {
      // The header is 16 bytes at the body's start (8-aligned): what follows keeps its alignment
      // once the header is cut out.
      if (size < 4 + 16) {
        participant_.log(name_ + ": a request of " + std::to_string(size) + " bytes from " +
                         guid_string(info.identity.writer) + " has no rmw_cyclonedds header; dropped");
        return;
      }
      std::memcpy(&client_id, data + 4, 8);
      std::memcpy(&seq, data + 12, 8);
      body.assign(data, data + 4);
      body.insert(body.end(), data + 20, data + size);
      fields = body.data();
      fields_size = body.size();
    }
    Request request;
    std::string error;
    if (!deserialize(fields, fields_size, request, &error)) {
      participant_.log(name_ + ": malformed request from " + guid_string(info.identity.writer) + " dropped (" + error + ")");
      return;
    }
    ReplyTo to;
    to.form = form;
    to.request = info.identity;
    to.reply_reader = info.related.writer;
    to.client_id = client_id;
    to.seq = seq;
    if (form == ClientForm::CycloneDds) to.client = user_data_value(user_data, "clientid");
    try {
      if (deferred_) {
        deferred_(request, to);
        return;
      }
      Response response;
      if (!handler_(request, response)) return;
      reply(to, response);
    } catch (const std::exception& e) {
      participant_.log(name_ + ": the request's handler failed: " + e.what());
    }
  }

  Participant& participant_;
  Handler handler_;
  DeferredHandler deferred_;
  std::string name_;
  std::unique_ptr<Writer> writer_;
  std::unique_ptr<Reader> reader_;
  bool known(const std::set<std::string>& set, const std::string& key) const {
    std::lock_guard<std::mutex> lock(clients_mutex_);
    return set.count(key) > 0;
  }
  void remember(std::set<std::string>& set, const std::string& key) {
    std::lock_guard<std::mutex> lock(clients_mutex_);
    if (set.size() >= 4096) set.clear();  // bounded: forgetting costs at most one wait
    set.insert(key);
  }

  mutable std::mutex clients_mutex_;
  std::set<std::string> seen_, gone_;  // clients' readers matched at a reply, and not matched
  std::chrono::steady_clock::time_point last_drop_log_{};
  std::atomic<std::uint64_t> served_[2] = {0, 0};
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace mechsim::ros2
