#pragma once
// A Foxglove WebSocket protocol server (foxglove_protocol.hpp) on Boost.Beast, with its own I/O
// thread. Everything it does with clients happens on that thread: the `poll` callback given to
// start() runs there too, so publish() needs no lock. Each client has a bounded send queue: when
// a client reads slower than messages come, its oldest queued messages are dropped (the newest
// win) and counted, so a stalled client costs a bounded amount of memory and never slows
// anything but itself. Listening happens in the constructor: a busy port is an error before
// anything else starts.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "live/foxglove_protocol.hpp"

namespace mechsim::live {

// A server that cannot start (port busy, bad address).
class LiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ServerOptions {
  std::string address = "127.0.0.1";  // loopback by default; "0.0.0.0" serves every interface
  unsigned short port = 8765;          // Foxglove's default; 0: any free port (see port())
  std::string name = "mechsim";
  // Per client: at most this many messages and bytes waiting to be sent (the oldest go first).
  std::size_t max_queued_messages = 32;
  std::size_t max_queued_bytes = 4u << 20;
  // The socket's kernel send buffer per client (bytes): what a stalled client can hold besides
  // its queue; small, so that a slow client sees recent messages rather than old ones.
  int send_buffer_bytes = 256 * 1024;
};

struct ServerStats {
  std::uint64_t clients_accepted = 0;
  std::uint64_t clients_now = 0;
  std::uint64_t messages_sent = 0;     // message data frames written to clients
  std::uint64_t messages_dropped = 0;  // dropped from a full client queue
  std::uint64_t peak_queued_bytes = 0;  // the largest queue of one client (bytes)
};

class FoxgloveServer {
 public:
  // Listens on options.address:options.port; throws LiveError naming the address and port.
  // Connections wait for start() (the kernel holds them in the listen backlog).
  explicit FoxgloveServer(ServerOptions options);
  ~FoxgloveServer();  // stop()
  FoxgloveServer(const FoxgloveServer&) = delete;
  FoxgloveServer& operator=(const FoxgloveServer&) = delete;

  unsigned short port() const;  // the port listened on (the chosen one for port 0)
  const std::string& address() const;

  // The channels every client is told about (before start()).
  void set_channels(std::vector<Channel> channels);
  // Starts the I/O thread; `poll` runs on it every `period`.
  void start(std::function<void()> poll, std::chrono::microseconds period);
  // Closes every connection and joins the thread (idempotent).
  void stop();

  // I/O thread only (from `poll`). Sends `payload` on `channel` to its subscribers.
  void publish(std::uint32_t channel, std::uint64_t timestamp_ns, const std::shared_ptr<const std::string>& payload);
  // The message a new subscriber of `channel` gets first (a latched topic: robot description).
  void set_latched(std::uint32_t channel, std::uint64_t timestamp_ns, std::shared_ptr<const std::string> payload);
  // Opcode 2 time to every client.
  void broadcast_time(std::uint64_t timestamp_ns);
  bool has_subscribers(std::uint32_t channel) const;

  ServerStats stats() const;  // any thread

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

}  // namespace mechsim::live
