#pragma once
// A ROS 2 action server over a controller's goal port (issue 37), speaking the action protocol
// rcl_action and rclcpp_action speak, to clients of both default middlewares:
//
//   <action>/_action/send_goal    <Action>_SendGoal {goal_id, goal} -> {accepted, stamp}
//   <action>/_action/cancel_goal  action_msgs/srv/CancelGoal (rcl_action's cancel policy below)
//   <action>/_action/get_result   <Action>_GetResult {goal_id} -> {status, result}; answered when
//                                 the goal ends (at once for an ended or unknown one)
//   <action>/_action/feedback     <Action>_FeedbackMessage {goal_id, feedback}
//   <action>/_action/status       action_msgs/msg/GoalStatusArray, every goal held, on each change
//
// Services use ServiceServer (service.hpp: rmw_fastrtps' and rmw_cyclonedds' request forms);
// QoS as rcl_action_server_get_default_options: services default, feedback rmw default,
// status reliable + transient local + keep last 1.
//
// Goals are keyed by their unique_identifier_msgs/UUID. A goal the port takes is accepted and
// EXECUTING at once (ros2_controllers accept and execute); one it refuses is rejected (accepted
// false; rclcpp_action keeps no record of it); a UUID already held is rejected. A newer goal the
// port takes preempts the active one (the port says so; the Policy says what result that gives).
// A goal ends as the port reports it (Succeeded -> SUCCEEDED, Preempted -> CANCELED, Aborted and
// Rejected -> ABORTED) on the next poll (ActionPoller: 20 Hz of wall time, ros2_controllers'
// action_monitor_rate), when the fresh feedback of the port's goal is published too.
//
// cancel_goal, as rcl_action_process_cancel_request: a goal id and a zero stamp cancel that goal
// (ERROR_UNKNOWN_GOAL_ID when unknown, ERROR_GOAL_TERMINATED when it has ended); a zero id and a
// zero stamp cancel every goal; a stamp cancels the goals accepted at or before it (and the
// goal id's). A canceled goal is CANCELING until the port reports it ended.
//
// An ended goal's result is kept `result_timeout` seconds of simulated time (rcl_action's
// result_timeout: 15 min in Humble, 10 s from Iron on), at most kMaxEnded goals (the oldest go
// first). A get_result request waiting for a goal is dropped as soon as its client is gone (its
// reply reader no longer matched: the client process ended or crashed), counted in stats(); the
// goal itself runs on, as rclcpp_action lets it. So a client vanishing mid-action leaves nothing
// behind once its goal ends and expires.
//
// Threads: requests arrive on Fast DDS's receive threads, poll() runs on the poller's thread;
// one mutex guards the goals; replies (which may wait up to 100 ms for a client's reader to
// match) are never sent under it. shutdown() (the controller is unloading) ends every held goal
// as the Policy says (ros2_controllers: CANCELED on deactivation) and never touches the port
// again.
//
// The Policy speaks one action over one kind of goal port (actions.cpp):
//   using Goal, Result, Feedback, SendGoal, GetResult, FeedbackMessage;   // generated types
//   struct Submission { bool accepted; std::uint64_t id; std::string why; };
//   Submission submit(const bridge::PortRef&, const Goal&);
//   bool cancel(const bridge::PortRef&, std::uint64_t id);
//   std::optional<control::GoalStatus> status(const bridge::PortRef&, std::uint64_t id);
//   Result result(const bridge::PortRef&, std::uint64_t id, control::GoalStatus, GoalEnding);
//   static Result shutdown_result();           // a goal ended by shutdown()
//   bool read_feedback(const bridge::PortRef&, std::uint64_t& goal_id, Feedback& out);  // fresh?

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <mechsim_ros2_msgs/action_msgs.hpp>
#include <mechsim_ros2_msgs/unique_identifier_msgs.hpp>

#include "bridge/sim_bridge.hpp"
#include "ros2/conversions.hpp"
#include "ros2/node.hpp"
#include "ros2/qos.hpp"
#include "ros2/service.hpp"

