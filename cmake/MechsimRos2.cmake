# The optional ROS 2 layer (src/ros2/): detection, the MECHSIM_ROS2 option and the generation of
# its message code. No ROS 2 is installed: the layer speaks ROS 2 on the wire through eProsima
# Fast DDS (Debian's libfastrtps-dev, libfastcdr-dev; src/ros2/README.md says why that library),
# and its message code comes from mechsim's own generator (src/ros2/msg_gen/generate.py), run with
# /usr/bin/python3 as the ROS 1 layer runs gencpp (never a pyenv/venv interpreter from PATH).
#
# The test peers use the other DDS implementation, Eclipse Cyclone DDS (cyclonedds-dev, idlc):
# without it the layer still builds and its peer tests are left out, with a message.

find_package(fastcdr QUIET)
find_package(fastrtps QUIET)
find_program(MECHSIM_ROS2_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH
             DOC "The system Python that runs src/ros2/msg_gen/generate.py")
set(_mechsim_ros2_missing "")
if(NOT fastrtps_FOUND)
  list(APPEND _mechsim_ros2_missing "Fast DDS (libfastrtps-dev)")
endif()
if(NOT fastcdr_FOUND)
  list(APPEND _mechsim_ros2_missing "Fast CDR (libfastcdr-dev)")
endif()
if(NOT MECHSIM_ROS2_PYTHON)
  list(APPEND _mechsim_ros2_missing "/usr/bin/python3")
endif()

# MECHSIM_ROS2 is AUTO, ON or OFF, as MECHSIM_ROS (cmake/MechsimRos.cmake): AUTO (the default)
# follows what is installed at every configure, so a build folder configured before the packages
# were installed gains the layer at its next build, and one moved to a machine without them loses
# it with a message instead of failing; ON requires it (a configure error names what is missing).
set(MECHSIM_ROS2 AUTO CACHE STRING
    "Build the ROS 2 layer (src/ros2): AUTO where Fast DDS is found, ON (required) or OFF")
set_property(CACHE MECHSIM_ROS2 PROPERTY STRINGS AUTO ON OFF)
string(TOUPPER "${MECHSIM_ROS2}" _mechsim_ros2_request)
if(_mechsim_ros2_request STREQUAL "AUTO")
  if(_mechsim_ros2_missing)
    set(_mechsim_ros2_enabled OFF)
    message(STATUS "mechsim: ROS 2 layer left out (missing: ${_mechsim_ros2_missing}); "
                   "`scripts/install-deps.sh --with-ros` installs it")
  else()
    set(_mechsim_ros2_enabled ON)
  endif()
elseif(_mechsim_ros2_request MATCHES "^(ON|YES|TRUE|1)$")
  if(_mechsim_ros2_missing)
    message(FATAL_ERROR "MECHSIM_ROS2 is ON but its libraries were not found (missing: ${_mechsim_ros2_missing}). "
                        "Install them with `scripts/install-deps.sh --with-ros` or configure with -DMECHSIM_ROS2=AUTO or OFF.")
  endif()
  set(_mechsim_ros2_enabled ON)
elseif(_mechsim_ros2_request MATCHES "^(OFF|NO|FALSE|0)$")
  set(_mechsim_ros2_enabled OFF)
else()
  message(FATAL_ERROR "MECHSIM_ROS2 is '${MECHSIM_ROS2}': expected AUTO, ON or OFF")
endif()
set(MECHSIM_ROS2 ${_mechsim_ros2_enabled})
set(MECHSIM_ROS2_ENABLED ${_mechsim_ros2_enabled} CACHE INTERNAL "What MECHSIM_ROS2 resolved to (read by scripts/test.sh)")
message(STATUS "mechsim: ROS 2 layer ${MECHSIM_ROS2}")

# mechsim_ros2_generate_messages(TARGET DEFINITIONS <dir holding common/ and <distro>/ sets>)
# Runs the generator on every set and makes TARGET a static library of the generated code with
# the include root (<mechsim_ros2_msgs/...>) as a SYSTEM include directory.
function(mechsim_ros2_generate_messages target)
  cmake_parse_arguments(ARG "" "DEFINITIONS" "" ${ARGN})
  set(out "${CMAKE_CURRENT_BINARY_DIR}/ros2_msgs")
  set(script "${CMAKE_CURRENT_SOURCE_DIR}/msg_gen/generate.py")
  file(GLOB sets LIST_DIRECTORIES true RELATIVE "${ARG_DEFINITIONS}" "${ARG_DEFINITIONS}/*")
  list(SORT sets)
  # `common` first: the generator resolves a distro set's types there when the set lacks them.
  list(REMOVE_ITEM sets common)
  list(PREPEND sets common)
  set(set_args "")
  set(outputs "")
  set(sources "")
  file(GLOB_RECURSE definitions CONFIGURE_DEPENDS "${ARG_DEFINITIONS}/*.msg" "${ARG_DEFINITIONS}/*.srv"
       "${ARG_DEFINITIONS}/*.action")
  foreach(s IN LISTS sets)
    list(APPEND set_args --set "${s}=${ARG_DEFINITIONS}/${s}")
    file(GLOB packages LIST_DIRECTORIES true RELATIVE "${ARG_DEFINITIONS}/${s}" "${ARG_DEFINITIONS}/${s}/*")
    foreach(pkg IN LISTS packages)
      if(s STREQUAL "common")
        set(base "${out}/mechsim_ros2_msgs/${pkg}")
      else()
        set(base "${out}/mechsim_ros2_msgs/${s}/${pkg}")
      endif()
      list(APPEND outputs "${base}.hpp" "${base}.cpp")
      list(APPEND sources "${base}.cpp")
    endforeach()
  endforeach()
  list(APPEND outputs "${out}/mechsim_ros2_msgs/type_table.hpp")
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONPATH --unset=PYTHONHOME
            ${MECHSIM_ROS2_PYTHON} "${script}" --out "${out}" ${set_args}
    DEPENDS ${definitions} "${script}"
    COMMENT "Generating ROS 2 message code (src/ros2/msgs)"
    VERBATIM)
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} SYSTEM PUBLIC "${out}")
  target_include_directories(${target} PUBLIC "${PROJECT_SOURCE_DIR}/src")
  target_link_libraries(${target} PUBLIC fastcdr)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
