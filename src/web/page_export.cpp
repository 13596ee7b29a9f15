#include "web/page_export.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "web/view_server.hpp"

namespace mechsim::web {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ViewError("cannot read " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

void replace_once(std::string& text, const std::string& what, const std::string& with, const fs::path& file) {
  const std::size_t at = text.find(what);
  if (at == std::string::npos) throw ViewError(file.string() + ": no '" + what + "' (a page from another mechsim build?)");
  text.replace(at, what.size(), with);
}

// Text placed inside <script>: "</script" would end the element early.
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) text.replace(at, 2, "<\\/");
  return text;
}

}  // namespace

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += two ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

void export_page(const ReplayFolder& folder, const fs::path& page_dir, const fs::path& out) {
  if (!folder.ok) throw ViewError(folder.error);
  std::string html = read_all(page_dir / "index.html");
  const std::string script = read_all(page_dir / "app.js");
  nlohmann::json embed;
  embed["status"] = {{"ok", true}, {"error", ""}, {"report", folder.report.string()}, {"scenario", folder.scenario}};
  embed["files"] = nlohmann::json::object();
  for (const std::string& file : folder.files) embed["files"][file] = base64(read_all(folder.report / file));
  replace_once(html, "<!--MECHSIM_EMBED-->", "<script>window.MECHSIM_EMBED = " + script_safe(embed.dump()) + ";</script>",
               page_dir / "index.html");
  replace_once(html, "<script src=\"app.js\"></script>", "<script>" + script_safe(script) + "</script>", page_dir / "index.html");
  std::ofstream file(out, std::ios::binary);
  file << html;
  file.close();
  if (!file) throw ViewError("cannot write " + out.string());
}

}  // namespace mechsim::web
