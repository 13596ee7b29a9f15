# mechsim_layer(NAME DEPS ... [PRIVATE_DEPS ...] [TEST_DEPS ...] [NOT_PARTS ...]): the standard
# layer folder.
#   <layer>/*.cpp, <layer>/<part>/*.cpp          -> library mechsim_<layer>
#   <layer>/[<part>/]test/*_test.cpp             -> test program <layer>_test (label "unit")
#   <layer>/[<part>/]test/conformance/*_test.cpp -> <layer>_conformance_test (label "conformance")
#   <layer>/[<part>/]test/scenario/*_test.cpp    -> <layer>_scenario_test (label "scenario")
#   <layer>/[<part>/]bench/*_bench.cpp           -> benchmark program <layer>_bench
# `*_util.cpp` beside a test folder's tests are its helpers. A part (a sub-folder such as
# controllers/drive/ or description/xacro/) belongs to its layer's one library: one folder under
# src/ is one library target (DESIGN.md). NOT_PARTS names sub-folders the layer's CMakeLists.txt
# builds otherwise (ros/: bridge/ is its own library, apps/ its executables).
# Files are globbed so that several people can add files (and parts) to one layer without
# editing this.
function(mechsim_layer name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS;TEST_DEPS;NOT_PARTS" ${ARGN})
  set(dir "${CMAKE_CURRENT_SOURCE_DIR}")
  file(GLOB_RECURSE all_sources CONFIGURE_DEPENDS RELATIVE "${dir}" "${dir}/*.cpp")
  # Sorted so that the programs' link order does not depend on the file system.
  list(SORT all_sources)
  set(lib_sources "")
  set(bench_sources "")
  set(unit_sources "")
  set(conformance_sources "")
  set(scenario_sources "")
  foreach(rel IN LISTS all_sources)
    string(REGEX MATCH "^[^/]+" top "${rel}")
    if(top IN_LIST ARG_NOT_PARTS)
      continue()
    endif()
    if(rel MATCHES "(^|/)bench/[^/]+_bench\\.cpp$")
      list(APPEND bench_sources "${dir}/${rel}")
    elseif(rel MATCHES "(^|/)test/(conformance|scenario)/[^/]+_(test|util)\\.cpp$")
      list(APPEND ${CMAKE_MATCH_2}_sources "${dir}/${rel}")
    elseif(rel MATCHES "(^|/)test/[^/]+_(test|util)\\.cpp$")
      list(APPEND unit_sources "${dir}/${rel}")
    elseif(NOT rel MATCHES "(^|/)(test|bench)/")
      list(APPEND lib_sources "${dir}/${rel}")
    endif()
  endforeach()
  if(NOT lib_sources)
    # A layer still being written: headers only.
    add_library(mechsim_${name} INTERFACE)
    target_include_directories(mechsim_${name} INTERFACE "${PROJECT_SOURCE_DIR}/src")
    target_link_libraries(mechsim_${name} INTERFACE ${ARG_DEPS})
  else()
    mechsim_library(${name} SOURCES ${lib_sources} DEPS ${ARG_DEPS} PRIVATE_DEPS ${ARG_PRIVATE_DEPS})
  endif()
  foreach(kind unit conformance scenario)
    if(kind STREQUAL "unit")
      set(test_name ${name}_test)
    else()
      set(test_name ${name}_${kind}_test)
    endif()
    if(${kind}_sources)
      mechsim_test(${test_name} SOURCES ${${kind}_sources} DEPS mechsim_${name} ${ARG_TEST_DEPS} LABELS ${kind})
    endif()
  endforeach()
  if(bench_sources)
    mechsim_benchmark(${name}_bench SOURCES ${bench_sources} DEPS mechsim_${name} ${ARG_TEST_DEPS})
  endif()
endfunction()
