// A Foxglove WebSocket client for measuring what a live view costs a run
// (scripts/live_rtf_bench.sh): connects to 127.0.0.1:PORT, subscribes to /tf and /joint_states,
// then reads for SECONDS and prints the rates it got, or ("stall") subscribes and never reads
// again, with a 4 kB receive buffer, until the server closes or SECONDS pass.
//   live_bench PORT read|stall SECONDS

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <thread>

#include "live/test/foxglove_test_client.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: live_bench PORT read|stall SECONDS\n");
    return 2;
  }
  const auto port = static_cast<unsigned short>(std::atoi(argv[1]));
  const std::string mode = argv[2];
  const double seconds = std::atof(argv[3]);
  // The run may still be building its world: retry the connection for up to 60 s.
  for (int attempt = 0; attempt < 600; ++attempt) {
    try {
      mechsim::live::test::FoxgloveTestClient client(port, mode == "stall" ? 4096 : 0);
      client.subscribe({"/tf", "/joint_states"});
      if (mode == "stall") {
        std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
        return 0;
      }
      const auto got = client.read_for(seconds);
      std::map<std::string, std::size_t> count;
      std::size_t bytes = 0;
      for (const auto& m : got) {
        ++count[m.topic];
        bytes += m.payload.size();
      }
      const double span = got.size() > 1 ? std::chrono::duration<double>(got.back().received - got.front().received).count() : 0.0;
      for (const auto& [topic, n] : count) {
        std::printf("%s: %zu messages, %.1f Hz over %.1f s\n", topic.c_str(), n, span > 0 ? static_cast<double>(n) / span : 0.0, span);
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