namespace mechsim::ros2 {

// Why a goal the port reports as Preempted ended, as far as the server knows.
enum class GoalEnding : std::uint8_t {
  Reported,         // the port's own reason (a plain command, the controller stopped)
  CancelRequested,  // a cancel_goal request canceled it
  Superseded,       // a newer goal of this server took over
};

// What every action server counts (logs, tests).
struct ActionStats {
  std::uint64_t accepted = 0, rejected = 0, succeeded = 0, canceled = 0, aborted = 0;
  std::uint64_t results_sent = 0;
  std::uint64_t results_dropped = 0;  // get_result requests whose client was gone
  std::size_t goals_held = 0;         // goals not expired yet (active or ended)
  std::size_t results_waiting = 0;    // get_result requests waiting for their goal
  ActionStats& operator+=(const ActionStats& o) {  // several servers' (a model's, the world's)
    accepted += o.accepted;
    rejected += o.rejected;
    succeeded += o.succeeded;
    canceled += o.canceled;
    aborted += o.aborted;
    results_sent += o.results_sent;
    results_dropped += o.results_dropped;
    goals_held += o.goals_held;
    results_waiting += o.results_waiting;
    return *this;
  }
};

// What the poller polls.
class Pollable {
 public:
  virtual ~Pollable() = default;
  virtual void poll() = 0;
};

// A thread that polls every registered server at `rate` Hz of wall time. remove() returns once
// the server is no longer polled (it waits for a poll in progress): after it, the poller holds
// no reference to it.
class ActionPoller {
 public:
  explicit ActionPoller(double rate = 20.0) : period_(1.0 / rate), thread_([this] { run(); }) {}
  ~ActionPoller() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  ActionPoller(const ActionPoller&) = delete;
  ActionPoller& operator=(const ActionPoller&) = delete;

  void add(std::shared_ptr<Pollable> p) {
    std::lock_guard<std::mutex> lock(mutex_);
    polled_.push_back(std::move(p));
  }
  // Not from a poll (the poller's own thread).
  void remove(const Pollable* p) {
    std::unique_lock<std::mutex> lock(mutex_);
    std::erase_if(polled_, [p](const std::shared_ptr<Pollable>& q) { return q.get() == p; });
    idle_.wait(lock, [this] { return !polling_; });
  }

 private:
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
      std::vector<std::shared_ptr<Pollable>> now = polled_;
      polling_ = true;
      lock.unlock();
      for (const auto& p : now) p->poll();
      now.clear();
      lock.lock();
      polling_ = false;
      idle_.notify_all();
      wake_.wait_for(lock, std::chrono::duration<double>(period_), [this] { return stop_; });
    }
  }

  double period_;
  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::vector<std::shared_ptr<Pollable>> polled_;
  bool polling_ = false;
  bool stop_ = false;
  std::thread thread_;  // last: starts once the rest exists
};

using GoalUuid = std::array<std::uint8_t, 16>;
// "0123abcd-..." as rclcpp_action prints a goal id.
std::string uuid_string(const GoalUuid& uuid);

template <class Policy>
class ActionServer : public Pollable {
 public:
  using Goal = typename Policy::Goal;
  using Result = typename Policy::Result;
  using Feedback = typename Policy::Feedback;
  using SendGoal = typename Policy::SendGoal;
  using GetResult = typename Policy::GetResult;
  using FeedbackMessage = typename Policy::FeedbackMessage;
  using CancelGoal = action_msgs::srv::CancelGoal;
  using Status = action_msgs::msg::GoalStatus;
  static constexpr std::size_t kMaxEnded = 100;          // ended goals kept at most
  static constexpr std::size_t kMaxWaiting = 64;         // get_result requests per goal

