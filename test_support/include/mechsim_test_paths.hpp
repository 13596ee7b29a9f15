#pragma once
// Where this checkout, its build and the shared test data are, for test programs and benchmarks.
//
// The values live in one generated source (test_support/test_paths.cpp.in, configured into the
// build folder) and reach the tests through the MECHSIM_SHARED_DIR, MECHSIM_SOURCE_DIR, ...
// macros, which expand to calls of these functions. Test objects therefore carry no absolute path
// of the checkout, and ccache shares them between clones (a new clone recompiled every test
// source when the paths were string literals on the compile line).
namespace mechsim::test_paths {

const char* shared_dir() noexcept;   // ../shared beside the checkout (MECHSIM_SHARED_DIR)
const char* source_dir() noexcept;   // the checkout (MECHSIM_SOURCE_DIR)
const char* binary_dir() noexcept;   // the build folder (MECHSIM_BINARY_DIR)
const char* mechsim_exe() noexcept;  // <build>/bin/mechsim (MECHSIM_EXE)
const char* test_plugin_dir() noexcept;         // <build>/test_plugins (MECHSIM_TEST_PLUGIN_DIR)
const char* example_plugin_package() noexcept;  // (MECHSIM_EXAMPLE_PLUGIN_PACKAGE)
// Defined only in the ROS integration test program (src/ros/CMakeLists.txt generates them).
const char* node_exe() noexcept;     // MECHSIM_NODE_EXE
const char* spawner_exe() noexcept;  // MECHSIM_SPAWNER_EXE

}  // namespace mechsim::test_paths
