#pragma once
// The parameter server's names when made; forget_new() deletes every parameter set since, so that
// a test that launched users' files (which load controllers at the root namespace) leaves nothing
// that a later node with robot namespace "/" would take for its controllers.

#include <algorithm>
#include <string>
#include <vector>

#include <ros/ros.h>

namespace mechsim::ros::test {

class ParamSnapshot {
 public:
  ParamSnapshot() {
    ::ros::param::getParamNames(names_);
    std::sort(names_.begin(), names_.end());
  }
  void forget_new() const {
    std::vector<std::string> now;
    ::ros::param::getParamNames(now);
    for (const std::string& name : now)
      if (!std::binary_search(names_.begin(), names_.end(), name)) ::ros::param::del(name);
  }

 private:
  std::vector<std::string> names_;
};

}  // namespace mechsim::ros::test
