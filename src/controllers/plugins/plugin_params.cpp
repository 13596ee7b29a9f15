#include "controllers/plugins/plugin_params.hpp"

#include <cmath>
#include <optional>

namespace mechsim::control {
namespace {

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return {};
  const auto b = s.find_last_not_of(" \t\r\n");
  return s.substr(a, b - a + 1);
}

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

std::string PluginParams::location(const char* key) const {
  if (auto p = params_.find(key)) {
    if (std::string l = p->location(); !l.empty()) return l;
  }
  return params_.location();
}

void PluginParams::fail(const char* key, const std::string& what) const {
  const std::string where = location(key);
  throw ControllerConfigError((where.empty() ? std::string() : where + ": ") + "<" + key + "> " + what);
}

std::string PluginParams::text(const char* key, const std::string& fallback) const {
  auto p = params_.find(key);
  if (!p) return fallback;
  if (!p->is_scalar()) fail(key, "must hold text, not elements");
  return trimmed(p->as<std::string>());
}

double PluginParams::number(const char* key, double fallback) const {
  if (!has(key)) return fallback;
  const std::string t = text(key, "");
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || end == nullptr || *end != '\0') fail(key, "is not a number: \"" + t + "\"");
  if (!std::isfinite(v)) fail(key, "must be finite (got " + t + ")");
  return v;
}

double PluginParams::positive(const char* key, double fallback) const {
  const double v = number(key, fallback);
  if (!(v > 0.0)) fail(key, "must be > 0 (got " + format(v) + ")");
  return v;
}

double PluginParams::non_negative(const char* key, double fallback) const {
  const double v = number(key, fallback);
  if (!(v >= 0.0)) fail(key, "must be >= 0 (got " + format(v) + ")");
  return v;
}

double PluginParams::rate(const char* key, double fallback) const {
  const double v = number(key, fallback);
  if (v < 0.0) fail(key, "is a rate in Hz and must be >= 0 (0: every step); got " + format(v));
  return v;
}

bool PluginParams::boolean(const char* key, bool fallback) const {
  if (!has(key)) return fallback;
  const std::string t = text(key, "");
  if (t == "true" || t == "1") return true;
  if (t == "false" || t == "0") return false;
  fail(key, "is not a boolean (true, false, 1 or 0): \"" + t + "\"");
}

std::string PluginParams::joint(const char* key, const std::string& fallback) const {
  const std::string j = text(key, fallback);
  if (j.empty()) fail(key, "names no joint");
  return j;
}

std::string PluginParams::required(const char* key) const {
  if (!has(key)) {
    const std::string where = params_.location();
    throw ControllerConfigError((where.empty() ? std::string() : where + ": ") + "<" + key + "> is missing (required)");
  }
  const std::string t = text(key, "");
  if (t.empty()) fail(key, "is empty");
  return t;
}

}  // namespace mechsim::control
