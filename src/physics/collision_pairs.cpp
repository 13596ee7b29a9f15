#include "physics/collision_pairs.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "physics/physics_options.hpp"

namespace mechsim::physics {
namespace {

// MuJoCo's filter on two welded bodies w1, w2 (body_weldid) with welded parents p1, p2: not one
// body, not parent and child (MuJoCo filters the parent unless told not to; mechsim never tells
// it), the world (0) exempt from the parent rule.
bool welds_may_touch(int w1, int p1, int w2, int p2) {
  if (w1 == w2) return false;
  return !(w1 != 0 && w2 != 0 && (w1 == p2 || w2 == p1));
}

}  // namespace

std::optional<std::vector<ListedPair>> list_collision_pairs(const std::vector<WrittenBody>& bodies,
                                                            const std::vector<WrittenGeom>& geoms,
                                                            const std::vector<std::pair<std::string, std::string>>& excludes) {
  // MuJoCo's body_weldid: the body itself when it has joints, else its parent's (bodies come after
  // their parents).
  std::vector<int> weld(bodies.size(), 0);
  std::map<std::string, int> body_index;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    body_index[bodies[b].name] = static_cast<int>(b);
    if (b == 0) continue;
    weld[b] = bodies[b].jointed ? static_cast<int>(b) : weld[static_cast<std::size_t>(bodies[b].parent)];
  }
  const auto weld_parent = [&](int w) { return weld[static_cast<std::size_t>(bodies[static_cast<std::size_t>(w)].parent)]; };
  std::set<std::pair<int, int>> excluded;
  for (const auto& [a, b] : excludes) {
    const auto ia = body_index.find(a), ib = body_index.find(b);
    if (ia == body_index.end() || ib == body_index.end()) continue;
    excluded.insert(std::minmax(ia->second, ib->second));
  }

  // (lower body, higher body, geom order on the lower, on the higher): MuJoCo's broad phase tests
  // body pairs by signature and, within one, the lower body's geoms against the higher's, in order.
  std::vector<std::tuple<int, int, std::size_t, std::size_t>> order;
  int moving = 0;
  for (std::size_t i = 0; i < geoms.size(); ++i)
    for (std::size_t j = i + 1; j < geoms.size(); ++j) {
      const WrittenGeom& a = geoms[i];
      const WrittenGeom& b = geoms[j];
      if (!((a.contype & b.conaffinity) || (b.contype & a.conaffinity))) continue;
      if (a.ground && b.ground) continue;  // no collision function
      const int wa = weld[static_cast<std::size_t>(a.body)], wb = weld[static_cast<std::size_t>(b.body)];
      if (!welds_may_touch(wa, weld_parent(wa), wb, weld_parent(wb))) continue;
      if (excluded.count(std::minmax(a.body, b.body))) continue;
      if (wa != 0 && wb != 0 && ++moving > kMaxListedMovingPairs) return std::nullopt;
      if (a.body <= b.body) order.emplace_back(a.body, b.body, i, j);
      else order.emplace_back(b.body, a.body, j, i);
    }
  std::sort(order.begin(), order.end());
  std::vector<ListedPair> out;
  out.reserve(order.size());
  for (const auto& [b1, b2, g1, g2] : order) out.push_back({&geoms[g1], &geoms[g2]});
  return out;
}

bool filters_let_touch(const mjModel& m, int g1, int g2) {
  const int ct1 = m.geom_contype[g1], ca1 = m.geom_conaffinity[g1];
  const int ct2 = m.geom_contype[g2], ca2 = m.geom_conaffinity[g2];
  if (!((ct1 & ca2) || (ct2 & ca1))) return false;
  const int b1 = m.geom_bodyid[g1], b2 = m.geom_bodyid[g2];
  const int w1 = m.body_weldid[b1], w2 = m.body_weldid[b2];
  if (w1 == w2) return false;
  const int p1 = m.body_weldid[m.body_parentid[w1]], p2 = m.body_weldid[m.body_parentid[w2]];
  const bool filter_parent = (m.opt.disableflags & mjDSBL_FILTERPARENT) == 0;
  if (filter_parent && w1 != 0 && w2 != 0 && (w1 == p2 || w2 == p1)) return false;
  for (int e = 0; e < m.nexclude; ++e) {
    const int s = m.exclude_signature[e];
    if (s == ((b1 + 1) << 16) + b2 + 1 || s == ((b2 + 1) << 16) + b1 + 1) return false;
  }
  return true;
}

