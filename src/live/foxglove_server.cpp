#include "live/foxglove_server.hpp"

#include <array>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/string_body.hpp>
#include <boost/beast/websocket/stream.hpp>

namespace mechsim::live {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

// One queued frame: a small head (the whole of a text frame, or a message data header) and an
// optional payload shared by every subscriber.
struct Outgoing {
  std::string head;
  std::shared_ptr<const std::string> payload;
  bool text = false;
  bool droppable = false;  // message data; protocol messages are never dropped
  std::size_t bytes() const { return head.size() + (payload ? payload->size() : 0); }
};

}  // namespace

struct FoxgloveServer::Impl : std::enable_shared_from_this<FoxgloveServer::Impl> {
  struct Session;

  ServerOptions options;
  std::vector<Channel> channels;
  std::string session_id;
  asio::io_context io{1};
  tcp::acceptor acceptor{io};
  asio::steady_timer poll_timer{io};
  std::function<void()> poll;
  std::chrono::microseconds poll_period{0};
  std::thread thread;
  std::vector<std::shared_ptr<Session>> sessions;  // I/O thread
  std::map<std::uint32_t, std::pair<std::uint64_t, std::shared_ptr<const std::string>>> latched;  // I/O thread
  std::atomic<std::uint64_t> accepted{0}, now{0}, sent{0}, dropped{0}, peak{0};
  bool stopped = false;

  struct Session : std::enable_shared_from_this<Session> {
    Impl& server;
    websocket::stream<tcp::socket> ws;
    beast::flat_buffer read_buffer;
    http::request<http::string_body> request;
    std::deque<Outgoing> queue;
    // The frame being written: out of the queue, so that dropping queued frames (a deque erase
    // moves elements) or closing never moves or frees what the write's buffers point into.
    std::optional<Outgoing> in_flight;
    std::size_t queued_bytes = 0;  // queue and in_flight
    bool open = false, closed = false;
    std::map<std::uint32_t, std::uint32_t> subscription_of_channel;  // channel -> subscription id
    std::array<asio::const_buffer, 2> buffers;

    Session(Impl& s, tcp::socket socket) : server(s), ws(std::move(socket)) {}

    void start() {
      beast::error_code ec;
      ws.next_layer().set_option(tcp::no_delay(true), ec);
      ws.next_layer().set_option(asio::socket_base::send_buffer_size(server.options.send_buffer_bytes), ec);
      http::async_read(ws.next_layer(), read_buffer, request,
                       [self = shared_from_this()](beast::error_code e, std::size_t) { self->on_request(e); });
    }

    void on_request(beast::error_code ec) {
      if (ec || !websocket::is_upgrade(request)) return close();
      const auto protocols = request[http::field::sec_websocket_protocol];
      const bool offered = std::string_view(protocols.data(), protocols.size()).find(kSubprotocol) != std::string_view::npos;
      ws.set_option(websocket::stream_base::decorator([offered](websocket::response_type& response) {
        response.set(http::field::server, "mechsim");
        if (offered) response.set(http::field::sec_websocket_protocol, std::string(kSubprotocol));
      }));
      ws.async_accept(request, [self = shared_from_this()](beast::error_code e) { self->on_accept(e); });
    }

    void on_accept(beast::error_code ec) {
      if (ec) return close();
      open = true;
      enqueue({server_info_message(server.options.name, server.session_id), nullptr, true, false});
      enqueue({advertise_message(server.channels), nullptr, true, false});
      read();
    }

