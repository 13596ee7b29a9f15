#pragma once
// Private to src/physics/*.cpp: the MuJoCo objects behind PhysicsModel. Never include this
// from a public header; it is the only header that includes mujoco.h.

#include <mujoco/mujoco.h>

#include "physics/physics_model.hpp"

namespace mechsim::physics {

struct PhysicsModel::Impl {
  mjModel* model = nullptr;  // compiled once; instances copy it (servo gains are per instance)
  // MuJoCo 2.2.2's compiler gives the stack 5 (njmax + nv)^2 mjtNums plus a term of the model's
  // other sizes; this is that term, read back after compiling, so that an arena set (or grown)
  // afterwards gets the stack the compiler would have given it (arena_estimate.hpp).
  long stack_residual = 0;
  ~Impl() {
    if (model != nullptr) mj_deleteModel(model);
  }
};

}  // namespace mechsim::physics
