# Helpers shared by every layer's CMakeLists.txt.

# Warnings (as errors unless MECHSIM_WERROR is off) on mechsim's own targets only.
function(mechsim_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wconversion -Wno-sign-conversion)
  if(MECHSIM_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# mechsim_library(NAME SOURCES ... DEPS ...): one layer folder = one library `mechsim_<NAME>`.
# Headers are included as "<layer>/<file>.hpp" from src/.
function(mechsim_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(mechsim_${name} ${ARG_SOURCES})
  target_include_directories(mechsim_${name} PUBLIC "${PROJECT_SOURCE_DIR}/src")
  target_link_libraries(mechsim_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  mechsim_warnings(mechsim_${name})
endfunction()

# mechsim_test(NAME SOURCES ... DEPS ... [LABELS ...]): a GoogleTest program run by CTest.
# LABELS defaults to "unit"; the sanitizer build runs the "unit" label only. Other labels in use:
# "conformance" (data-driven suites over ../shared), "scenario" (whole simulations), "cli".
# Tests find ../shared through MECHSIM_SHARED_DIR and skip when it is absent.
function(mechsim_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LABELS" ${ARGN})
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  add_executable(${name} ${ARG_SOURCES})
  # mechsim_test_paths: MECHSIM_SHARED_DIR, MECHSIM_SOURCE_DIR, MECHSIM_BINARY_DIR, MECHSIM_EXE (and
  # the like) as calls into one generated source, not absolute paths on the compile line.
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} mechsim_test_paths GTest::gtest GTest::gmock GTest::gtest_main)
  mechsim_warnings(${name})
  # GoogleTest/GoogleMock and the standard headers every test uses, parsed once per program
  # instead of once per source (they were about half of a test source's compile time).
  target_precompile_headers(${name} PRIVATE <gmock/gmock.h> <gtest/gtest.h> <filesystem> <fstream>
                                            <functional> <map> <memory> <sstream> <string> <vector>
                                            <mechsim_test_paths.hpp>)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # Through the precompiled header, GCC 12 at -O3 reports its known false positives on inlined
    # std::string code ("literal" + std::string: GCC bugs 105329, 105651; memcpy bounds) that it
    # keeps quiet about when the same headers are parsed in the source. Test programs only.
    target_compile_options(${name} PRIVATE -Wno-stringop-overflow -Wno-stringop-overread -Wno-restrict -Wno-array-bounds)
  endif()
  if(MECHSIM_SANITIZE)
    # One CTest test per program: under the sanitizers a process takes ~0.5 s to start, and
    # one process per test (gtest_discover_tests) spent more time starting than testing.
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES TIMEOUT 1800 LABELS "${ARG_LABELS}")
  else()
    gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60
                         PROPERTIES TIMEOUT 300 LABELS "${ARG_LABELS}")
  endif()
endfunction()

# mechsim_fuzz(NAME SOURCES ... DEPS ...): a fuzz target (a source defining LLVMFuzzerTestOneInput).
# With MECHSIM_FUZZ (Clang, scripts/fuzz.sh) it is a libFuzzer program. In every other build it is
# a program that replays fuzz/regressions/NAME (the inputs that once found a defect, and seeds of
# what each target must survive) and a "unit" test running it, so that the sanitizer run of CI
# replays them too.
function(mechsim_fuzz name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  if(MECHSIM_FUZZ)
    add_executable(${name} ${ARG_SOURCES})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  else()
    add_executable(${name} ${ARG_SOURCES} "${PROJECT_SOURCE_DIR}/fuzz/replay_main.cpp")
    add_test(NAME ${name}_replay COMMAND ${name} "${PROJECT_SOURCE_DIR}/fuzz/regressions/${name}")
    set_tests_properties(${name}_replay PROPERTIES LABELS unit TIMEOUT 300)
  endif()
  target_include_directories(${name} PRIVATE "${PROJECT_SOURCE_DIR}/fuzz")
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  mechsim_warnings(${name})
endfunction()

# mechsim_benchmark(NAME SOURCES ... DEPS ...): a Google Benchmark program (not run by CTest).
function(mechsim_benchmark name)
  if(NOT MECHSIM_BENCHMARKS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  # The paths as in mechsim_test (no precompiled header here: the declarations come by -include).
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} mechsim_test_paths benchmark::benchmark)
  target_compile_options(${name} PRIVATE -include mechsim_test_paths.hpp)
  mechsim_warnings(${name})
endfunction()
