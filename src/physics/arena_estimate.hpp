#pragma once
// Private to src/physics/*.cpp: sizing MuJoCo 2.2.2's per-instance arena (nconmax contacts,
// njmax constraint rows and the stack that goes with them) from a compiled model.

#include "physics/mujoco_internal.hpp"

namespace mechsim::physics {

// What can touch what in `m` and the arena that holds it with margin (see ArenaEstimate).
ArenaEstimate estimate_arena(const mjModel& m);

// Gives `m` (and so every mjData made from it) an arena of `size`, with the stack MuJoCo's
// compiler would have given that many constraints (PhysicsModel::Impl::stack_residual).
void set_arena(mjModel& m, const ArenaSize& size, long stack_residual);

// The arena of `m`.
inline ArenaSize arena_of(const mjModel& m) { return {m.nconmax, m.njmax}; }

}  // namespace mechsim::physics
