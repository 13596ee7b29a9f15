#include "sim/controller_set.hpp"

#include <algorithm>
#include <numeric>
#include <set>

namespace mechsim::sim {

std::vector<std::string> widest_conflict_free(const std::vector<control::ControllerInfo>& loaded) {
  std::vector<std::set<std::string>> joints(loaded.size());
  for (std::size_t k = 0; k < loaded.size(); ++k) {
    for (const control::ResourceClaim& claim : loaded[k].claims) joints[k].insert(claim.joints.begin(), claim.joints.end());
  }
  std::vector<std::size_t> order(loaded.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return joints[a].size() > joints[b].size(); });
  std::set<std::string> taken;
  std::vector<bool> chosen(loaded.size(), false);
  for (const std::size_t k : order) {
    if (std::any_of(joints[k].begin(), joints[k].end(), [&](const std::string& j) { return taken.count(j) > 0; })) continue;
    taken.insert(joints[k].begin(), joints[k].end());
    chosen[k] = true;
  }
  std::vector<std::string> out;
  for (std::size_t k = 0; k < loaded.size(); ++k) {
    if (chosen[k]) out.push_back(loaded[k].name);
  }
  return out;
}

}  // namespace mechsim::sim
