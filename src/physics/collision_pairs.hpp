#pragma once
// Private to src/physics/*.cpp: the geom pairs MuJoCo 2.2.2's collision filters let touch, listed
// as predefined <pair>s so that a step tests them without the broad phase (StepCost::listed_pairs,
// physics/README.md "Step cost").
//
// mjcf_writer.cpp records the bodies and collision geoms as it writes them (MuJoCo numbers bodies in
// document order, depth first) and lists the pairs with MuJoCo's own rules; PhysicsModel::build
// checks the compiled model against MuJoCo's filters and falls back to the broad phase if they
// differ, so a mistake here costs speed, never physics.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "physics/mujoco_internal.hpp"

namespace mechsim::physics {

// A body as written: its parent's index (the world is body 0, its own parent) and whether it has
// joints (one without is welded to its parent, MuJoCo's body_weldid).
struct WrittenBody {
  std::string name;
  int parent = 0;
  bool jointed = false;
};

// A collision geom as written (visual geoms never collide and are not recorded).
struct WrittenGeom {
  std::string name;
  int body = 0;
  int contype = 0, conaffinity = 0;
  bool ground = false;    // a plane or height field: MuJoCo has no plane-plane or plane-hfield test
  double friction = 1.0;  // its one sliding coefficient
};

struct ListedPair {
  const WrittenGeom* geom1 = nullptr;  // the one on the lower body, as MuJoCo's broad phase orders them
  const WrittenGeom* geom2 = nullptr;
};

// Every pair of `geoms` that MuJoCo 2.2.2's filters let touch: contype/conaffinity bits, not one
// welded body, not a welded parent and child, not an excluded body pair (`excludes`: body names),
// in the order MuJoCo's broad phase would test them (body pairs by signature, then geoms in order),
// so that contacts come out in the same order. nullopt when more than kMaxListedMovingPairs of them
// join two movable bodies (the broad phase's sweep is then the cheaper way).
std::optional<std::vector<ListedPair>> list_collision_pairs(const std::vector<WrittenBody>& bodies,
                                                            const std::vector<WrittenGeom>& geoms,
                                                            const std::vector<std::pair<std::string, std::string>>& excludes);

// Whether MuJoCo 2.2.2's dynamic collision filters let geoms g1 and g2 of `m` touch (the rules
// above, read from the compiled model).
bool filters_let_touch(const mjModel& m, int g1, int g2);

// Checks a model compiled with listed pairs: exactly the geom pairs MuJoCo's filters let touch
// (those with a collision function), each with the condim, friction, solref, solimp, margin and
// gap MuJoCo's dynamic collision would give it. Empty when they match; else what differs first.
std::string check_listed_pairs(const mjModel& m);

}  // namespace mechsim::physics
