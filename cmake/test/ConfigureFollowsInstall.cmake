# A build folder configured before ROS was installed gains the ROS layer once it is installed
# (issue 19: `scripts/run.sh` then `scripts/test.sh` on a fresh machine used to keep a cached
# MECHSIM_ROS=OFF and run 32 fewer tests without a word). "Not installed" is played by hiding
# pkg-config's files for the first configure. Run by CTest (test `configure_follows_install`):
#   cmake -DSOURCE=<repo> -DWORK=<scratch folder> -P cmake/test/ConfigureFollowsInstall.cmake
cmake_minimum_required(VERSION 3.22)
if(NOT SOURCE OR NOT WORK)
  message(FATAL_ERROR "ConfigureFollowsInstall: pass -DSOURCE=<repo> -DWORK=<scratch folder>")
endif()
file(REMOVE_RECURSE "${WORK}")

function(configure label expect)  # further arguments: environment assignments, then --, then cache options
  set(envs "")
  set(opts "")
  set(target envs)
  foreach(a IN LISTS ARGN)
    if(a STREQUAL "--")
      set(target opts)
    else()
      list(APPEND ${target} "${a}")
    endif()
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${envs}
                          ${CMAKE_COMMAND} -S "${SOURCE}" -B "${WORK}" -G Ninja -DCMAKE_BUILD_TYPE=Release
                          -DMECHSIM_BENCHMARKS=OFF ${opts}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    file(REMOVE_RECURSE "${WORK}")
    message(FATAL_ERROR "${label}: configure failed (${rc}):\n${out}\n${err}")
  endif()
  string(REGEX MATCH "mechsim: ROS 1 layer (ON|OFF)" line "${out}")
  if(NOT CMAKE_MATCH_1 STREQUAL expect)
    file(REMOVE_RECURSE "${WORK}")
    message(FATAL_ERROR "${label}: expected the ROS layer ${expect}, configure said '${line}'")
  endif()
  message(STATUS "${label}: ROS layer ${expect}")
endfunction()

configure("before ROS is installed" OFF PKG_CONFIG_LIBDIR=/nonexistent PKG_CONFIG_PATH=)
configure("the same folder once ROS is installed" ON --)
configure("explicit OFF is kept" OFF -- -DMECHSIM_ROS=OFF)
configure("explicit OFF stays OFF at the next configure" OFF --)
configure("back to AUTO" ON -- -DMECHSIM_ROS=AUTO)
configure("a folder from before AUTO (BOOL option cached OFF by detection)" ON -- -DMECHSIM_ROS:BOOL=OFF)
file(REMOVE_RECURSE "${WORK}")
