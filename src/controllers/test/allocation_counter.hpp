#pragma once
// The counting operator new of the controllers test program (defined in allocation_test.cpp): hot
// paths are checked to allocate nothing between start and stop.

namespace mechsim::control::testing {

void start_counting_allocations() noexcept;
long stop_counting_allocations() noexcept;  // allocations since start

}  // namespace mechsim::control::testing
