// A ROS 2 client on Eclipse Cyclone DDS (Debian's cyclonedds-dev) in rmw_cyclonedds_cpp's forms,
// for any service, action or topic of ../common/ros2_definitions.hpp: the scripted client of
// ../common/script.hpp over Cyclone.
//
//   cyclone_client --domain D --script JSON [--seconds S]
//
// As rmw_cyclonedds_cpp does, the middleware carries bytes the client serializes itself: a
// sertype of its own (rmw_cyclonedds' serdata.cpp does the same with rosidl's type support) whose
// samples are CDR bytes, written by ../common/cdr_json.hpp from the official field lists.
// Services in rmw_cyclonedds' form (its serdata.hpp, rmw_node.cpp): each request and reply body
// starts with cdds_request_header_t {uint64 client_id; int64 seq} in the same CDR stream; the
// client id is the request writer's instance handle, the client's reader and writer carry
// USER_DATA "clientid=<id>;", and the client keeps the replies carrying its own id.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include <dds/dds.h>
#include <dds/ddsi/ddsi_serdata.h>
#include <dds/ddsi/ddsi_sertype.h>
#include <dds/ddsi/q_radmin.h>

#include "../common/cdr_json.hpp"
#include "../common/ros2_definitions.hpp"
#include "../common/script.hpp"

namespace peers = mechsim::ros2::peers;
using peers::json;

