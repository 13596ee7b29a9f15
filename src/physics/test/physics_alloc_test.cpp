// The hot path allocates nothing: step(), joint I/O, commands, poses, twists and (with enough
// capacity) contacts. Counts C++ heap allocations in this test program (MuJoCo itself works
// in its preallocated arena).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "physics_test_util.hpp"

namespace {
std::atomic<long> g_allocations{0};  // test-program instrumentation only
}  // namespace

// Every unaligned form is replaced, not only the throwing one: libraries loaded into this
// program (Mesa's LLVM, for the renderer tests) allocate with the nothrow form and free with
// the plain delete, so a partial replacement pairs AddressSanitizer's new with our free().
// The aligned forms stay the runtime's, new and delete alike.
namespace {
void* counted_malloc(std::size_t size) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
void* counted_new(std::size_t size) {
  if (void* p = counted_malloc(size)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return counted_new(size); }
void* operator new[](std::size_t size) { return counted_new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return counted_malloc(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return counted_malloc(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace mechsim::physics {
namespace {

TEST(PhysicsAlloc, HotPathAllocatesNothing) {
  BuildOptions o;
  o.spawn.z = 0.3;
  auto model = test::build(test::pendulum_urdf(1.0, 1.0, 1e-3, R"(<limit lower="-1" upper="1" effort="50" velocity="5"/>)", "revolute"));
  Physics p(model);
  Physics box(test::build(test::box_urdf(), o));
  std::vector<Contact> contacts;
  contacts.reserve(64);
  p.set_mode(0, JointMode::Position);
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(p.step().ok());  // warm up
  const long before = g_allocations.load();
  double sink = 0.0;
  for (int i = 0; i < 1000; ++i) {
    p.set_position_command(0, 0.5);
    const StepStatus s = p.step();
    sink += s.ok() ? p.position(0) + p.velocity(0) + p.effort(0) : 0.0;
    sink += p.link_pose(0).position.z + p.link_twist(0).angular.y;
    EXPECT_TRUE(box.step().ok());
    sink += static_cast<double>(box.contacts(contacts)) + box.base_pose().position.z + box.base_twist().linear.z;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_NE(sink, 0.0);
}

}  // namespace
}  // namespace mechsim::physics