    void read() {
      ws.async_read(read_buffer, [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
    }

    void on_read(beast::error_code ec) {
      if (ec) return close();
      if (ws.got_text()) handle(beast::buffers_to_string(read_buffer.data()));
      read_buffer.consume(read_buffer.size());
      read();
    }

    void handle(const std::string& text) {
      const ClientRequest r = parse_client_request(text);
      switch (r.op) {
        case ClientRequest::Op::Subscribe:
          for (const ClientRequest::Subscription& s : r.subscribe) {
            bool known = false;
            for (const Channel& c : server.channels) known = known || c.id == s.channel;
            if (!known) {
              enqueue({status_message(1, "subscribe: no channel " + std::to_string(s.channel)), nullptr, true, false});
              continue;
            }
            subscription_of_channel[s.channel] = s.id;
            if (auto l = server.latched.find(s.channel); l != server.latched.end()) {
              enqueue({message_data_header(s.id, l->second.first), l->second.second, false, false});
            }
          }
          break;
        case ClientRequest::Op::Unsubscribe:
          for (const std::uint32_t id : r.unsubscribe) {
            for (auto it = subscription_of_channel.begin(); it != subscription_of_channel.end();) {
              it = it->second == id ? subscription_of_channel.erase(it) : std::next(it);
            }
          }
          break;
        case ClientRequest::Op::Ignored:
        case ClientRequest::Op::Invalid:
          enqueue({status_message(1, r.error), nullptr, true, false});
          break;
      }
    }

    void enqueue(Outgoing out) {
      if (closed) return;
      queued_bytes += out.bytes();
      queue.push_back(std::move(out));
      // Over the bounds: drop the oldest droppable message waiting (not the one being written).
      while (queue.size() > server.options.max_queued_messages || queued_bytes > server.options.max_queued_bytes) {
        auto victim = queue.begin();
        while (victim != queue.end() && !victim->droppable) ++victim;
        if (victim == queue.end()) break;
        queued_bytes -= victim->bytes();
        queue.erase(victim);
        server.dropped.fetch_add(1, std::memory_order_relaxed);
      }
      std::uint64_t peak = server.peak.load(std::memory_order_relaxed);
      while (queued_bytes > peak && !server.peak.compare_exchange_weak(peak, queued_bytes)) {
      }
      write();
    }

    void write() {
      if (in_flight || queue.empty() || !open || closed) return;
      in_flight = std::move(queue.front());
      queue.pop_front();
      const Outgoing& out = *in_flight;
      ws.text(out.text);
      buffers[0] = asio::buffer(out.head);
      buffers[1] = out.payload ? asio::buffer(*out.payload) : asio::const_buffer();
      ws.async_write(buffers, [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_write(ec); });
    }

    void on_write(beast::error_code ec) {
      queued_bytes -= in_flight->bytes();
      if (!ec && in_flight->droppable) server.sent.fetch_add(1, std::memory_order_relaxed);
      in_flight.reset();
      if (ec) return close();
      write();
    }

    void close() {
      if (closed) return;
      closed = true;
      for (const Outgoing& out : queue) queued_bytes -= out.bytes();
      queue.clear();  // in_flight stays until its write completes (aborted by the close below)
      beast::error_code ec;
      ws.next_layer().shutdown(tcp::socket::shutdown_both, ec);
      ws.next_layer().close(ec);
      auto& list = server.sessions;
      for (auto it = list.begin(); it != list.end(); ++it) {
        if (it->get() == this) {
          list.erase(it);
          server.now.fetch_sub(1, std::memory_order_relaxed);
          break;
        }
      }
    }
  };

  void accept() {
    acceptor.async_accept([self = shared_from_this()](beast::error_code ec, tcp::socket socket) {
      if (ec) return;  // closed by stop()
      auto session = std::make_shared<Session>(*self, std::move(socket));
      self->sessions.push_back(session);
      self->accepted.fetch_add(1, std::memory_order_relaxed);
      self->now.fetch_add(1, std::memory_order_relaxed);
      session->start();
      self->accept();
    });
  }

  void schedule_poll() {
    poll_timer.expires_after(poll_period);
    poll_timer.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec || self->stopped) return;
      if (self->poll) self->poll();
      self->schedule_poll();
    });
  }
};

