#pragma once
// A running simulation streamed to Foxglove Studio / Lichtblick (and any Foxglove WebSocket
// client) while it runs. The tick side and the network side share nothing but a triple buffer:
//   tick (loop thread)  an observer copies a Snapshot into the triple buffer's free slot every
//                       1/snapshot_rate s of simulation time: no allocation, no lock, no wait;
//   server (I/O thread) every poll period takes the newest snapshot (if any), encodes the
//                       channels that are due as JSON and queues them to their subscribers,
//                       dropping the oldest queued messages of a client that reads too slowly.
// Rates are in simulation time (Hz): with a real-time pace they are wall-clock rates too.

#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "live/foxglove_server.hpp"
#include "live/snapshot.hpp"
#include "live/triple_buffer.hpp"

namespace mechsim::sim {
class Simulation;
}  // namespace mechsim::sim

namespace mechsim::live {

struct StreamRates {
  double tf = 30.0;           // Hz, /tf
  double joint_states = 30.0;  // Hz, /joint_states
  double odometry = 30.0;     // Hz, /odom
  double scans = 10.0;        // Hz at most, /scan/<name> (never faster than the laser)
};

struct StreamStats {
  ServerStats server;
  std::uint64_t snapshots_published = 0;  // by the tick
  std::uint64_t snapshots_taken = 0;      // by the server (the rest were overwritten unread)
};

class LiveStream {
 public:
  // Lays out `sim`'s robot, advertises its channels on `server` (already listening) and starts
  // it, and adds the snapshot observer to `sim`. The stream must outlive the simulation's ticks
  // (the observer refers to it); `urdf` is the expanded description (/robot_description, empty:
  // none), `waypoints` (x, y) in the world (m) the scenario markers (empty: none).
  LiveStream(std::unique_ptr<FoxgloveServer> server, sim::Simulation& sim, std::string urdf,
             std::vector<std::array<double, 2>> waypoints, StreamRates rates);
  ~LiveStream();
  LiveStream(const LiveStream&) = delete;
  LiveStream& operator=(const LiveStream&) = delete;

  const StreamLayout& layout() const { return layout_; }
  const FoxgloveServer& server() const { return *server_; }
  const std::vector<Channel>& channels() const { return channels_; }
  StreamStats stats() const;
  // Stops the server (closes every connection); the observer then only fills the buffer.
  void stop();

 private:
  void poll();  // I/O thread

  enum class Kind { Tf, JointStates, Odometry, Scan, RobotDescription, Markers };
  struct ChannelState {
    Kind kind = Kind::Tf;
    std::size_t laser = 0;
    double period = 0.0;    // s of simulation time between messages
    double last_sent = -1e300;  // s, the simulation time of the last message
    std::uint64_t last_scan = 0;
    std::string text;       // reused encoding buffer
  };

  StreamRates rates_;
  StreamLayout layout_;
  std::vector<Channel> channels_;
  std::vector<ChannelState> state_;  // per channel (I/O thread)
  TripleBuffer<Snapshot> buffer_;
  std::uint64_t snapshot_every_ = 1;  // ticks
  double snapshot_period_ = 0.0;      // s
  std::unique_ptr<FoxgloveServer> server_;
};

// "ws://ADDRESS:PORT" of a server (0.0.0.0 shown as localhost).
std::string live_url(const FoxgloveServer& server);

}  // namespace mechsim::live
