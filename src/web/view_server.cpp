#include "web/view_server.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <fstream>
#include <sstream>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

#include "web/replay_folder.hpp"

namespace mechsim::web {
namespace {

namespace fs = std::filesystem;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

std::optional<std::string> read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

// The status.json body: the folder's check as the page reads it.
std::string status_json(const ReplayFolder& folder) {
  nlohmann::json j = {{"ok", folder.ok}, {"error", folder.error}, {"report", folder.report.string()}, {"scenario", folder.scenario}};
  return j.dump();
}

}  // namespace

std::string content_type(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".jsonl") return "application/x-ndjson";
  if (ext == ".png") return "image/png";
  if (ext == ".urdf") return "application/xml";
  if (ext == ".obj") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

struct ViewServer::Impl {
  fs::path report, page_dir;
  asio::io_context io;
  tcp::acceptor acceptor{io};

  http::response<http::string_body> respond(const http::request<http::string_body>& request) {
    http::response<http::string_body> response;
    response.version(request.version());
    response.keep_alive(false);
    response.set(http::field::server, "mechsim view");
    response.set(http::field::cache_control, "no-store");
    auto body = [&](http::status status, std::string type, std::string text) {
      response.result(status);
      response.set(http::field::content_type, type);
      response.body() = std::move(text);
    };
    if (request.method() != http::verb::get && request.method() != http::verb::head) {
      body(http::status::method_not_allowed, "text/plain", "GET only\n");
      response.prepare_payload();
      return response;
    }
    std::string target(request.target());
    if (const auto q = target.find('?'); q != std::string::npos) target.resize(q);
    if (target == "/") target = "/index.html";
    std::optional<std::string> text;
    std::string type;
    if (target == "/index.html" || target == "/app.js") {
      text = read_file(page_dir / target.substr(1));
      type = content_type(target);
    } else if (target == "/status.json") {
      text = status_json(check_replay_folder(report));
      type = "application/json";
    } else if (target.rfind("/report/", 0) == 0) {
      // Only what the folder's check lists, so that no path (.., links) reaches elsewhere.
      const std::string relative = target.substr(8);
      const ReplayFolder folder = check_replay_folder(report);
      if (std::find(folder.files.begin(), folder.files.end(), relative) != folder.files.end()) {
        text = read_file(report / relative);
        type = content_type(relative);
      }
    }
    if (text) {
      body(http::status::ok, type, std::move(*text));
    } else {
      body(http::status::not_found, "text/plain", "not found: " + target + "\n");
    }
    response.prepare_payload();
    return response;
  }

  void serve(tcp::socket socket) {
    beast::tcp_stream stream(std::move(socket));
    beast::flat_buffer buffer;
    http::request<http::string_body> request;
    beast::error_code ec;
    stream.expires_after(std::chrono::seconds(10));
    http::read(stream, buffer, request, ec);
    if (ec) return;  // the client went away or sent no HTTP: nothing to answer
    http::response<http::string_body> response = respond(request);
    if (request.method() == http::verb::head) response.body().clear();
    http::write(stream, response, ec);
    stream.socket().shutdown(tcp::socket::shutdown_send, ec);
  }

  void accept_next() {
    acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
      if (!ec) serve(std::move(socket));
      if (acceptor.is_open()) accept_next();
    });
  }
};

ViewServer::ViewServer(fs::path report, fs::path page_dir, unsigned short port) : impl_(std::make_unique<Impl>()) {
  impl_->report = std::move(report);
  impl_->page_dir = std::move(page_dir);
  const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"), port);
  beast::error_code ec;
  impl_->acceptor.open(endpoint.protocol(), ec);
  // SO_REUSEADDR: a port left in TIME_WAIT by an earlier view is free again; Linux still refuses
  // a second listener on it.
  if (!ec) impl_->acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) impl_->acceptor.bind(endpoint, ec);
  if (ec == asio::error::address_in_use) {
    throw ViewError("port " + std::to_string(port) + " on 127.0.0.1 is in use (another mechsim view?): choose another with --port, or --port 0 for any free one");
  }
  if (!ec) impl_->acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) throw ViewError("cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + ec.message());
}

ViewServer::~ViewServer() = default;

unsigned short ViewServer::port() const { return impl_->acceptor.local_endpoint().port(); }

void ViewServer::run(const std::atomic<int>& stop) {
  impl_->accept_next();
  while (stop.load() == 0) {
    impl_->io.run_for(std::chrono::milliseconds(200));
    if (impl_->io.stopped()) impl_->io.restart();
  }
  beast::error_code ec;
  impl_->acceptor.close(ec);
  impl_->io.run_for(std::chrono::milliseconds(50));
}

}  // namespace mechsim::web
