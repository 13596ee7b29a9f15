#include "live/foxglove_protocol.hpp"

#include <nlohmann/json.hpp>

namespace mechsim::live {

namespace {

void put_le(std::string& out, std::uint64_t value, int bytes) {
  for (int k = 0; k < bytes; ++k) out.push_back(static_cast<char>((value >> (8 * k)) & 0xffu));
}

std::uint64_t get_le(std::string_view in, std::size_t at, int bytes) {
  std::uint64_t value = 0;
  for (int k = 0; k < bytes; ++k) value |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + static_cast<std::size_t>(k)])) << (8 * k);
  return value;
}

}  // namespace

std::string server_info_message(const std::string& name, const std::string& session_id) {
  nlohmann::json j = {{"op", "serverInfo"},
                      {"name", name},
                      {"capabilities", nlohmann::json::array({"time"})},
                      {"metadata", nlohmann::json::object()},
                      {"sessionId", session_id}};
  return j.dump();
}

std::string advertise_message(const std::vector<Channel>& channels) {
  nlohmann::json list = nlohmann::json::array();
  for (const Channel& c : channels) {
    list.push_back({{"id", c.id},
                    {"topic", c.topic},
                    {"encoding", c.encoding},
                    {"schemaName", c.schema_name},
                    {"schema", c.schema},
                    {"schemaEncoding", c.schema_encoding}});
  }
  return nlohmann::json{{"op", "advertise"}, {"channels", list}}.dump();
}

std::string status_message(int level, const std::string& text) {
  return nlohmann::json{{"op", "status"}, {"level", level}, {"message", text}}.dump();
}

std::string message_data_header(std::uint32_t subscription_id, std::uint64_t timestamp_ns) {
  std::string out;
  out.reserve(13);
  out.push_back('\x01');
  put_le(out, subscription_id, 4);
  put_le(out, timestamp_ns, 8);
  return out;
}

std::string time_message(std::uint64_t timestamp_ns) {
  std::string out;
  out.push_back('\x02');
  put_le(out, timestamp_ns, 8);
  return out;
}

ClientRequest parse_client_request(std::string_view text) {
  ClientRequest r;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) {
    r.error = "not a JSON object";
    return r;
  }
  const auto op = j.find("op");
  if (op == j.end() || !op->is_string()) {
    r.error = "no string field 'op'";
    return r;
  }
  const std::string name = op->get<std::string>();
  auto number = [](const nlohmann::json& v) { return v.is_number_unsigned() && v.get<std::uint64_t>() <= 0xffffffffu; };
  if (name == "subscribe") {
    const auto subs = j.find("subscriptions");
    if (subs == j.end() || !subs->is_array()) {
      r.error = "subscribe: no array 'subscriptions'";
      return r;
    }
    for (const nlohmann::json& s : *subs) {
      if (!s.is_object() || !s.contains("id") || !s.contains("channelId") || !number(s["id"]) || !number(s["channelId"])) {
        r.error = "subscribe: each subscription needs unsigned 32-bit 'id' and 'channelId'";
        r.subscribe.clear();
        return r;
      }
      r.subscribe.push_back({s["id"].get<std::uint32_t>(), s["channelId"].get<std::uint32_t>()});
    }
    r.op = ClientRequest::Op::Subscribe;
    return r;
  }
  if (name == "unsubscribe") {
    const auto ids = j.find("subscriptionIds");
    if (ids == j.end() || !ids->is_array()) {
      r.error = "unsubscribe: no array 'subscriptionIds'";
      return r;
    }
    for (const nlohmann::json& id : *ids) {
      if (!number(id)) {
        r.error = "unsubscribe: 'subscriptionIds' holds unsigned 32-bit numbers";
        r.unsubscribe.clear();
        return r;
      }
      r.unsubscribe.push_back(id.get<std::uint32_t>());
    }
    r.op = ClientRequest::Op::Unsubscribe;
    return r;
  }
  // Operations of capabilities this server does not declare (parameters, services, publishing).
  r.op = ClientRequest::Op::Ignored;
  r.error = "operation '" + name + "' is not supported by this server";
  return r;
}

std::optional<MessageData> parse_message_data(std::string_view frame) {
  if (frame.size() < 13 || frame[0] != '\x01') return std::nullopt;
  MessageData m;
  m.subscription_id = static_cast<std::uint32_t>(get_le(frame, 1, 4));
  m.timestamp_ns = get_le(frame, 5, 8);
  m.payload = frame.substr(13);
  return m;
}

}  // namespace mechsim::live
