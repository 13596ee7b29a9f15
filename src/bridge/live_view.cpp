// SimBridge's live view (~foxglove_port): the live layer's stream over the bridge's simulation.
#include <string>

#include "live/live_stream.hpp"
#include "bridge/bridge_impl.hpp"

namespace mechsim::bridge {

std::string SimBridge::start_live_view(const std::string& address, int port, const std::string& urdf, double rate) {
  if (port < 0 || port > 65535) throw std::runtime_error("~foxglove_port: " + std::to_string(port) + " is not a TCP port (0..65535)");
  live::ServerOptions server;
  server.address = address;
  server.port = static_cast<unsigned short>(port);
  auto listening = std::make_unique<live::FoxgloveServer>(server);  // throws LiveError (a runtime_error)
  live::StreamRates rates;
  rates.tf = rates.joint_states = rates.odometry = rate;
  impl_->live = std::make_unique<live::LiveStream>(std::move(listening), *impl_->simulation, urdf,
                                                   std::vector<std::array<double, 2>>{}, rates);
  return live::live_url(impl_->live->server());
}

std::string SimBridge::live_view_summary() const {
  if (!impl_->live) return "";
  const live::StreamStats s = impl_->live->stats();
  return std::to_string(s.server.clients_accepted) + " clients, " + std::to_string(s.server.messages_sent) +
         " messages sent, " + std::to_string(s.server.messages_dropped) + " dropped, peak client queue " +
         std::to_string(s.server.peak_queued_bytes) + " bytes";
}

}  // namespace mechsim::bridge
