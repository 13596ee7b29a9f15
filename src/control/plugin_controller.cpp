#include "control/plugin_controller.hpp"

#include <deque>
#include <optional>
#include <stdexcept>

namespace mechsim::control {

namespace api = controller_api;

namespace {

class ApiJoint final : public api::Joint {
 public:
  explicit ApiJoint(JointHandle handle) : handle_(handle) {}
  const std::string& name() const noexcept override { return handle_.name(); }
  double position() const noexcept override { return handle_.position(); }
  double velocity() const noexcept override { return handle_.velocity(); }
  double effort() const noexcept override { return handle_.effort(); }
  void set_command(double value) noexcept override { handle_.set_command(value); }
  double command() const noexcept override { return handle_.command(); }

 private:
  JointHandle handle_;
};

class ApiCommandInput final : public api::CommandInput {
 public:
  explicit ApiCommandInput(ScalarCommandPort& port) : port_(port) {}
  double read() noexcept override { return port_.read_from_rt(); }
  void reset(double value) noexcept override { port_.reset_from_rt(value); }

 private:
  ScalarCommandPort& port_;
};

class ApiStateOutput final : public api::StateOutput {
 public:
  explicit ApiStateOutput(StatePort<JointControllerState>& port) : port_(port) {}
  void publish(double time, double period, const api::ControllerState& in) noexcept override {
    port_.publish_from_rt([&](JointControllerState& s) {
      s.stamp = time;
      s.time_step = period;
      s.set_point = in.set_point;
      s.process_value = in.process_value;
      s.process_value_dot = in.process_value_dot;
      s.error = in.error;
      s.command = in.command;
    });
  }

 private:
  StatePort<JointControllerState>& port_;
};

// ParamsError is a std::runtime_error naming the path (and file:line): it reaches the plugin's
// caller, the manager, unchanged.
class ApiParameters final : public api::Parameters {
 public:
  explicit ApiParameters(const Params& params) : params_(params) {}
  const std::string& path() const noexcept override { return params_.path(); }
  bool has(const std::string& key) const override { return params_.has(key); }
  double get_double(const std::string& key) const override { return params_.get<double>(key); }
  double get_double_or(const std::string& key, double fallback) const override { return params_.get<double>(key, fallback); }
  std::int64_t get_int_or(const std::string& key, std::int64_t fallback) const override {
    return params_.has(key) ? params_.get<int>(key) : fallback;
  }
  bool get_bool_or(const std::string& key, bool fallback) const override { return params_.get<bool>(key, fallback); }
  std::string get_string(const std::string& key) const override { return params_.get<std::string>(key); }
  std::string get_string_or(const std::string& key, const std::string& fallback) const override {
    return params_.get<std::string>(key, fallback);
  }
  std::vector<std::string> get_string_list(const std::string& key) const override {
    return params_.get<std::vector<std::string>>(key);
  }
  std::vector<double> get_double_list(const std::string& key) const override { return params_.get<std::vector<double>>(key); }

 private:
  const Params& params_;
};

HardwareInterface to_interface(api::Interface iface) {
  switch (iface) {
    case api::Interface::Effort: return HardwareInterface::Effort;
    case api::Interface::Position: return HardwareInterface::Position;
    case api::Interface::Velocity: return HardwareInterface::Velocity;
  }
  throw ControllerConfigError("unknown hardware interface " + std::to_string(static_cast<std::uint32_t>(iface)) +
                              " (controller_api::Interface is Effort, Position or Velocity)");
}

}  // namespace

struct PluginController::Bindings {
  std::deque<ApiJoint> joints;  // stable addresses: the plugin keeps references
  std::optional<ApiCommandInput> command;
  std::optional<ApiStateOutput> state;
};

namespace {

class ApiSetup final : public api::Setup {
 public:
  ApiSetup(RobotHardware& hardware, const Params& params, PluginController::Bindings& bindings,
           std::unique_ptr<ScalarCommandPort>& command, std::unique_ptr<StatePort<JointControllerState>>& state)
      : hardware_(hardware), params_(params), api_params_(params), bindings_(bindings), command_(command), state_(state) {}

  const api::Parameters& params() const noexcept override { return api_params_; }

  api::Joint& claim_joint(const std::string& joint, api::Interface iface, const std::string& param_key) override {
    const std::string path = param_key.empty() ? params_.path() : join_param_path(params_.path(), param_key);
    return bindings_.joints.emplace_back(hardware_.claim_joint(joint, to_interface(iface), path));
  }

  api::CommandInput& add_command_input(double initial) override {
    if (command_) throw ControllerConfigError(params_.path() + ": add_command_input called twice (one \"command\" input a controller)");
    command_ = std::make_unique<ScalarCommandPort>("command");
    command_->reset_from_rt(initial);
    return bindings_.command.emplace(*command_);
  }

  api::StateOutput& add_state_output() override {
    if (state_) throw ControllerConfigError(params_.path() + ": add_state_output called twice (one \"state\" output a controller)");
    state_ = std::make_unique<StatePort<JointControllerState>>("state");
    state_->init(JointControllerState{});
    return bindings_.state.emplace(*state_);
  }

 private:
  RobotHardware& hardware_;
  const Params& params_;
  ApiParameters api_params_;
  PluginController::Bindings& bindings_;
  std::unique_ptr<ScalarCommandPort>& command_;
  std::unique_ptr<StatePort<JointControllerState>>& state_;
};

}  // namespace

PluginController::PluginController(std::shared_ptr<void> library, std::unique_ptr<api::Controller> plugin)
    : library_(std::move(library)), bindings_(std::make_unique<Bindings>()), plugin_(std::move(plugin)) {}

PluginController::~PluginController() = default;

bool PluginController::init(RobotHardware& hardware, const Params& params, std::string& /*error*/) {
  ApiSetup setup(hardware, params, *bindings_, command_, state_);
  plugin_->init(setup);  // exceptions go to the manager, which names the controller and type
  return true;
}

void PluginController::starting(double time) { plugin_->starting(time); }

UpdateStatus PluginController::update(double time, double period) {
  const api::Status status = plugin_->update(time, period);
  return status.ok ? UpdateStatus::Ok() : UpdateStatus::Error(status.reason != nullptr ? status.reason : "fault");
}

void PluginController::stopping(double time) { plugin_->stopping(time); }

std::vector<Port*> PluginController::ports() {
  std::vector<Port*> out;
  if (command_) out.push_back(command_.get());
  if (state_) out.push_back(state_.get());
  return out;
}

}  // namespace mechsim::control
