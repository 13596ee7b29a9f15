#include "live/foxglove_protocol.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace mechsim::live {
namespace {

TEST(FoxgloveProtocol, MessageDataHeaderIsOpcodeOneThenLittleEndianIdAndTime) {
  const std::string h = message_data_header(0x01020304u, 0x1122334455667788ull);
  ASSERT_EQ(h.size(), 13u);
  const unsigned char expected[13] = {0x01, 0x04, 0x03, 0x02, 0x01, 0x88, 0x77, 0x66, 0x55, 0x44, 0x33, 0x22, 0x11};
  for (std::size_t k = 0; k < 13; ++k) EXPECT_EQ(static_cast<unsigned char>(h[k]), expected[k]) << "byte " << k;
  const std::string frame = h + "{\"a\":1}";  // the parsed views point into it
  const auto m = parse_message_data(frame);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->subscription_id, 0x01020304u);
  EXPECT_EQ(m->timestamp_ns, 0x1122334455667788ull);
  EXPECT_EQ(m->payload, "{\"a\":1}");
  EXPECT_FALSE(parse_message_data(time_message(5)));
  EXPECT_EQ(time_message(5).size(), 9u);
  EXPECT_EQ(time_message(5)[0], '\x02');
}

TEST(FoxgloveProtocol, ServerMessagesHaveTheSpecsFields) {
  const nlohmann::json info = nlohmann::json::parse(server_info_message("mechsim", "42"));
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["capabilities"], nlohmann::json::array({"time"}));
  EXPECT_EQ(info["sessionId"], "42");
  Channel c;
  c.id = 3;
  c.topic = "/tf";
  c.schema_name = "foxglove.FrameTransforms";
  c.schema = "{}";
  const nlohmann::json ad = nlohmann::json::parse(advertise_message({c}));
  EXPECT_EQ(ad["op"], "advertise");
  ASSERT_EQ(ad["channels"].size(), 1u);
  EXPECT_EQ(ad["channels"][0]["id"], 3);
  EXPECT_EQ(ad["channels"][0]["topic"], "/tf");
  EXPECT_EQ(ad["channels"][0]["encoding"], "json");
  EXPECT_EQ(ad["channels"][0]["schemaName"], "foxglove.FrameTransforms");
  EXPECT_EQ(ad["channels"][0]["schemaEncoding"], "jsonschema");
  EXPECT_EQ(nlohmann::json::parse(status_message(1, "x"))["level"], 1);
}

TEST(FoxgloveProtocol, ParsesSubscribeAndUnsubscribe) {
  const ClientRequest s = parse_client_request(R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3},{"id":1,"channelId":5}]})");
  ASSERT_EQ(s.op, ClientRequest::Op::Subscribe);
  ASSERT_EQ(s.subscribe.size(), 2u);
  EXPECT_EQ(s.subscribe[1].id, 1u);
  EXPECT_EQ(s.subscribe[1].channel, 5u);
  const ClientRequest u = parse_client_request(R"({"op":"unsubscribe","subscriptionIds":[0,1]})");
  ASSERT_EQ(u.op, ClientRequest::Op::Unsubscribe);
  EXPECT_EQ(u.unsubscribe, (std::vector<std::uint32_t>{0, 1}));
}

TEST(FoxgloveProtocol, BadRequestsSayWhatIsWrong) {
  EXPECT_EQ(parse_client_request("{not json").op, ClientRequest::Op::Invalid);
  EXPECT_EQ(parse_client_request(R"({"nop":1})").error, "no string field 'op'");
  const ClientRequest neg = parse_client_request(R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":3}]})");
  EXPECT_EQ(neg.op, ClientRequest::Op::Invalid);
  EXPECT_NE(neg.error.find("unsigned 32-bit"), std::string::npos);
  const ClientRequest other = parse_client_request(R"({"op":"getParameters","parameterNames":[]})");
  EXPECT_EQ(other.op, ClientRequest::Op::Ignored);
  EXPECT_NE(other.error.find("getParameters"), std::string::npos);
}

}  // namespace
}  // namespace mechsim::live