namespace {

// ---- a sertype whose samples are serialized bytes (encapsulation header included)
struct RawSample {
  std::vector<std::uint8_t> bytes;
};

struct RawSerdata : ddsi_serdata {
  std::vector<std::uint8_t> bytes;  // padded to a multiple of 4 (to_ser may read up to that)
  std::uint32_t size = 0;           // the serialized size
};

RawSerdata* new_serdata(const ddsi_sertype* type, ddsi_serdata_kind kind, std::size_t size) {
  auto* d = new RawSerdata();
  ddsi_serdata_init(d, type, kind);
  d->hash = type->serdata_basehash;
  d->size = static_cast<std::uint32_t>(size);
  d->bytes.assign((size + 3) & ~std::size_t{3}, 0);
  return d;
}

bool sd_eqkey(const ddsi_serdata*, const ddsi_serdata*) { return true; }  // keyless
uint32_t sd_get_size(const ddsi_serdata* d) { return static_cast<const RawSerdata*>(d)->size; }
ddsi_serdata* sd_from_ser(const ddsi_sertype* type, ddsi_serdata_kind kind, const nn_rdata* fragchain, size_t size) {
  RawSerdata* d = new_serdata(type, kind, size);
  std::uint32_t off = 0;
  // Fragments in order, possibly overlapping (as rmw_cyclonedds' serdata_rmw_from_ser reads them).
  for (const nn_rdata* f = fragchain; f != nullptr; f = f->nextfrag) {
    if (f->maxp1 <= off) continue;
    const unsigned char* payload = NN_RMSG_PAYLOADOFF(f->rmsg, NN_RDATA_PAYLOAD_OFF(f));
    const std::uint32_t end = std::min<std::uint32_t>(f->maxp1, static_cast<std::uint32_t>(size));
    if (end > off) std::memcpy(d->bytes.data() + off, payload + (off - f->min), end - off);
    off = f->maxp1;
  }
  return d;
}
ddsi_serdata* sd_from_ser_iov(const ddsi_sertype* type, ddsi_serdata_kind kind, ddsrt_msg_iovlen_t niov,
                              const ddsrt_iovec_t* iov, size_t size) {
  RawSerdata* d = new_serdata(type, kind, size);
  std::size_t off = 0;
  for (ddsrt_msg_iovlen_t i = 0; i < niov && off < size; ++i) {
    const std::size_t n = std::min<std::size_t>(iov[i].iov_len, size - off);
    std::memcpy(d->bytes.data() + off, iov[i].iov_base, n);
    off += n;
  }
  return d;
}
ddsi_serdata* sd_from_keyhash(const ddsi_sertype* type, const ddsi_keyhash*) { return new_serdata(type, SDK_KEY, 0); }
ddsi_serdata* sd_from_sample(const ddsi_sertype* type, ddsi_serdata_kind kind, const void* sample) {
  const auto* s = static_cast<const RawSample*>(sample);
  if (kind != SDK_DATA) return new_serdata(type, kind, 0);
  RawSerdata* d = new_serdata(type, kind, s->bytes.size());
  std::memcpy(d->bytes.data(), s->bytes.data(), s->bytes.size());
  return d;
}
void sd_to_ser(const ddsi_serdata* d, size_t off, size_t sz, void* buf) {
  std::memcpy(buf, static_cast<const RawSerdata*>(d)->bytes.data() + off, sz);
}
ddsi_serdata* sd_to_ser_ref(const ddsi_serdata* d, size_t off, size_t sz, ddsrt_iovec_t* ref) {
  ref->iov_base = const_cast<std::uint8_t*>(static_cast<const RawSerdata*>(d)->bytes.data() + off);
  ref->iov_len = static_cast<ddsrt_iov_len_t>(sz);
  return ddsi_serdata_ref(d);
}
void sd_to_ser_unref(ddsi_serdata* d, const ddsrt_iovec_t*) { ddsi_serdata_unref(d); }
bool sd_to_sample(const ddsi_serdata* d, void* sample, void**, void*) {
  const auto* r = static_cast<const RawSerdata*>(d);
  static_cast<RawSample*>(sample)->bytes.assign(r->bytes.begin(), r->bytes.begin() + r->size);
  return true;
}
ddsi_serdata* sd_to_untyped(const ddsi_serdata* d) { return ddsi_serdata_ref(d); }  // keyless: nothing to strip
bool sd_untyped_to_sample(const ddsi_sertype*, const ddsi_serdata*, void* sample, void**, void*) {
  static_cast<RawSample*>(sample)->bytes.clear();
  return true;
}
void sd_free(ddsi_serdata* d) { delete static_cast<RawSerdata*>(d); }
size_t sd_print(const ddsi_sertype*, const ddsi_serdata* d, char* buf, size_t size) {
  return static_cast<size_t>(std::snprintf(buf, size, "(%u bytes)", static_cast<const RawSerdata*>(d)->size));
}
void sd_get_keyhash(const ddsi_serdata*, ddsi_keyhash* buf, bool) { std::memset(buf, 0, sizeof *buf); }

const ddsi_serdata_ops kSerdataOps = {sd_eqkey,    sd_get_size,     sd_from_ser,   sd_from_ser_iov, sd_from_keyhash,
                                      sd_from_sample, sd_to_ser,    sd_to_ser_ref, sd_to_ser_unref, sd_to_sample,
                                      sd_to_untyped, sd_untyped_to_sample, sd_free, sd_print,      sd_get_keyhash
#ifdef DDS_HAS_SHM
                                      , nullptr, nullptr
#endif
};

void st_free(ddsi_sertype* tp) {
  ddsi_sertype_fini(tp);
  delete tp;
}
void st_zero_samples(const ddsi_sertype*, void* samples, size_t count) {
  for (size_t i = 0; i < count; ++i) static_cast<RawSample*>(samples)[i].bytes.clear();
}
void st_realloc_samples(void** ptrs, const ddsi_sertype*, void* old, size_t oldcount, size_t count) {
  auto* fresh = new RawSample[count];
  for (size_t i = 0; i < std::min(oldcount, count); ++i) fresh[i] = static_cast<RawSample*>(old)[i];
  delete[] static_cast<RawSample*>(old);
  for (size_t i = 0; i < count; ++i) ptrs[i] = &fresh[i];
}
void st_free_samples(const ddsi_sertype*, void** ptrs, size_t count, dds_free_op_t op) {
  if (count == 0) return;
  if (op & DDS_FREE_ALL_BIT) {
    delete[] static_cast<RawSample*>(ptrs[0]);
  } else {
    for (size_t i = 0; i < count; ++i) static_cast<RawSample*>(ptrs[i])->bytes.clear();
  }
}
bool st_equal(const ddsi_sertype*, const ddsi_sertype*) { return true; }  // same name, same ops: same type
uint32_t st_hash(const ddsi_sertype*) { return 0; }
size_t st_serialized_size(const ddsi_sertype*, const void* sample) { return static_cast<const RawSample*>(sample)->bytes.size(); }
bool st_serialize_into(const ddsi_sertype*, const void* sample, void* dst, size_t size) {
  const auto* s = static_cast<const RawSample*>(sample);
  if (size < s->bytes.size()) return false;
  std::memcpy(dst, s->bytes.data(), s->bytes.size());
  return true;
}

const ddsi_sertype_ops kSertypeOps = {ddsi_sertype_v0, nullptr, st_free, st_zero_samples, st_realloc_samples,
                                      st_free_samples, st_equal, st_hash, nullptr, nullptr, nullptr, nullptr,
                                      st_serialized_size, st_serialize_into};

// A topic of `dds_type` (rmw's type name) carrying raw samples.
dds_entity_t raw_topic(dds_entity_t pp, const std::string& name, const std::string& dds_type) {
  auto* st = new ddsi_sertype();
  ddsi_sertype_init(st, dds_type.c_str(), &kSertypeOps, &kSerdataOps, true);
  ddsi_sertype* as = st;
  const dds_entity_t t = dds_create_topic_sertype(pp, name.c_str(), &as, nullptr, nullptr, nullptr);
  if (t < 0) throw std::runtime_error("topic " + name + ": " + dds_strretcode(-t));
  return t;
}

dds_qos_t* qos_of(peers::PeerQos q, const std::string& user_data = "") {
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, q.reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT, DDS_MSECS(100));
  dds_qset_durability(qos, q.transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, q.depth);
  if (!user_data.empty()) dds_qset_userdata(qos, user_data.data(), user_data.size());
  return qos;
}