  // Serves `name` (resolved in `node`) over `port`; `now` is the simulated time (s). Throws
  // NameError or std::runtime_error when the endpoints cannot be made.
  ActionServer(Node& node, const std::string& name, bridge::PortRef port, std::function<double()> now,
               double result_timeout, Policy policy = Policy())
      : node_(node), name_(node.resolve(name)), port_(std::move(port)), now_(std::move(now)),
        result_timeout_(result_timeout), policy_(std::move(policy)) {
    const std::string base = name_ + "/_action/";
    status_pub_ = node.create_publisher<action_msgs::msg::GoalStatusArray>(base + "status", Qos::latched());
    feedback_pub_ = node.create_publisher<FeedbackMessage>(base + "feedback", Qos::defaults());
    // The goal and cancel responses go out before the status they change, as rclcpp_action
    // sends them (a client ignores the status of a goal it has not heard of yet).
    send_goal_ = std::make_unique<ServiceServer<SendGoal>>(
        node, base + "send_goal",
        typename ServiceServer<SendGoal>::DeferredHandler([this](const typename SendGoal::Request& q, const ReplyTo& to) {
          if (!ready_.load()) return;  // a request before the constructor ended: the client asks again
          typename SendGoal::Response a;
          const bool changed = on_send_goal(q, a);
          send_goal_->reply(to, a);
          if (changed) publish_status();
        }));
    cancel_goal_ = std::make_unique<ServiceServer<CancelGoal>>(
        node, base + "cancel_goal",
        typename ServiceServer<CancelGoal>::DeferredHandler([this](const CancelGoal::Request& q, const ReplyTo& to) {
          if (!ready_.load()) return;
          CancelGoal::Response a;
          on_cancel(q, a);
          cancel_goal_->reply(to, a);
          if (!a.goals_canceling.empty()) publish_status();
        }));
    get_result_ = std::make_unique<ServiceServer<GetResult>>(
        node, base + "get_result",
        typename ServiceServer<GetResult>::DeferredHandler(
            [this](const typename GetResult::Request& q, const ReplyTo& to) {
              if (ready_.load()) on_get_result(q, to);
            }));
    publish_status();  // an empty list: a late client learns there is nothing
    ready_.store(true);
  }
  ~ActionServer() override { shutdown("the action server is going"); }
  ActionServer(const ActionServer&) = delete;
  ActionServer& operator=(const ActionServer&) = delete;

  const std::string& name() const { return name_; }

