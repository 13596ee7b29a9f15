#pragma once
// The scripted client's middleware in the Fast DDS peer (../common/script.hpp): service clients,
// readers and writers in rmw_fastrtps_cpp's forms. Only fastdds_peer.cpp includes it.
#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/rtps/common/WriteParams.h>
#include <fastrtps/types/DynamicPubSubType.h>

#include "../common/script.hpp"
#include "fast_types.hpp"

namespace mechsim::ros2::peers::fast {

namespace fdds = eprosima::fastdds::dds;

// A type support whose preallocated payload size is capped: the max serialized size Fast DDS
// computes from kStringBound would be ~100 MB per sample for a string sequence; the payloads
// are PREALLOCATED_WITH_REALLOC (rmw_fastrtps' policy), so a larger sample still goes.
inline types::DynamicPubSubType* type_support(const types::DynamicType_ptr& type) {
  auto* support = new types::DynamicPubSubType(type);
  support->m_typeSize = std::min<std::uint32_t>(support->m_typeSize, 64 * 1024);
  return support;
}

inline fdds::DataWriterQos writer_qos(peers::PeerQos q) {
  fdds::DataWriterQos wq = fdds::DATAWRITER_QOS_DEFAULT;
  wq.reliability().kind = q.reliable ? fdds::RELIABLE_RELIABILITY_QOS : fdds::BEST_EFFORT_RELIABILITY_QOS;
  wq.durability().kind = q.transient_local ? fdds::TRANSIENT_LOCAL_DURABILITY_QOS : fdds::VOLATILE_DURABILITY_QOS;
  wq.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  wq.history().depth = q.depth;
  wq.endpoint().history_memory_policy = eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  return wq;
}
inline fdds::DataReaderQos reader_qos(peers::PeerQos q) {
  fdds::DataReaderQos rq = fdds::DATAREADER_QOS_DEFAULT;
  rq.reliability().kind = q.reliable ? fdds::RELIABLE_RELIABILITY_QOS : fdds::BEST_EFFORT_RELIABILITY_QOS;
  rq.durability().kind = q.transient_local ? fdds::TRANSIENT_LOCAL_DURABILITY_QOS : fdds::VOLATILE_DURABILITY_QOS;
  rq.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  rq.history().depth = q.depth;
  rq.endpoint().history_memory_policy = eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  return rq;
}

class FastBackend : public peers::Backend {
 public:
  FastBackend(fdds::DomainParticipant* pp, fdds::Publisher* pub, fdds::Subscriber* sub, Types& types)
      : pp_(pp), pub_(pub), sub_(sub), types_(types) {}
  std::string form() const override { return "rmw_fastrtps"; }

  fdds::Topic* topic(const std::string& dds_name, const std::string& type) {
    if (auto it = topics_.find(dds_name); it != topics_.end()) return it->second;
    fdds::TypeSupport support(type_support(types_.get(type)));
    support->auto_fill_type_object(false);
    support->auto_fill_type_information(false);
    support.register_type(pp_);
    return topics_[dds_name] = pp_->create_topic(dds_name, support.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  }

  // As rmw_fastrtps_cpp's client: the reply reader's GUID in each request's
  // related_sample_identity, replies matched by theirs (Fast DDS writes every reply to every
  // client's reader).
  class Client : public peers::ServiceClient {
   public:
    Client(FastBackend& b, const std::string& service, const std::string& type) : b_(b), req_(type + "_Request"), rep_(type + "_Response") {
      w_ = b.pub_->create_datawriter(b.topic("rq" + service + "Request", req_), writer_qos({true, false, 1000}));
      r_ = b.sub_->create_datareader(b.topic("rr" + service + "Reply", rep_), reader_qos({true, false, 1000}));
      reply_ = types::DynamicDataFactory::get_instance()->create_data(b.types_.get(rep_));
    }
    ~Client() override {
      b_.pub_->delete_datawriter(w_);
      b_.sub_->delete_datareader(r_);
    }
    bool available() override {
      fdds::PublicationMatchedStatus pm;
      fdds::SubscriptionMatchedStatus sm;
      w_->get_publication_matched_status(pm);
      r_->get_subscription_matched_status(sm);
      return pm.current_count > 0 && sm.current_count > 0;
    }
    std::optional<std::int64_t> send(const peers::json& request) override {
      types::DynamicData_ptr d(types::DynamicDataFactory::get_instance()->create_data(b_.types_.get(req_)));
      write_message(b_.types_, d.get(), req_, request);
      eprosima::fastrtps::rtps::WriteParams params;
      params.related_sample_identity().writer_guid(r_->guid());
      if (!w_->write(d.get(), params)) return std::nullopt;
      sent_ = params.sample_identity().writer_guid();
      return params.sample_identity().sequence_number().to64long();
    }
    std::vector<std::pair<std::int64_t, peers::json>> take() override {
      std::vector<std::pair<std::int64_t, peers::json>> out;
      fdds::SampleInfo info;
      while (r_->take_next_sample(reply_.get(), &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data) continue;
        if (info.related_sample_identity.writer_guid() != sent_) {
          ++foreign;
          continue;
        }
        out.emplace_back(info.related_sample_identity.sequence_number().to64long(), read_message(b_.types_, reply_.get(), rep_));
      }
      return out;
    }

   private:
    FastBackend& b_;
    std::string req_, rep_;
    fdds::DataWriter* w_ = nullptr;
    fdds::DataReader* r_ = nullptr;
    types::DynamicData_ptr reply_;
    eprosima::fastrtps::rtps::GUID_t sent_;
  };

  class Reader : public peers::TopicReader {
   public:
    Reader(FastBackend& b, const std::string& topic, const std::string& type, peers::PeerQos q) : b_(b), type_(type) {
      r_ = b.sub_->create_datareader(b.topic("rt" + topic, type), reader_qos(q));
      data_ = types::DynamicDataFactory::get_instance()->create_data(b.types_.get(type));
    }
    ~Reader() override { b_.sub_->delete_datareader(r_); }
    std::vector<peers::json> take() override {
      std::vector<peers::json> out;
      fdds::SampleInfo info;
      while (r_->take_next_sample(data_.get(), &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK)
        if (info.valid_data) out.push_back(read_message(b_.types_, data_.get(), type_));
      return out;
    }

   private:
    FastBackend& b_;
    std::string type_;
    fdds::DataReader* r_ = nullptr;
    types::DynamicData_ptr data_;
  };

  class Writer : public peers::TopicWriter {
   public:
    Writer(FastBackend& b, const std::string& topic, const std::string& type, peers::PeerQos q) : b_(b), type_(type) {
      w_ = b.pub_->create_datawriter(b.topic("rt" + topic, type), writer_qos(q));
    }
    ~Writer() override { b_.pub_->delete_datawriter(w_); }
    int matched() override {
      fdds::PublicationMatchedStatus pm;
      w_->get_publication_matched_status(pm);
      return pm.current_count;
    }
    bool write(const peers::json& message) override {
      types::DynamicData_ptr d(types::DynamicDataFactory::get_instance()->create_data(b_.types_.get(type_)));
      write_message(b_.types_, d.get(), type_, message);
      return w_->write(d.get());
    }

   private:
    FastBackend& b_;
    std::string type_;
    fdds::DataWriter* w_ = nullptr;
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
  fdds::DomainParticipant* pp_;
  fdds::Publisher* pub_;
  fdds::Subscriber* sub_;
  Types& types_;
  std::map<std::string, fdds::Topic*> topics_;
};

}  // namespace mechsim::ros2::peers::fast