std::vector<RawSample> take_all(dds_entity_t reader) {
  constexpr int kBatch = 16;
  std::vector<RawSample> out;
  for (;;) {
    RawSample samples[kBatch];
    void* ptrs[kBatch];
    for (int i = 0; i < kBatch; ++i) ptrs[i] = &samples[i];
    dds_sample_info_t infos[kBatch];
    const dds_return_t n = dds_take(reader, ptrs, infos, kBatch, kBatch);
    if (n <= 0) break;
    for (int i = 0; i < n; ++i)
      if (infos[i].valid_data) out.push_back(std::move(samples[i]));
    if (n < kBatch) break;
  }
  return out;
}

class CycloneBackend : public peers::Backend {
 public:
  CycloneBackend(dds_entity_t pp, peers::CdrCodec& codec) : pp_(pp), codec_(codec) {}
  std::string form() const override { return "rmw_cyclonedds"; }

  class Client : public peers::ServiceClient {
   public:
    Client(CycloneBackend& b, const std::string& service, const std::string& type)
        : b_(b), req_(type + "_Request"), rep_(type + "_Response") {
      const std::string user = "clientid=cyclone_client." + std::to_string(getpid()) + "." + std::to_string(++b.clients_) + ";";
      dds_qos_t* q = qos_of({true, false, 1000}, user);
      w_ = dds_create_writer(b.pp_, raw_topic(b.pp_, "rq" + service + "Request", peers::dds_type_name(req_)), q, nullptr);
      r_ = dds_create_reader(b.pp_, raw_topic(b.pp_, "rr" + service + "Reply", peers::dds_type_name(rep_)), q, nullptr);
      dds_delete_qos(q);
      if (w_ < 0 || r_ < 0) throw std::runtime_error("service " + service + ": no writer or reader");
      dds_instance_handle_t ih = 0;
      dds_get_instance_handle(w_, &ih);
      client_id_ = ih;
    }
    ~Client() override {
      dds_delete(w_);
      dds_delete(r_);
    }
    bool available() override {
      dds_publication_matched_status_t pm;
      dds_subscription_matched_status_t sm;
      dds_get_publication_matched_status(w_, &pm);
      dds_get_subscription_matched_status(r_, &sm);
      return pm.current_count > 0 && sm.current_count > 0;
    }
    std::optional<std::int64_t> send(const json& request) override {
      peers::CdrOut out;
      const std::int64_t seq = ++seq_;
      out.put<std::uint64_t>(client_id_);
      out.put<std::int64_t>(seq);
      b_.codec_.encode(req_, request, out);
      RawSample s{out.bytes()};
      if (dds_write(w_, &s) < 0) return std::nullopt;
      return seq;
    }
    std::vector<std::pair<std::int64_t, json>> take() override {
      std::vector<std::pair<std::int64_t, json>> out;
      for (const RawSample& s : take_all(r_)) {
        // Every reply on the topic reaches every client's reader: those to rmw_fastrtps clients
        // (no header: too short, or a header that is not ours) are someone else's.
        std::uint64_t id = 0;
        std::int64_t seq = 0;
        std::optional<peers::CdrIn> in;
        try {
          in.emplace(s.bytes.data(), s.bytes.size());
          id = in->get<std::uint64_t>();
          seq = in->get<std::int64_t>();
        } catch (const std::exception&) {
          ++foreign;
          continue;
        }
        if (id != client_id_) {
          ++foreign;
          continue;
        }
        out.emplace_back(seq, b_.codec_.decode(rep_, *in));
      }
      return out;
    }

