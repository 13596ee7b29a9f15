// ROS 2 name resolution and mangling (names.hpp).
#include "ros2/names.hpp"

#include <cctype>

namespace mechsim::ros2 {

namespace {

bool token_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Checks an absolute name ("/", "/a/b"); `what` says what it is in the error.
void check_absolute(const std::string& name, const std::string& what) {
  if (name.empty() || name[0] != '/') throw NameError(what + " '" + name + "' is not absolute");
  if (name.size() > 1 && name.back() == '/') throw NameError(what + " '" + name + "' ends with '/'");
  bool token_start = true;
  for (std::size_t i = 1; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '/') {
      if (token_start) throw NameError(what + " '" + name + "' has an empty token ('//')");
      token_start = true;
      continue;
    }
    if (!token_char(c)) {
      throw NameError(what + " '" + name + "' has the character '" + std::string(1, c) +
                      "' (ROS 2 names hold letters, digits, '_' and '/')");
    }
    if (token_start && std::isdigit(static_cast<unsigned char>(c)) != 0) {
      throw NameError(what + " '" + name + "' has a token starting with a digit");
    }
    token_start = false;
  }
}

}  // namespace

std::string normalize_namespace(const std::string& ns) {
  std::string out = ns.empty() || ns[0] != '/' ? "/" + ns : ns;
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  check_absolute(out, "namespace");
  return out;
}

void check_node_name(const std::string& name) {
  if (name.empty()) throw NameError("empty node name");
  for (char c : name) {
    if (!token_char(c)) throw NameError("node name '" + name + "' has the character '" + std::string(1, c) + "'");
  }
  if (std::isdigit(static_cast<unsigned char>(name[0])) != 0) throw NameError("node name '" + name + "' starts with a digit");
}

std::string expand_topic(const std::string& topic, const std::string& ns, const std::string& name) {
  if (topic.empty()) throw NameError("empty topic name");
  const std::string base = ns == "/" ? "" : ns;
  std::string out;
  if (topic[0] == '/') {
    out = topic;
  } else if (topic == "~") {
    out = base + "/" + name;
  } else if (topic.rfind("~/", 0) == 0) {
    out = base + "/" + name + topic.substr(1);
  } else if (topic[0] == '~') {
    throw NameError("topic '" + topic + "': '~' must be followed by '/'");
  } else {
    out = base + "/" + topic;
  }
  check_absolute(out, "topic");
  return out;
}

std::string resolve_topic(const std::string& topic, const std::string& ns, const std::string& name,
                          const std::vector<Remap>& remaps) {
  const std::string expanded = expand_topic(topic, ns, name);
  for (const Remap& r : remaps) {
    if (expand_topic(r.from, ns, name) == expanded) return expand_topic(r.to, ns, name);
  }
  return expanded;
}

Remap parse_remap(const std::string& rule) {
  const std::size_t sep = rule.find(":=");
  if (sep == std::string::npos || sep == 0 || sep + 2 == rule.size()) {
    throw NameError("remapping '" + rule + "' is not from:=to");
  }
  auto trim = [](std::string s) {
    const auto b = s.find_first_not_of(" \t\n\r");
    const auto e = s.find_last_not_of(" \t\n\r");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
  };
  return {trim(rule.substr(0, sep)), trim(rule.substr(sep + 2))};
}

std::string dds_topic(const std::string& fq_name) { return "rt" + fq_name; }
std::string dds_request_topic(const std::string& fq_name) { return "rq" + fq_name + "Request"; }
std::string dds_reply_topic(const std::string& fq_name) { return "rr" + fq_name + "Reply"; }

std::string ros_topic_of(const std::string& dds_name) {
  auto ends_with = [&](const char* suffix) {
    const std::string s(suffix);
    return dds_name.size() >= s.size() && dds_name.compare(dds_name.size() - s.size(), s.size(), s) == 0;
  };
  if (dds_name.rfind("rt/", 0) == 0) return dds_name.substr(2);
  if (dds_name.rfind("rq/", 0) == 0 && ends_with("Request")) return dds_name.substr(2, dds_name.size() - 2 - 7);
  if (dds_name.rfind("rr/", 0) == 0 && ends_with("Reply")) return dds_name.substr(2, dds_name.size() - 2 - 5);
  return "";
}

}  // namespace mechsim::ros2
