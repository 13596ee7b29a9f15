#pragma once
// `mechsim view`'s HTTP server (Boost.Beast) on 127.0.0.1: the replay page (index.html, app.js
// from the built front end), status.json (the report folder's check, redone on every request so
// that a report rewritten under a running server shows its state), and the report's replay files
// under /report/ (only the files the check lists: nothing else of the disk is reachable).

#include <atomic>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

namespace mechsim::web {

struct ViewError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ViewServer {
 public:
  // Binds 127.0.0.1:`port` (0: a free port the system picks). Throws ViewError when the port is
  // in use or cannot be bound, naming it.
  ViewServer(std::filesystem::path report, std::filesystem::path page_dir, unsigned short port);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  unsigned short port() const;
  // Serves until *stop becomes non-zero (checked about every 0.2 s), one request a connection.
  void run(const std::atomic<int>& stop);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A page file's MIME type from its extension.
std::string content_type(const std::filesystem::path& file);

}  // namespace mechsim::web
