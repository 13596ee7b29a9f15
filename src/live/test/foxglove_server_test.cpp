#include "live/foxglove_server.hpp"

#include <atomic>
#include <thread>

#include <gtest/gtest.h>

#include "live/test/foxglove_test_client.hpp"

namespace mechsim::live {
namespace {

std::vector<Channel> two_channels() {
  Channel a;
  a.id = 1;
  a.topic = "/a";
  a.schema_name = "A";
  a.schema = "{}";
  Channel b = a;
  b.id = 2;
  b.topic = "/b";
  return {a, b};
}

ServerOptions any_port() {
  ServerOptions o;
  o.port = 0;
  return o;
}

TEST(FoxgloveServer, ClientGetsInfoAdvertiseAndItsSubscriptionsOnly) {
  auto server = std::make_unique<FoxgloveServer>(any_port());
  ASSERT_NE(server->port(), 0);
  server->set_channels(two_channels());
  server->set_latched(2, 5, std::make_shared<const std::string>("latched"));
  std::atomic<int> polls{0};
  FoxgloveServer* s = server.get();
  server->start(
      [s, &polls] {
        const int n = ++polls;
        s->publish(1, static_cast<std::uint64_t>(n), std::make_shared<const std::string>("a" + std::to_string(n)));
      },
      std::chrono::milliseconds(5));
  test::FoxgloveTestClient client(server->port());
  EXPECT_EQ(client.subprotocol(), "foxglove.websocket.v1");
  EXPECT_EQ(client.server_info()["name"], "mechsim");
  ASSERT_EQ(client.channels().size(), 2u);
  client.subscribe({"/b"});
  const std::vector<test::ReceivedMessage> only_b = client.read_for(0.3);
  ASSERT_EQ(only_b.size(), 1u);  // the latched message; nothing of /a
  EXPECT_EQ(only_b[0].topic, "/b");
  EXPECT_EQ(only_b[0].payload, "latched");
  EXPECT_EQ(only_b[0].timestamp_ns, 5u);
  client.subscribe({"/a"});
  const std::vector<test::ReceivedMessage> got = client.read_for(0.5);
  ASSERT_GT(got.size(), 10u);
  for (const auto& m : got) {
    EXPECT_EQ(m.topic, "/a");
    EXPECT_EQ(m.payload, "a" + std::to_string(m.timestamp_ns));
  }
  client.send_text(R"({"op":"subscribe","subscriptions":[{"id":9,"channelId":77}]})");
  client.read_for(0.2);
  ASSERT_FALSE(client.texts().empty());
  EXPECT_NE(client.texts().back().find("no channel 77"), std::string::npos);
  server->stop();
  EXPECT_EQ(server->stats().clients_accepted, 1u);
}

TEST(FoxgloveServer, BusyPortIsAClearError) {
  FoxgloveServer first(any_port());
  ServerOptions same;
  same.port = first.port();
  try {
    FoxgloveServer second(same);
    FAIL() << "a second server listened on a busy port";
  } catch (const LiveError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cannot listen on 127.0.0.1:" + std::to_string(first.port())), std::string::npos) << what;
    EXPECT_NE(what.find("--port"), std::string::npos) << what;
  }
  ServerOptions bad;
  bad.address = "not-an-address";
  EXPECT_THROW(FoxgloveServer{bad}, LiveError);
}

// A client that subscribes and then stops reading: the server drops its oldest messages, its
// queue stays within the bounds, and the publisher (the poll) never waits.
TEST(FoxgloveServer, StalledClientGetsDropsAndBoundedMemory) {
  ServerOptions options = any_port();
  options.max_queued_messages = 16;
  options.max_queued_bytes = 256 * 1024;
  options.send_buffer_bytes = 16 * 1024;
  auto server = std::make_unique<FoxgloveServer>(options);
  server->set_channels(two_channels());
  const auto payload = std::make_shared<const std::string>(std::string(20000, 'x'));
  std::atomic<int> polls{0};
  std::atomic<double> slowest_poll{0.0};
  FoxgloveServer* s = server.get();
  server->start(
      [&, s] {
        const auto t0 = std::chrono::steady_clock::now();
        for (int k = 0; k < 10; ++k) s->publish(1, 1, payload);
        const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (took > slowest_poll.load()) slowest_poll.store(took);
        ++polls;
      },
      std::chrono::milliseconds(2));
  test::FoxgloveTestClient client(server->port(), 4096);
  client.subscribe({"/a"});
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // not reading
  const ServerStats st = server->stats();
  EXPECT_GT(polls.load(), 100);  // the poll kept its pace
  EXPECT_GT(st.messages_dropped, 1000u);
  EXPECT_LE(st.peak_queued_bytes, options.max_queued_bytes + payload->size() + 64);
  EXPECT_LT(slowest_poll.load(), 0.1);
  server->stop();
}

}  // namespace
}  // namespace mechsim::live
