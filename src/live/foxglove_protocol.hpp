#pragma once
// The Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1) as mechsim speaks it:
// the server's JSON operations (serverInfo, advertise, status), the client's (subscribe,
// unsubscribe), and the binary frames (opcode 1 message data, opcode 2 time). Integers in
// binary frames are little-endian; timestamps are nanoseconds of simulation time.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mechsim::live {

inline constexpr std::string_view kSubprotocol = "foxglove.websocket.v1";

// One advertised channel. Messages are JSON; schemas are JSON Schema documents.
struct Channel {
  std::uint32_t id = 0;
  std::string topic;
  std::string schema_name;  // e.g. foxglove.FrameTransforms, sensor_msgs/JointState
  std::string schema;       // JSON Schema text
  std::string encoding = "json";
  std::string schema_encoding = "jsonschema";
};

std::string server_info_message(const std::string& name, const std::string& session_id);
std::string advertise_message(const std::vector<Channel>& channels);
// level: 0 info, 1 warning, 2 error.
std::string status_message(int level, const std::string& text);

// Opcode 1: subscription id, receive timestamp (ns), then the payload. The 13-byte header alone
// (the payload is sent after it from a buffer shared by every subscriber).
std::string message_data_header(std::uint32_t subscription_id, std::uint64_t timestamp_ns);
// Opcode 2: the server's current time (ns).
std::string time_message(std::uint64_t timestamp_ns);

// A client's request, parsed. Unknown operations and malformed text give `error`.
struct ClientRequest {
  enum class Op { Subscribe, Unsubscribe, Ignored, Invalid } op = Op::Invalid;
  struct Subscription {
    std::uint32_t id = 0, channel = 0;
  };
  std::vector<Subscription> subscribe;    // Op::Subscribe
  std::vector<std::uint32_t> unsubscribe;  // Op::Unsubscribe
  std::string error;                       // Op::Invalid: what is wrong
};
ClientRequest parse_client_request(std::string_view text);

// The parts of a message data frame (for clients and tests); nullopt when `frame` is not one.
struct MessageData {
  std::uint32_t subscription_id = 0;
  std::uint64_t timestamp_ns = 0;
  std::string_view payload;
};
std::optional<MessageData> parse_message_data(std::string_view frame);

}  // namespace mechsim::live
