#pragma once
// Bad input while building a mechanism. what() reads
//   "<file>:<line>: transmission '<name>' (<type>): <what is wrong>"
// and the fields name the parts for programs that want them.

#include <stdexcept>
#include <string>

namespace mechsim::mechanism {

class MechanismError : public std::runtime_error {
 public:
  MechanismError(const std::string& message, std::string transmission, std::string element, int line)
      : std::runtime_error(message),
        transmission_(std::move(transmission)),
        element_(std::move(element)),
        line_(line) {}
  const std::string& transmission() const { return transmission_; }  // empty when not about one
  const std::string& element() const { return element_; }  // the joint/actuator/parameter named, or empty
  int line() const { return line_; }  // 1-based line in the description, 0 when unknown

 private:
  std::string transmission_;
  std::string element_;
  int line_;
};

}  // namespace mechsim::mechanism