  // Ends every held goal (CANCELED with the Policy's shutdown result), answers their waiting
  // get_result requests; the port is never touched again. Idempotent.
  void shutdown(const std::string& why) {
    std::vector<std::pair<ReplyTo, typename GetResult::Response>> replies;
    bool changed = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!alive_) return;
      alive_ = false;
      for (Record& r : goals_) {
        if (ended(r.status)) continue;
        r.status = Status::STATUS_CANCELED;
        r.result = Policy::shutdown_result();
        r.ended_at = now_();
        ++stats_.canceled;
        changed = true;
        for (const Waiter& w : r.waiting) replies.emplace_back(w.to, response_of(r));
        r.waiting.clear();
      }
      if (changed) node_.participant().log(name_ + ": goals canceled: " + why);
    }
    if (changed) publish_status();
    send_results(replies);
  }

  ActionStats stats() const {
    std::lock_guard<std::mutex> lock(mutex_);
    ActionStats s = stats_;
    s.goals_held = goals_.size();
    s.results_waiting = 0;
    for (const Record& r : goals_) s.results_waiting += r.waiting.size();
    return s;
  }
  std::uint64_t replies_dropped() const {
    return send_goal_->dropped() + cancel_goal_->dropped() + get_result_->dropped();
  }

  // The poller's thread: what the port reports, feedback, vanished clients, expiry.
  void poll() override {
    std::vector<std::pair<ReplyTo, typename GetResult::Response>> replies;
    std::optional<FeedbackMessage> feedback;
    bool changed = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!alive_) return;
      const double now = now_();
      // Fresh feedback about the port's goal, while it runs (and once as it ends, before its
      // result, so a goal shorter than the poll period still gets one).
      std::uint64_t feedback_goal = 0;
      Feedback fb;
      const bool fresh = policy_.read_feedback(port_, feedback_goal, fb);
      for (Record& r : goals_) {
        if (ended(r.status)) continue;
        if (fresh && feedback_goal == r.port_id) {
          feedback.emplace();
          feedback->goal_id.uuid = r.uuid;
          feedback->feedback = std::move(fb);
        }
        const std::optional<control::GoalStatus> s = policy_.status(port_, r.port_id);
        if (!s || !control::goal_finished(*s)) continue;
        const GoalEnding ending = r.status == Status::STATUS_CANCELING ? GoalEnding::CancelRequested
                                  : r.superseded                      ? GoalEnding::Superseded
                                                                      : GoalEnding::Reported;
        r.result = policy_.result(port_, r.port_id, *s, ending);
        r.status = *s == control::GoalStatus::Succeeded   ? Status::STATUS_SUCCEEDED
                   : *s == control::GoalStatus::Preempted ? Status::STATUS_CANCELED
                                                          : Status::STATUS_ABORTED;
        ++(r.status == Status::STATUS_SUCCEEDED  ? stats_.succeeded
           : r.status == Status::STATUS_CANCELED ? stats_.canceled
                                                 : stats_.aborted);
        r.ended_at = now;
        changed = true;
        for (const Waiter& w : r.waiting) replies.emplace_back(w.to, response_of(r));
        r.waiting.clear();
      }
      // get_result requests whose client is gone: dropped now, not when the goal ends.
      for (Record& r : goals_) {
        const std::size_t before = r.waiting.size();
        const auto wall = std::chrono::steady_clock::now();
        std::erase_if(r.waiting, [&](Waiter& w) {
          const bool alive = get_result_->client_alive(w.to);
          w.seen = w.seen || alive;
          return !alive && (w.seen || wall - w.since > kMatchGrace);
        });
        if (r.waiting.size() != before) {
          stats_.results_dropped += before - r.waiting.size();
          node_.participant().log(name_ + ": goal " + uuid_string(r.uuid) + ": " + std::to_string(before - r.waiting.size()) +
                                  " get_result request(s) dropped: the client is gone");
        }
      }
      // Expiry (rcl_action_expire_goals): ended goals older than result_timeout; a world reset
      // (time going back) restarts their clock.
      std::size_t ended_count = 0;
      for (Record& r : goals_) {
        if (!ended(r.status)) continue;
        if (now < r.ended_at) r.ended_at = now;
        ++ended_count;
      }
      std::erase_if(goals_, [&](const Record& r) {
        const bool expire = ended(r.status) && (now - r.ended_at > result_timeout_ || ended_count > kMaxEnded);
        if (expire) --ended_count;
        return expire;
      });
    }
    if (feedback && feedback_pub_->matched() > 0) feedback_pub_->publish(*feedback);
    if (changed) publish_status();  // then the results, as rclcpp_action
    send_results(replies);
  }

 private:
  // A get_result request waiting for its goal. Its client counts as gone once its reply reader,
  // matched before, is not any more (or was never matched within kMatchGrace: a request can come
  // before the server's reply writer has matched the client's reader).
  struct Waiter {
    ReplyTo to;
    std::chrono::steady_clock::time_point since = std::chrono::steady_clock::now();
    bool seen = false;  // its reader was matched once
  };
  static constexpr std::chrono::seconds kMatchGrace{5};
  struct Record {
    GoalUuid uuid{};
    std::uint64_t port_id = 0;
    std::int8_t status = Status::STATUS_EXECUTING;
    builtin_interfaces::msg::Time stamp;  // accepted at (simulated time)
    bool superseded = false;              // a newer goal was accepted after it
    Result result;
    double ended_at = 0.0;
    std::vector<Waiter> waiting;  // get_result requests
  };
  static bool ended(std::int8_t s) {
    return s == Status::STATUS_SUCCEEDED || s == Status::STATUS_CANCELED || s == Status::STATUS_ABORTED;
  }
  static bool zero(const GoalUuid& u) {
    return std::all_of(u.begin(), u.end(), [](std::uint8_t b) { return b == 0; });
  }
  static typename GetResult::Response response_of(const Record& r) {
    typename GetResult::Response a;
    a.status = r.status;
    a.result = r.result;
    return a;
  }
  Record* find(const GoalUuid& uuid) {
    for (Record& r : goals_)
      if (r.uuid == uuid) return &r;
    return nullptr;
  }

  // True when the goal was accepted (the status changed).
  bool on_send_goal(const typename SendGoal::Request& q, typename SendGoal::Response& a) {
    std::lock_guard<std::mutex> lock(mutex_);
    const double now = now_();
    a.stamp = to_time(now);
    a.accepted = false;
    const std::string id = uuid_string(q.goal_id.uuid);
    if (!alive_) {
      ++stats_.rejected;
      node_.participant().log(name_ + ": goal " + id + " rejected: the controller is being unloaded");
      return false;
    }
    if (find(q.goal_id.uuid) != nullptr) {
      ++stats_.rejected;
      node_.participant().log(name_ + ": goal " + id + " rejected: goal ID already exists");
      return false;
    }
    const typename Policy::Submission s = policy_.submit(port_, q.goal);
    if (!s.accepted) {
      ++stats_.rejected;
      node_.participant().log(name_ + ": goal " + id + " rejected: " + s.why);
      return false;
    }
    for (Record& r : goals_)
      if (!ended(r.status)) r.superseded = true;  // the port preempts it
    Record& r = goals_.emplace_back();
    r.uuid = q.goal_id.uuid;
    r.port_id = s.id;
    r.stamp = a.stamp;
    a.accepted = true;
    ++stats_.accepted;
    return true;
  }

  void on_cancel(const CancelGoal::Request& q, CancelGoal::Response& a) {
    std::lock_guard<std::mutex> lock(mutex_);
    const GoalUuid& uuid = q.goal_info.goal_id.uuid;
    const std::int64_t stamp = std::int64_t{q.goal_info.stamp.sec} * 1000000000 + q.goal_info.stamp.nanosec;
    auto cancelable = [](const Record& r) { return r.status == Status::STATUS_ACCEPTED || r.status == Status::STATUS_EXECUTING; };
    auto nanos = [](const builtin_interfaces::msg::Time& t) { return std::int64_t{t.sec} * 1000000000 + t.nanosec; };
    std::vector<Record*> chosen;
    a.return_code = CancelGoal::Response::ERROR_NONE;
    if (!zero(uuid) && stamp == 0) {
      Record* r = find(uuid);
      if (r == nullptr) a.return_code = CancelGoal::Response::ERROR_UNKNOWN_GOAL_ID;
      else if (!cancelable(*r)) a.return_code = CancelGoal::Response::ERROR_GOAL_TERMINATED;
      else chosen.push_back(r);
    } else {
      const std::int64_t before = zero(uuid) && stamp == 0 ? INT64_MAX : stamp;
      for (Record& r : goals_)
        if (cancelable(r) && (nanos(r.stamp) <= before || r.uuid == uuid)) chosen.push_back(&r);
    }
    for (Record* r : chosen) {
      // ros2_controllers accept every cancel; a goal the port no longer knows as running ends on
      // the next poll anyway.
      if (alive_) policy_.cancel(port_, r->port_id);
      r->status = Status::STATUS_CANCELING;
      action_msgs::msg::GoalInfo& info = a.goals_canceling.emplace_back();
      info.goal_id.uuid = r->uuid;
      info.stamp = r->stamp;
    }
  }

  void on_get_result(const typename GetResult::Request& q, const ReplyTo& to) {
    typename GetResult::Response a;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      Record* r = find(q.goal_id.uuid);
      if (r != nullptr && !ended(r->status)) {
        if (r->waiting.size() >= kMaxWaiting) {
          node_.participant().log(name_ + ": goal " + uuid_string(r->uuid) + ": more than " + std::to_string(kMaxWaiting) +
                                  " get_result requests waiting; this one is refused (STATUS_UNKNOWN)");
        } else {
          r->waiting.push_back({to});
          return;
        }
      } else if (r != nullptr) {
        a = response_of(*r);
      } else {
        a.status = Status::STATUS_UNKNOWN;  // rclcpp_action: an unknown goal's result
      }
    }
    if (get_result_->reply(to, a)) {
      std::lock_guard<std::mutex> lock(mutex_);
      ++stats_.results_sent;
    }
  }

  void send_results(const std::vector<std::pair<ReplyTo, typename GetResult::Response>>& replies) {
    for (const auto& [to, response] : replies) {
      const bool sent = get_result_->reply(to, response);
      std::lock_guard<std::mutex> lock(mutex_);
      ++(sent ? stats_.results_sent : stats_.results_dropped);
    }
  }

  // The goals as they are now. Snapshots are taken and written in order (publish_mutex_), so the
  // last status a late subscriber gets (transient local, keep last 1) is the newest.
  void publish_status() {
    std::lock_guard<std::mutex> order(publish_mutex_);
    action_msgs::msg::GoalStatusArray array;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const Record& r : goals_) {
        Status& s = array.status_list.emplace_back();
        s.goal_info.goal_id.uuid = r.uuid;
        s.goal_info.stamp = r.stamp;
        s.status = r.status;
      }
    }
    status_pub_->publish(array);
  }

  Node& node_;
  std::string name_;
  bridge::PortRef port_;
  std::function<double()> now_;
  double result_timeout_;
  std::atomic<bool> ready_{false};  // the constructor ended (the service pointers are set)
  std::mutex publish_mutex_;        // taken before mutex_
  mutable std::mutex mutex_;
  bool alive_ = true;        // under mutex_
  std::vector<Record> goals_;  // under mutex_, in acceptance order
  ActionStats stats_;          // under mutex_
  Policy policy_;              // under mutex_
  std::unique_ptr<Publisher<action_msgs::msg::GoalStatusArray>> status_pub_;
  std::unique_ptr<Publisher<FeedbackMessage>> feedback_pub_;
  std::unique_ptr<ServiceServer<SendGoal>> send_goal_;
  std::unique_ptr<ServiceServer<CancelGoal>> cancel_goal_;
  std::unique_ptr<ServiceServer<GetResult>> get_result_;
};

}  // namespace mechsim::ros2