FoxgloveServer::FoxgloveServer(ServerOptions options) : impl_(std::make_shared<Impl>()) {
  impl_->options = std::move(options);
  impl_->session_id = std::to_string(std::chrono::system_clock::now().time_since_epoch().count());
  const std::string where = impl_->options.address + ":" + std::to_string(impl_->options.port);
  beast::error_code ec;
  const asio::ip::address address = asio::ip::make_address(impl_->options.address, ec);
  if (ec) throw LiveError("live view: '" + impl_->options.address + "' is not an IP address");
  const tcp::endpoint endpoint(address, impl_->options.port);
  impl_->acceptor.open(endpoint.protocol(), ec);
  if (!ec) impl_->acceptor.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) impl_->acceptor.bind(endpoint, ec);
  if (!ec) impl_->acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) {
    std::string text = "live view: cannot listen on " + where + ": " + ec.message();
    if (ec == asio::error::address_in_use) {
      text += " (another mechsim --live, a foxglove_bridge or another server has it: choose another --port, or 0 for any free port)";
    }
    throw LiveError(text);
  }
}

FoxgloveServer::~FoxgloveServer() { stop(); }

unsigned short FoxgloveServer::port() const {
  beast::error_code ec;
  return impl_->acceptor.local_endpoint(ec).port();
}

const std::string& FoxgloveServer::address() const { return impl_->options.address; }

void FoxgloveServer::set_channels(std::vector<Channel> channels) { impl_->channels = std::move(channels); }

void FoxgloveServer::start(std::function<void()> poll, std::chrono::microseconds period) {
  impl_->poll = std::move(poll);
  impl_->poll_period = period;
  impl_->accept();
  impl_->schedule_poll();
  impl_->thread = std::thread([impl = impl_] { impl->io.run(); });
}

void FoxgloveServer::stop() {
  if (!impl_->thread.joinable()) return;
  asio::post(impl_->io, [impl = impl_] {
    impl->stopped = true;
    beast::error_code ec;
    impl->acceptor.close(ec);
    impl->poll_timer.cancel();
    const auto sessions = impl->sessions;  // close() edits the list
    for (const auto& s : sessions) s->close();
    // run() returns once the aborted operations' handlers have run: nothing is left holding
    // the server or a session.
  });
  impl_->thread.join();
}

void FoxgloveServer::publish(std::uint32_t channel, std::uint64_t timestamp_ns, const std::shared_ptr<const std::string>& payload) {
  const auto sessions = impl_->sessions;  // a failing write may close (and remove) a session
  for (const auto& s : sessions) {
    const auto sub = s->subscription_of_channel.find(channel);
    if (sub == s->subscription_of_channel.end()) continue;
    s->enqueue({message_data_header(sub->second, timestamp_ns), payload, false, true});
  }
}

void FoxgloveServer::set_latched(std::uint32_t channel, std::uint64_t timestamp_ns, std::shared_ptr<const std::string> payload) {
  impl_->latched[channel] = {timestamp_ns, std::move(payload)};
}

void FoxgloveServer::broadcast_time(std::uint64_t timestamp_ns) {
  const std::string frame = time_message(timestamp_ns);
  const auto sessions = impl_->sessions;
  for (const auto& s : sessions) {
    if (s->open) s->enqueue({frame, nullptr, false, true});
  }
}

bool FoxgloveServer::has_subscribers(std::uint32_t channel) const {
  for (const auto& s : impl_->sessions) {
    if (s->subscription_of_channel.count(channel) != 0) return true;
  }
  return false;
}

ServerStats FoxgloveServer::stats() const {
  ServerStats s;
  s.clients_accepted = impl_->accepted.load(std::memory_order_relaxed);
  s.clients_now = impl_->now.load(std::memory_order_relaxed);
  s.messages_sent = impl_->sent.load(std::memory_order_relaxed);
  s.messages_dropped = impl_->dropped.load(std::memory_order_relaxed);
  s.peak_queued_bytes = impl_->peak.load(std::memory_order_relaxed);
  return s;
}

}  // namespace mechsim::live
