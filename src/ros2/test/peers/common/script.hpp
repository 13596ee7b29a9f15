#pragma once
// A scripted ROS 2 client for the wire tests, the same for the Fast DDS peer (rmw_fastrtps' forms)
// and the Cyclone DDS client (rmw_cyclonedds' forms): each middleware supplies a Backend (service
// clients, readers, writers carrying JSON), the script says what to do, one JSON line per step.
//
// --script '[STEP, ...]', each STEP an object with "op":
//   call       {"service", "type": "pkg/srv/T", "request": {...}, "count": 1, "wait": true,
//              "burst": count, "interval": 0} (count requests, written `burst` at a time back
//              to back, `interval` seconds apart)
//              -> {"available", "sent", "replies", "foreign", "response": the first reply, "ms",
//              "reply_ms": from the first request written to the last reply};
//              "wait": false sends and goes on (a call the client leaves, e.g. to vanish)
//   send_goal  {"action", "type": "pkg/action/A", "goal": {...}, "as": NAME, "result": true}
//              the goal with a fresh UUID; then (result true) its get_result request at once, as
//              rclcpp_action's client does -> {"accepted", "stamp", "ms"}
//   cancel     {"goal": NAME} or {"action", "all": true} -> {"return_code", "canceling": n}
//   result     {"goal": NAME, "timeout": s} waits for the goal's get_result reply (sends the
//              request if none is out) -> {"status", "result", "feedback": count,
//              "last_feedback", "statuses": every status seen for it on <action>/_action/status}
//   take       {"topic", "type", "qos": "tl"|"rel"|"be", "field", "as": VAR, "timeout", "print"} one
//              sample; its field becomes "$VAR" in later requests and goals -> {"got", "length",
//              "value" (with "print": true)}; "reader": NAME takes from a listen's reader instead
//              of a fresh one; "all": true takes every sample until the timeout -> {"got": count,
//              "values"}
//   listen     {"topic", "type", "qos", "as": NAME} a reader kept for later takes (a volatile
//              topic's samples written after it, e.g. /parameter_events)
//   publish    {"topic", "type", "qos", "message"} once matched (kept until the script ends)
//   sleep      {"seconds"}
//   vanish     {} the process ends at once, as a crash: nothing closed, nothing said
//   exit       {} the script ends here and the client closes (its participant deleted, as a ROS 2
//              client stopped with Ctrl-C), whatever it left waiting
// Between steps and while waiting, feedback, status and replies keep being taken.

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace mechsim::ros2::peers {

using json = nlohmann::json;

struct PeerQos {
  bool reliable = true;
  bool transient_local = false;
  int depth = 10;
  static PeerQos parse(const std::string& s) {
    if (s == "tl") return {true, true, 1};
    if (s == "be") return {false, false, 10};
    return {};
  }
};

class ServiceClient {
 public:
  virtual ~ServiceClient() = default;
  virtual bool available() = 0;  // a matched request reader and reply writer
  // The request's id, or nothing when it could not be written.
  virtual std::optional<std::int64_t> send(const json& request) = 0;
  // Replies to this client's requests (others' are counted in foreign).
  virtual std::vector<std::pair<std::int64_t, json>> take() = 0;
  std::uint64_t foreign = 0;
};

class TopicReader {
 public:
  virtual ~TopicReader() = default;
  virtual std::vector<json> take() = 0;
};

class TopicWriter {
 public:
  virtual ~TopicWriter() = default;
  virtual int matched() = 0;
  virtual bool write(const json& message) = 0;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string form() const = 0;  // "rmw_fastrtps", "rmw_cyclonedds"
  // `type`: "pkg/srv/T" or an action's service "pkg/action/A_SendGoal" ("_Request"/"_Response" added).
  virtual std::unique_ptr<ServiceClient> client(const std::string& service, const std::string& type) = 0;
  virtual std::unique_ptr<TopicReader> reader(const std::string& topic, const std::string& type, PeerQos qos) = 0;
  virtual std::unique_ptr<TopicWriter> writer(const std::string& topic, const std::string& type, PeerQos qos) = 0;
};

class Script {
 public:
  explicit Script(Backend& backend) : backend_(backend) {}

  int run(const json& steps) {
    if (!steps.is_array()) {
      std::fprintf(stderr, "--script: a JSON array of steps\n");
      return 2;
    }
    int index = 0;
    for (const json& step : steps) {
      if (step.value("op", "") == "exit") break;
      json out = {{"step", index++}, {"op", step.value("op", "")}, {"form", backend_.form()}};
      const auto t0 = clock::now();
      try {
        run_step(step, out);
      } catch (const std::exception& e) {
        out["error"] = e.what();
      }
      out["ms"] = 1e3 * since(t0);
      std::printf("%s\n", out.dump().c_str());
      std::fflush(stdout);
    }
    return 0;
  }

 private:
  using clock = std::chrono::steady_clock;
  static double since(clock::time_point t) { return std::chrono::duration<double>(clock::now() - t).count(); }

  struct Action {
    std::string name, type;
    std::unique_ptr<ServiceClient> send_goal, cancel, get_result;
    std::unique_ptr<TopicReader> feedback, status;
  };
  struct Goal {
    Action* action = nullptr;
    json uuid;  // 16 numbers
    std::optional<std::int64_t> result_request;
    std::optional<json> result;  // the get_result reply
    int feedback = 0;
    json last_feedback;
    std::vector<int> statuses;
  };

  void run_step(const json& s, json& out) {
    const std::string op = s.value("op", "");
    if (op == "call") call(s, out);
    else if (op == "send_goal") send_goal(s, out);
    else if (op == "cancel") cancel(s, out);
    else if (op == "result") result(s, out);
    else if (op == "take") take(s, out);
    else if (op == "listen")
      readers_[s.value("as", "reader")] = backend_.reader(s.at("topic"), s.at("type"), PeerQos::parse(s.value("qos", "rel")));
    else if (op == "publish") publish(s, out);
    else if (op == "sleep") pump_for(s.value("seconds", 1.0));
    else if (op == "vanish") {
      std::fflush(stdout);
      _exit(0);
    } else {
      throw std::runtime_error("unknown op '" + op + "'");
    }
  }

  // "$VAR" strings replaced by what take stored.
  json substitute(const json& v) const {
    if (v.is_string()) {
      const std::string s = v.get<std::string>();
      if (s.size() > 1 && s[0] == '$') {
        const auto it = vars_.find(s.substr(1));
        if (it != vars_.end()) return it->second;
      }
      return v;
    }
    if (v.is_object() || v.is_array()) {
      json out = v;
      for (auto it = out.begin(); it != out.end(); ++it) *it = substitute(*it);
      return out;
    }
    return v;
  }

  bool wait_available(ServiceClient& c, double seconds) {
    const auto t0 = clock::now();
    while (!c.available()) {
      if (since(t0) > seconds) return false;
      pump();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  }

  void call(const json& s, json& out) {
    const std::string service = s.at("service");
    out["service"] = service;
    auto c = backend_.client(service, s.at("type"));
    const bool available = wait_available(*c, 10.0);
    out["available"] = available;
    const int count = s.value("count", 1);
    const int burst = s.value("burst", count);  // requests written back to back,
    const double interval = s.value("interval", 0.0);  // then this long taking replies
    const json request = substitute(s.value("request", json::object()));
    std::vector<std::int64_t> sent;
    std::map<std::int64_t, bool> got;
    int replies = 0;
    json first;
    auto collect = [&] {
      for (auto& [id, reply] : c->take()) {
        const auto it = got.find(id);
        if (it == got.end() || it->second) continue;
        it->second = true;
        if (replies++ == 0) first = reply;
      }
      pump();
    };
    const auto t0 = clock::now();  // the replies' time, discovery not counted
    for (int i = 0; available && i < count; ++i) {
      if (i > 0 && burst > 0 && i % burst == 0) {
        const auto b0 = clock::now();
        while (since(b0) < interval) {
          collect();
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
      }
      if (auto id = c->send(request)) {
        sent.push_back(*id);
        got[*id] = false;
      }
    }
    if (!s.value("wait", true)) {
      out["sent"] = sent.size();
      left_.push_back(std::move(c));  // its endpoints stay: the call is still out
      return;
    }
    while (replies < static_cast<int>(sent.size()) && since(t0) < s.value("timeout", 30.0)) {
      collect();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    out["sent"] = sent.size();
    out["replies"] = replies;
    out["reply_ms"] = 1e3 * since(t0);
    out["foreign"] = c->foreign;
    out["response"] = first;
  }

  Action& action(const std::string& name, const std::string& type) {
    for (auto& a : actions_)
      if (a->name == name) return *a;
    auto a = std::make_unique<Action>();
    a->name = name;
    a->type = type;
    a->send_goal = backend_.client(name + "/_action/send_goal", type + "_SendGoal");
    a->cancel = backend_.client(name + "/_action/cancel_goal", "action_msgs/srv/CancelGoal");
    a->get_result = backend_.client(name + "/_action/get_result", type + "_GetResult");
    // rcl_action's client: feedback as rmw's default, status reliable + transient local, keep last 1.
    a->feedback = backend_.reader(name + "/_action/feedback", type + "_FeedbackMessage", PeerQos{});
    a->status = backend_.reader(name + "/_action/status", "action_msgs/GoalStatusArray", PeerQos{true, true, 1});
    actions_.push_back(std::move(a));
    return *actions_.back();
  }

  Goal& goal(const std::string& name) {
    const auto it = goals_.find(name);
    if (it == goals_.end()) throw std::runtime_error("no goal named '" + name + "'");
    return it->second;
  }

  // One reply of `c` to `id` (others kept for the pump), at most `seconds`.
  std::optional<json> wait_reply(ServiceClient& c, std::int64_t id, double seconds) {
    const auto t0 = clock::now();
    while (since(t0) < seconds) {
      for (auto& [rid, reply] : c.take()) {
        if (rid == id) return reply;
        stray_[&c].emplace_back(rid, reply);
      }
      pump();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return std::nullopt;
  }

  void send_goal(const json& s, json& out) {
    Action& a = action(s.at("action"), s.at("type"));
    out["action"] = a.name;
    const std::string name = s.value("as", "goal" + std::to_string(goals_.size()));
    out["goal"] = name;
    const bool available = wait_available(*a.send_goal, 10.0) && wait_available(*a.cancel, 10.0) &&
                           wait_available(*a.get_result, 10.0);
    out["available"] = available;
    if (!available) return;
    Goal& g = goals_[name];
    g.action = &a;
    g.uuid = json::array();
    for (int i = 0; i < 16; ++i) g.uuid.push_back(static_cast<unsigned>(random_() & 0xff));
    const json request = {{"goal_id", {{"uuid", g.uuid}}}, {"goal", substitute(s.value("goal", json::object()))}};
    const auto id = a.send_goal->send(request);
    if (!id) throw std::runtime_error("the goal request could not be written");
    const std::optional<json> reply = wait_reply(*a.send_goal, *id, s.value("timeout", 10.0));
    out["replied"] = reply.has_value();
    if (!reply) return;
    out["accepted"] = (*reply)["accepted"];
    out["stamp"] = (*reply)["stamp"];
    if ((*reply)["accepted"].get<bool>() && s.value("result", true)) request_result(g);
  }

  void request_result(Goal& g) {
    g.result_request = g.action->get_result->send({{"goal_id", {{"uuid", g.uuid}}}});
  }

  void cancel(const json& s, json& out) {
    json request = {{"goal_info", {{"goal_id", {{"uuid", json::array()}}}, {"stamp", {{"sec", 0}, {"nanosec", 0}}}}}};
    Action* a = nullptr;
    if (s.contains("goal")) {
      Goal& g = goal(s["goal"]);
      a = g.action;
      request["goal_info"]["goal_id"]["uuid"] = g.uuid;
    } else {
      a = &action(s.at("action"), s.at("type"));
      if (!wait_available(*a->cancel, 10.0)) throw std::runtime_error("cancel_goal is not available");
    }
    const auto id = a->cancel->send(request);
    if (!id) throw std::runtime_error("the cancel request could not be written");
    const std::optional<json> reply = wait_reply(*a->cancel, *id, s.value("timeout", 10.0));
    out["replied"] = reply.has_value();
    if (!reply) return;
    out["return_code"] = (*reply)["return_code"];
    out["canceling"] = (*reply)["goals_canceling"].size();
  }

  void result(const json& s, json& out) {
    const std::string name = s.at("goal");
    Goal& g = goal(name);
    out["goal"] = name;
    if (!g.result_request && !g.result) request_result(g);
    const auto t0 = clock::now();
    while (!g.result && since(t0) < s.value("timeout", 30.0)) {
      pump();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    pump();
    out["replied"] = g.result.has_value();
    if (g.result) {
      out["status"] = (*g.result)["status"];
      out["result"] = (*g.result)["result"];
    }
    out["feedback"] = g.feedback;
    out["last_feedback"] = g.last_feedback;
    out["statuses"] = g.statuses;
  }

  void take(const json& s, json& out) {
    std::unique_ptr<TopicReader> fresh;
    TopicReader* r = nullptr;
    if (s.contains("reader")) {
      const auto it = readers_.find(s["reader"].get<std::string>());
      if (it == readers_.end()) throw std::runtime_error("no reader named " + s["reader"].dump());
      r = it->second.get();
    } else {
      fresh = backend_.reader(s.at("topic"), s.at("type"), PeerQos::parse(s.value("qos", "rel")));
      r = fresh.get();
    }
    const auto t0 = clock::now();
    if (s.value("all", false)) {
      out["values"] = json::array();
      while (since(t0) < s.value("timeout", 1.0)) {
        for (const json& m : r->take()) out["values"].push_back(s.contains("field") ? m[s["field"].get<std::string>()] : m);
        pump();
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
      out["got"] = out["values"].size();
      return;
    }
    out["got"] = false;
    while (since(t0) < s.value("timeout", 10.0)) {
      for (const json& m : r->take()) {
        const json v = s.contains("field") ? m[s["field"].get<std::string>()] : m;
        vars_[s.value("as", "value")] = v;
        out["got"] = true;
        out["length"] = v.is_string() ? v.get<std::string>().size() : v.dump().size();
        if (s.value("print", false)) out["value"] = v;
        return;
      }
      pump();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  void publish(const json& s, json& out) {
    auto w = backend_.writer(s.at("topic"), s.at("type"), PeerQos::parse(s.value("qos", "rel")));
    // A transient-local writer keeps the sample for late readers; a volatile one waits for one.
    const bool tl = s.value("qos", "rel") == "tl";
    const auto t0 = clock::now();
    while (!tl && w->matched() == 0 && since(t0) < 10.0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    out["written"] = w->write(substitute(s.at("message")));
    writers_.push_back(std::move(w));
  }

  void pump_for(double seconds) {
    const auto t0 = clock::now();
    while (since(t0) < seconds) {
      pump();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  // Feedback, status and get_result replies of every action.
  void pump() {
    for (auto& a : actions_) {
      for (const json& m : a->feedback->take()) {
        for (auto& [name, g] : goals_) {
          if (g.action != a.get() || m["goal_id"]["uuid"] != g.uuid) continue;
          ++g.feedback;
          g.last_feedback = m["feedback"];
        }
      }
      for (const json& m : a->status->take()) {
        for (const json& st : m["status_list"]) {
          for (auto& [name, g] : goals_) {
            if (g.action != a.get() || st["goal_info"]["goal_id"]["uuid"] != g.uuid) continue;
            const int v = st["status"].get<int>();
            if (g.statuses.empty() || g.statuses.back() != v) g.statuses.push_back(v);
          }
        }
      }
      std::vector<std::pair<std::int64_t, json>> replies = a->get_result->take();
      auto& stray = stray_[a->get_result.get()];
      replies.insert(replies.end(), stray.begin(), stray.end());
      stray.clear();
      for (auto& [id, reply] : replies) {
        for (auto& [name, g] : goals_)
          if (g.action == a.get() && g.result_request && *g.result_request == id) g.result = reply;
      }
    }
  }

  Backend& backend_;
  std::mt19937_64 random_{std::random_device{}()};
  std::vector<std::unique_ptr<Action>> actions_;
  std::map<std::string, Goal> goals_;
  std::map<std::string, json> vars_;
  std::map<ServiceClient*, std::vector<std::pair<std::int64_t, json>>> stray_;
  std::vector<std::unique_ptr<TopicWriter>> writers_;
  std::map<std::string, std::unique_ptr<TopicReader>> readers_;  // listen's
  std::vector<std::unique_ptr<ServiceClient>> left_;  // calls not waited for
};

}  // namespace mechsim::ros2::peers