   private:
    CycloneBackend& b_;
    std::string req_, rep_;
    dds_entity_t w_ = 0, r_ = 0;
    std::uint64_t client_id_ = 0;
    std::int64_t seq_ = 0;
  };

  class Reader : public peers::TopicReader {
   public:
    Reader(CycloneBackend& b, const std::string& topic, const std::string& type, peers::PeerQos q) : b_(b), type_(type) {
      dds_qos_t* qos = qos_of(q);
      r_ = dds_create_reader(b.pp_, raw_topic(b.pp_, "rt" + topic, peers::dds_type_name(type)), qos, nullptr);
      dds_delete_qos(qos);
      if (r_ < 0) throw std::runtime_error("no reader for " + topic);
    }
    ~Reader() override { dds_delete(r_); }
    std::vector<json> take() override {
      std::vector<json> out;
      for (const RawSample& s : take_all(r_)) {
        peers::CdrIn in(s.bytes.data(), s.bytes.size());
        out.push_back(b_.codec_.decode(type_, in));
      }
      return out;
    }

   private:
    CycloneBackend& b_;
    std::string type_;
    dds_entity_t r_ = 0;
  };

  class Writer : public peers::TopicWriter {
   public:
    Writer(CycloneBackend& b, const std::string& topic, const std::string& type, peers::PeerQos q) : b_(b), type_(type) {
      dds_qos_t* qos = qos_of(q);
      w_ = dds_create_writer(b.pp_, raw_topic(b.pp_, "rt" + topic, peers::dds_type_name(type)), qos, nullptr);
      dds_delete_qos(qos);
      if (w_ < 0) throw std::runtime_error("no writer for " + topic);
    }
    ~Writer() override { dds_delete(w_); }
    int matched() override {
      dds_publication_matched_status_t pm;
      dds_get_publication_matched_status(w_, &pm);
      return static_cast<int>(pm.current_count);
    }
    bool write(const json& message) override {
      peers::CdrOut out;
      b_.codec_.encode(type_, message, out);
      RawSample s{out.bytes()};
      return dds_write(w_, &s) >= 0;
    }

   private:
    CycloneBackend& b_;
    std::string type_;
    dds_entity_t w_ = 0;
  };

  std::unique_ptr<peers::ServiceClient> client(const std::string& service, const std::string& type) override {
    return std::make_unique<Client>(*this, service, type);
  }
  std::unique_ptr<peers::TopicReader> reader(const std::string& topic, const std::string& type, peers::PeerQos q) override {
    return std::make_unique<Reader>(*this, topic, type, q);
  }
  std::unique_ptr<peers::TopicWriter> writer(const std::string& topic, const std::string& type, peers::PeerQos q) override {
    return std::make_unique<Writer>(*this, topic, type, q);
  }

 private:
  dds_entity_t pp_;
  peers::CdrCodec& codec_;
  int clients_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  int domain = 0;
  double seconds = 0.0;
  std::string distro = "jazzy", script;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if (a == "--domain" && more) domain = std::atoi(argv[++i]);
    else if (a == "--distro" && more) distro = argv[++i];
    else if (a == "--seconds" && more) seconds = std::atof(argv[++i]);
    else if (a == "--script" && more) script = argv[++i];
    else {
      std::fprintf(stderr, "cyclone_client: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  json steps;
  try {
    steps = json::parse(script.empty() ? "[]" : script);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclone_client: --script: %s\n", e.what());
    return 2;
  }
  dds_qos_t* pq = dds_create_qos();
  const char* enclave = "enclave=/;";  // rmw's participant USER_DATA
  dds_qset_userdata(pq, enclave, std::strlen(enclave));
  const dds_entity_t pp = dds_create_participant(static_cast<dds_domainid_t>(domain), pq, nullptr);
  dds_delete_qos(pq);
  if (pp < 0) {
    std::fprintf(stderr, "cyclone_client: dds_create_participant: %s\n", dds_strretcode(-pp));
    return 1;
  }
  peers::CdrCodec codec(peers::definitions(distro));
  int rc = 0;
  {
    CycloneBackend backend(pp, codec);
    peers::Script runner(backend);
    rc = runner.run(steps);
    if (seconds > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  }
  dds_delete(pp);
  return rc;
}
