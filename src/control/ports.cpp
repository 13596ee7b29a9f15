#include "control/ports.hpp"

#include <cmath>

namespace mechsim::control {

bool RejectionLog::reject(std::string reason, std::string* error) {
  count_.fetch_add(1, std::memory_order_relaxed);
  if (error != nullptr) *error = reason;
  std::lock_guard<std::mutex> lock(mutex_);
  last_ = std::move(reason);
  return false;
}

namespace {

std::string number(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return std::to_string(v);
}

}  // namespace

bool ScalarCommandPort::write(double value, std::string* error) {
  if (!std::isfinite(value)) {
    return reject("port '" + name() + "': rejected non-finite command " + number(value) + "; the previous command stays",
                  error);
  }
  buffer_.write(value);
  return true;
}

ArrayCommandPort::ArrayCommandPort(std::string name, std::size_t size)
    : Port(std::move(name)), size_(size), buffer_(std::vector<double>(size, 0.0)) {}

bool ArrayCommandPort::write(std::span<const double> values, std::string* error) {
  if (values.size() != size_) {
    return reject("port '" + name() + "': dimension of command (" + std::to_string(values.size()) +
                      ") does not match number of joints (" + std::to_string(size_) + "); not executing",
                  error);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      return reject("port '" + name() + "': rejected non-finite command " + number(values[i]) + " at index " +
                        std::to_string(i) + "; the previous command stays",
                    error);
    }
  }
  buffer_.write(std::vector<double>(values.begin(), values.end()));
  return true;
}

void ArrayCommandPort::reset_from_rt(std::span<const double> values) noexcept {
  buffer_.reset_from_rt([values](std::vector<double>& rt) {
    for (std::size_t i = 0; i < rt.size() && i < values.size(); ++i) rt[i] = values[i];
  });
}

bool TwistCommandPort::write(const Twist& t, std::string* error) {
  for (double v : {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z}) {
    if (!std::isfinite(v)) {
      return reject("port '" + name() + "': rejected non-finite twist component " + number(v) +
                        "; the previous command stays",
                    error);
    }
  }
  buffer_.write(t);
  accepted_.fetch_add(1, std::memory_order_release);
  return true;
}

bool PidGainsPort::write(const PidGains& g, std::string* error) {
  for (double v : {g.p, g.i, g.d, g.i_max, g.i_min}) {
    if (!std::isfinite(v)) {
      if (error != nullptr) *error = "port '" + name() + "': PID gains must be finite";
      return false;
    }
  }
  pid_->set_gains(g);
  return true;
}

}  // namespace mechsim::control
