#pragma once
// Fast DDS's side of mechsim's participant (dds_participant.cpp): GUID and sample identity
// conversions, QoS policy names, and the one topic type mechsim registers per DDS type name.
// Internal to the ROS 2 layer.

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <fastdds/dds/core/policy/QosPolicies.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/rtps/common/Guid.h>
#include <fastdds/rtps/common/SampleIdentity.h>

#include "ros2/dds_participant.hpp"

namespace mechsim::ros2::fastdds_types {

namespace dds = eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

inline Guid to_guid(const rtps::GUID_t& g) {
  Guid out{};
  std::memcpy(out.data(), g.guidPrefix.value, 12);
  std::memcpy(out.data() + 12, g.entityId.value, 4);
  return out;
}

inline rtps::GUID_t from_guid(const Guid& g) {
  rtps::GUID_t out;
  std::memcpy(out.guidPrefix.value, g.data(), 12);
  std::memcpy(out.entityId.value, g.data() + 12, 4);
  return out;
}

inline SampleIdentity to_identity(const rtps::SampleIdentity& id) {
  SampleIdentity out;
  out.writer = to_guid(id.writer_guid());
  out.sequence = static_cast<std::int64_t>(id.sequence_number().to64long());
  return out;
}

inline const char* policy_name(dds::QosPolicyId_t id) {
  switch (id) {
    case dds::RELIABILITY_QOS_POLICY_ID: return "reliability";
    case dds::DURABILITY_QOS_POLICY_ID: return "durability";
    case dds::DEADLINE_QOS_POLICY_ID: return "deadline";
    case dds::LIVELINESS_QOS_POLICY_ID: return "liveliness";
    case dds::OWNERSHIP_QOS_POLICY_ID: return "ownership";
    case dds::DESTINATIONORDER_QOS_POLICY_ID: return "destination order";
    case dds::LATENCYBUDGET_QOS_POLICY_ID: return "latency budget";
    case dds::PRESENTATION_QOS_POLICY_ID: return "presentation";
    case dds::DATAREPRESENTATION_QOS_POLICY_ID: return "data representation";
    default: return "another policy";
  }
}

// What a serialized sample of mechsim looks like to Fast DDS: one type per DDS type name. A sample
// written is an OutMessage (type-erased generated code); a sample read is its bytes (InSample),
// deserialized by the subscription itself so that a malformed one is reported with its topic.
struct InSample {
  std::vector<std::uint8_t> bytes;
};

class CdrType final : public dds::TopicDataType {
 public:
  explicit CdrType(const std::string& name) {
    setName(name.c_str());
    m_typeSize = 512;  // an initial payload size; payloads grow as samples need (realloc pools)
    m_isGetKeyDefined = false;
    // No XTypes type information, as rmw_fastrtps and rmw_cyclonedds announce none: matching
    // goes by the type name.
    auto_fill_type_object(false);
    auto_fill_type_information(false);
  }
  bool serialize(void* data, rtps::SerializedPayload_t* payload) override {
    const auto* m = static_cast<const OutMessage*>(data);
    try {
      payload->length = static_cast<std::uint32_t>(m->write(m->message, reinterpret_cast<char*>(payload->data), payload->max_size));
    } catch (const std::exception&) {
      return false;
    }
    payload->encapsulation = CDR_LE;
    return true;
  }
  bool deserialize(rtps::SerializedPayload_t* payload, void* data) override {
    auto* s = static_cast<InSample*>(data);
    s->bytes.assign(payload->data, payload->data + payload->length);
    return true;
  }
  std::function<std::uint32_t()> getSerializedSizeProvider(void* data) override {
    const auto* m = static_cast<const OutMessage*>(data);
    return [m] { return static_cast<std::uint32_t>(m->size(m->message)); };
  }
  void* createData() override { return new InSample(); }
  void deleteData(void* data) override { delete static_cast<InSample*>(data); }
  bool getKey(void*, rtps::InstanceHandle_t*, bool) override { return false; }
};

}  // namespace mechsim::ros2::fastdds_types
