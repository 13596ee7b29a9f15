#pragma once
// Private to src/physics/*.cpp: the MuJoCo objects behind PhysicsModel. Never include this
// from a public header; it is the only header that includes mujoco.h.

#include <mujoco/mujoco.h>

#include "physics/physics_model.hpp"

namespace mechsim::physics {

struct PhysicsModel::Impl {
  mjModel* model = nullptr;  // compiled once; instances copy it (servo gains are per instance)
  ~Impl() {
    if (model != nullptr) mj_deleteModel(model);
  }
};

}  // namespace mechsim::physics
