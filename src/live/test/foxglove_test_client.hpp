#pragma once
// A Foxglove WebSocket protocol client for tests (Boost.Beast, blocking, loopback): connects
// with the foxglove.websocket.v1 subprotocol, reads serverInfo and advertise, subscribes by topic
// and reads frames until a deadline. Header-only: the live layer's unit tests and the CLI test of
// `mechsim run --live` both use it.

#include <poll.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/websocket/stream.hpp>
#include <nlohmann/json.hpp>

#include "live/foxglove_protocol.hpp"

namespace mechsim::live::test {

struct ReceivedMessage {
  std::string topic;
  std::uint64_t timestamp_ns = 0;
  std::string payload;
  std::chrono::steady_clock::time_point received;
};

class FoxgloveTestClient {
 public:
  // Connects to 127.0.0.1:port; `receive_buffer` > 0 sets the socket's kernel receive buffer
  // (bytes) before connecting (a small one makes a client that stops reading stall the server's
  // writes quickly). Throws on failure.
  explicit FoxgloveTestClient(unsigned short port, int receive_buffer = 0) : ws_(io_) {
    namespace asio = boost::asio;
    using tcp = asio::ip::tcp;
    tcp::socket& socket = ws_.next_layer();
    socket.open(tcp::v4());
    if (receive_buffer > 0) socket.set_option(asio::socket_base::receive_buffer_size(receive_buffer));
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    boost::beast::websocket::response_type response;
    ws_.set_option(boost::beast::websocket::stream_base::decorator([](boost::beast::websocket::request_type& request) {
      request.set(boost::beast::http::field::sec_websocket_protocol, std::string(kSubprotocol));
    }));
    ws_.handshake(response, "127.0.0.1:" + std::to_string(port), "/");
    const auto protocol = response[boost::beast::http::field::sec_websocket_protocol];
    subprotocol_ = std::string(protocol.data(), protocol.size());
    // serverInfo, then advertise.
    while (server_info_.is_null() || channels_.empty()) {
      std::string text;
      if (!read_frame(text) || !text_) continue;
      const nlohmann::json j = nlohmann::json::parse(text);
      if (j.at("op") == "serverInfo") server_info_ = j;
      if (j.at("op") == "advertise") {
        for (const nlohmann::json& c : j.at("channels")) channels_[c.at("topic").get<std::string>()] = c;
      }
    }
  }

  const std::string& subprotocol() const { return subprotocol_; }
  const nlohmann::json& server_info() const { return server_info_; }
  const std::map<std::string, nlohmann::json>& channels() const { return channels_; }

  // Subscribes to `topics` (each must be advertised); subscription ids 1, 2, ...
  void subscribe(const std::vector<std::string>& topics) {
    nlohmann::json subs = nlohmann::json::array();
    for (const std::string& topic : topics) {
      const std::uint32_t id = static_cast<std::uint32_t>(topic_of_.size() + 1);
      topic_of_[id] = topic;
      subs.push_back({{"id", id}, {"channelId", channels_.at(topic).at("id")}});
    }
    send_text(nlohmann::json{{"op", "subscribe"}, {"subscriptions", subs}}.dump());
  }

  void send_text(const std::string& text) {
    ws_.text(true);
    ws_.write(boost::asio::buffer(text));
  }

  // Reads frames for `seconds` of wall time (or until the server closes): message data frames
  // of the subscriptions, and the text frames (status) in texts().
  std::vector<ReceivedMessage> read_for(double seconds) {
    std::vector<ReceivedMessage> out;
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                            std::chrono::duration<double>(seconds));
    while (std::chrono::steady_clock::now() < end) {
      std::string frame;
      if (!read_frame(frame, end)) break;
      if (text_) {
        texts_.push_back(frame);
        continue;
      }
      if (const auto m = parse_message_data(frame)) {
        const auto topic = topic_of_.find(m->subscription_id);
        out.push_back({topic == topic_of_.end() ? "" : topic->second, m->timestamp_ns, std::string(m->payload),
                       std::chrono::steady_clock::now()});
      } else if (!frame.empty() && frame[0] == '\x02') {
        ++time_frames_;
      }
    }
    return out;
  }

  const std::vector<std::string>& texts() const { return texts_; }
  std::size_t time_frames() const { return time_frames_; }

 private:
  // One frame (false: closed, or the deadline passed).
  bool read_frame(std::string& frame, std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt) {
    boost::beast::error_code ec;
    if (deadline) {
      // Wait for data in short polls so that read_for() ends on time; readable with nothing to
      // read is the server's end of the connection.
      while (buffer_.size() == 0) {
        pollfd fd{ws_.next_layer().native_handle(), POLLIN, 0};
        const int ready = ::poll(&fd, 1, 2);
        if (ready < 0) return false;
        if (ready > 0) {
          if ((fd.revents & (POLLERR | POLLHUP)) != 0) return false;
          if (ws_.next_layer().available(ec) == 0 || ec) return false;
          break;
        }
        if (std::chrono::steady_clock::now() >= *deadline) return false;
      }
    }
    buffer_.consume(buffer_.size());
    ws_.read(buffer_, ec);
    if (ec) return false;
    text_ = ws_.got_text();
    frame = boost::beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    return true;
  }

  boost::asio::io_context io_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws_;
  boost::beast::flat_buffer buffer_;
  bool text_ = false;
  std::string subprotocol_;
  nlohmann::json server_info_;
  std::map<std::string, nlohmann::json> channels_;
  std::map<std::uint32_t, std::string> topic_of_;
  std::vector<std::string> texts_;
  std::size_t time_frames_ = 0;
};

}  // namespace mechsim::live::test
