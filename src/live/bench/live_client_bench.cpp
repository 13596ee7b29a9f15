// A Foxglove WebSocket client for measuring what a live view costs a run
// (scripts/live_rtf_bench.sh) and for looking at a stream: connects to 127.0.0.1:PORT, subscribes
// to TOPICs (default /tf and /joint_states), then reads for SECONDS (or until the server closes)
// and prints the rates it got and each topic's last message cut to 300 characters, or ("stall")
// subscribes and never reads again, with a 4 kB receive buffer.
//   live_bench PORT read|stall SECONDS [TOPIC...]

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "live/test/foxglove_test_client.hpp"

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: live_bench PORT read|stall SECONDS [TOPIC...]\n");
    return 2;
  }
  const auto port = static_cast<unsigned short>(std::atoi(argv[1]));
  const std::string mode = argv[2];
  const double seconds = std::atof(argv[3]);
  std::vector<std::string> topics(argv + 4, argv + argc);
  if (topics.empty()) topics = {"/tf", "/joint_states"};
  // The run may still be building its world: retry the connection for up to 60 s.
  for (int attempt = 0; attempt < 600; ++attempt) {
    try {
      mechsim::live::test::FoxgloveTestClient client(port, mode == "stall" ? 4096 : 0);
      for (const std::string& t : topics) {
        if (client.channels().count(t) == 0) {
          std::fprintf(stderr, "live_bench: no channel %s\n", t.c_str());
          return 1;
        }
      }
      client.subscribe(topics);
      if (mode == "stall") {
        std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
        return 0;
      }
      const auto got = client.read_for(seconds);
      std::map<std::string, std::size_t> count;
      std::map<std::string, std::string> last;
      std::size_t bytes = 0;
      for (const auto& m : got) {
        ++count[m.topic];
        last[m.topic] = m.payload.substr(0, 300);
        bytes += m.payload.size();
      }
      const double span = got.size() > 1 ? std::chrono::duration<double>(got.back().received - got.front().received).count() : 0.0;
      for (const auto& [topic, n] : count) {
        std::printf("%s: %zu messages, %.1f Hz over %.1f s\n", topic.c_str(), n, span > 0 ? static_cast<double>(n) / span : 0.0, span);
        if (getenv("LIVE_BENCH_SHOW") != nullptr) std::printf("  last: %s\n", last[topic].c_str());
      }
      std::printf("%.1f kB/s\n", span > 0 ? static_cast<double>(bytes) / span / 1e3 : 0.0);
      return 0;
    } catch (const std::exception&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  std::fprintf(stderr, "live_bench: no server on 127.0.0.1:%u\n", port);
  return 1;
}
