// Proves that the manager tick allocates nothing: this test program replaces the global
// operator new/delete with counting versions, and the count is taken over whole ticks (the
// mechanism propagation, every controller's update, safety limits) with 40 running controllers.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <sstream>

#include "control/controller_manager.hpp"
#include "controllers/builtin_controllers.hpp"
#include "controllers/test/test_robot.hpp"
#include "controllers/test/allocation_counter.hpp"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void* counted_alloc(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

void* counted_aligned_alloc(std::size_t size, std::align_val_t align) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  const auto a = static_cast<std::size_t>(align);
  void* p = std::aligned_alloc(a, (size + a - 1) / a * a);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

}  // namespace

void* operator new(std::size_t size) { return counted_alloc(size); }
void* operator new[](std::size_t size) { return counted_alloc(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted_alloc(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t size, std::align_val_t a) { return counted_aligned_alloc(size, a); }
void* operator new[](std::size_t size, std::align_val_t a) { return counted_aligned_alloc(size, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

// The counter for the other tests of this program (the counting operator new lives here, once).
namespace mechsim::control::testing {
void start_counting_allocations() noexcept {
  g_allocations = 0;
  g_counting = true;
}
long stop_counting_allocations() noexcept {
  g_counting = false;
  return g_allocations.load();
}
}  // namespace mechsim::control::testing

namespace mechsim::control {
namespace {

class AllocationCounter {
 public:
  AllocationCounter() {
    g_allocations = 0;
    g_counting = true;
  }
  ~AllocationCounter() { g_counting = false; }
  long count() const { return g_allocations.load(); }
};

TEST(Allocation, TheCounterSeesAllocations) {
  AllocationCounter counter;
  auto* v = new std::vector<double>(100);
  delete v;
  EXPECT_GE(counter.count(), 2);
}

TEST(Allocation, ManagerTickWith40RunningPositionControllersAllocatesNothing) {
  constexpr int kJoints = 40;
  auto robot = testing::make_robot(kJoints);
  std::ostringstream yaml;
  std::vector<std::string> names;
  for (int i = 0; i < kJoints; ++i) {
    names.push_back(std::string("c").append(std::to_string(i)));
    yaml << names.back() << ": {type: effort_controllers/JointPositionController, joint: j" << i
         << ", pid: {p: 100, i: 1, d: 20, i_clamp: 5}}\n";
  }
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(yaml.str()),
                            builtin_controller_registry());
  for (const auto& n : names) ASSERT_TRUE(manager.load_controller(n).ok);
  ASSERT_TRUE(manager.switch_controllers(names, {}, SwitchStrictness::Strict).ok);
  for (int i = 0; i < kJoints; ++i) {
    ASSERT_TRUE(manager.controller(names[i])->port_as<ScalarCommandPort>("command")->write(0.01 * i));
  }
  long allocations = 0;
  double time = 0.0;
  {
    AllocationCounter counter;
    time = testing::run(manager, *robot, time, 1000);  // includes the tick that starts them all
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
  int running = 0;
  for (const auto& info : manager.list_controllers()) running += info.state == ControllerLifecycle::Running;
  EXPECT_EQ(running, kJoints);
  EXPECT_EQ(manager.controller_info("c0")->statistics.updates, 1000u);
  // Commands written between ticks are picked up without allocating either.
  for (int i = 0; i < kJoints; ++i) {
    ASSERT_TRUE(manager.controller(names[i])->port_as<ScalarCommandPort>("command")->write(-0.01 * i));
  }
  {
    AllocationCounter counter;
    time = testing::run(manager, *robot, time, 10);
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
}

TEST(Allocation, EveryBuiltInControllerUpdatesWithoutAllocating) {
  auto robot = testing::make_robot(12);
  ControllerManager manager(robot->model, robot->state, Params::from_yaml_string(R"(
js: {type: joint_state_controller/JointStateController, publish_rate: 500}
e: {type: effort_controllers/JointEffortController, joint: j0}
v: {type: effort_controllers/JointVelocityController, joint: j1, pid: {p: 1}}
p: {type: effort_controllers/JointPositionController, joint: j2, pid: {p: 1}}
ge: {type: effort_controllers/JointGroupEffortController, joints: [j3]}
gp: {type: effort_controllers/JointGroupPositionController, joints: [j4, j5], j4: {pid: {p: 1}}, j5: {pid: {p: 2}}}
pp: {type: position_controllers/JointPositionController, joint: j6}
pg: {type: position_controllers/JointGroupPositionController, joints: [j7]}
vv: {type: velocity_controllers/JointVelocityController, joint: j8}
vg: {type: velocity_controllers/JointGroupVelocityController, joints: [j9]}
rp: {type: robot_mechanism_controllers/JointPositionController, joint: j10, pid: {p: 1}}
rv: {type: robot_mechanism_controllers/JointVelocityController, joint: j11, pid: {p: 1}}
)"), builtin_controller_registry());
  std::vector<std::string> names{"js", "e", "v", "p", "ge", "gp", "pp", "pg", "vv", "vg", "rp", "rv"};
  for (const auto& n : names) ASSERT_TRUE(manager.load_controller(n).ok) << n;
  ASSERT_TRUE(manager.switch_controllers(names, {}, SwitchStrictness::Strict).ok);
  long allocations = 0;
  {
    AllocationCounter counter;
    testing::run(manager, *robot, 0.0, 200);
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
  EXPECT_GE(manager.controller("js")->port_as<StatePort<JointStateSnapshot>>("joint_states")->sequence(), 99u);
}

}  // namespace
}  // namespace mechsim::control