std::string check_listed_pairs(const mjModel& m) {
  const auto has_function = [&](int g1, int g2) {
    const int t1 = std::min(m.geom_type[g1], m.geom_type[g2]), t2 = std::max(m.geom_type[g1], m.geom_type[g2]);
    return mjCOLLISIONFUNC[t1][t2] != nullptr;
  };
  const auto name = [&](int g) {
    const char* n = mj_id2name(&m, mjOBJ_GEOM, g);
    return std::string(n != nullptr ? n : "?");
  };
  std::set<std::pair<int, int>> listed;
  for (int p = 0; p < m.npair; ++p) {
    const int g1 = m.pair_geom1[p], g2 = m.pair_geom2[p];
    const std::string which = "pair " + name(g1) + " / " + name(g2);
    if (!listed.insert(std::minmax(g1, g2)).second) return which + " listed twice";
    if (!filters_let_touch(m, g1, g2)) return which + " is one MuJoCo's filters keep apart";
    // The parameters MuJoCo 2.2.2's dynamic collision (mj_collideGeoms) gives the pair: those of
    // the geom with the higher priority, else the larger condim and friction and the solmix mix.
    const int p1 = m.geom_priority[g1], p2 = m.geom_priority[g2];
    int condim;
    mjtNum friction[5], solref[mjNREF], solimp[mjNIMP];
    if (p1 != p2) {
      const int gp = p1 > p2 ? g1 : g2;
      condim = m.geom_condim[gp];
      for (int i = 0; i < 3; ++i) friction[2 * i] = m.geom_friction[3 * gp + i];
      for (int i = 0; i < mjNREF; ++i) solref[i] = m.geom_solref[mjNREF * gp + i];
      for (int i = 0; i < mjNIMP; ++i) solimp[i] = m.geom_solimp[mjNIMP * gp + i];
    } else {
      condim = std::max(m.geom_condim[g1], m.geom_condim[g2]);
      for (int i = 0; i < 3; ++i) friction[2 * i] = std::max(m.geom_friction[3 * g1 + i], m.geom_friction[3 * g2 + i]);
      const mjtNum s1 = m.geom_solmix[g1], s2 = m.geom_solmix[g2];
      const mjtNum mix = s1 >= mjMINVAL && s2 >= mjMINVAL ? s1 / (s1 + s2)
                         : s1 < mjMINVAL && s2 < mjMINVAL ? 0.5
                         : s1 < mjMINVAL                  ? 0.0
                                                          : 1.0;
      const mjtNum* r1 = m.geom_solref + mjNREF * g1;
      const mjtNum* r2 = m.geom_solref + mjNREF * g2;
      for (int i = 0; i < mjNREF; ++i)
        solref[i] = r1[0] > 0 && r2[0] > 0 ? mix * r1[i] + (1 - mix) * r2[i] : std::min(r1[i], r2[i]);
      for (int i = 0; i < mjNIMP; ++i) {
        solimp[i] = m.geom_solimp[mjNIMP * g1 + i] * mix;
        solimp[i] += m.geom_solimp[mjNIMP * g2 + i] * (1 - mix);
      }
    }
    friction[1] = friction[0];
    friction[3] = friction[4];
    if (m.pair_dim[p] != condim) return which + ": condim " + std::to_string(m.pair_dim[p]) + ", MuJoCo would give " + std::to_string(condim);
    for (int i = 0; i < 5; ++i)
      if (m.pair_friction[5 * p + i] != friction[i]) return which + ": friction differs from what MuJoCo would give";
    for (int i = 0; i < mjNREF; ++i)
      if (m.pair_solref[mjNREF * p + i] != solref[i]) return which + ": solref differs from what MuJoCo would give";
    for (int i = 0; i < mjNIMP; ++i)
      if (m.pair_solimp[mjNIMP * p + i] != solimp[i]) return which + ": solimp differs from what MuJoCo would give";
    if (m.pair_margin[p] != std::max(m.geom_margin[g1], m.geom_margin[g2]) || m.pair_gap[p] != std::max(m.geom_gap[g1], m.geom_gap[g2]))
      return which + ": margin or gap differs from what MuJoCo would give";
  }
  for (int g1 = 0; g1 < m.ngeom; ++g1)
    for (int g2 = g1 + 1; g2 < m.ngeom; ++g2)
      if (filters_let_touch(m, g1, g2) && has_function(g1, g2) && !listed.count({g1, g2}))
        return "pair " + name(g1) + " / " + name(g2) + " can touch but is not listed";
  return {};
}

}  // namespace mechsim::physics
