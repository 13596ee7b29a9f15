# The optional ROS 1 layer (src/ros/): detection, the MECHSIM_ROS option, and message generation
# with Debian's genmsg/gencpp from plain CMake (no catkin workspace).
#
# Catkin's own CMake runs the generators with whatever python3 comes first on PATH, which breaks
# when that is not the system interpreter (pyenv, venvs): Debian's genmsg, gencpp and empy live
# in /usr/lib/python3/dist-packages only. So every generator here runs with /usr/bin/python3 and
# with PYTHONPATH/PYTHONHOME unset.

find_path(MECHSIM_ROS_INCLUDE_DIR ros/ros.h)
find_program(MECHSIM_ROS_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH
             DOC "The system Python that has Debian's genmsg/gencpp (never a pyenv/venv one)")
find_file(MECHSIM_GENCPP_SCRIPT gen_cpp.py PATHS /usr/lib/gencpp NO_DEFAULT_PATH
          DOC "gencpp's generator script (python3-gencpp)")
find_path(MECHSIM_GENCPP_TEMPLATE_DIR msg.h.template PATHS /usr/share/gencpp NO_DEFAULT_PATH
          DOC "gencpp's msg.h/srv.h templates (python3-gencpp)")
find_file(MECHSIM_GENACTION_SCRIPT genaction.py PATHS /usr/lib/actionlib_msgs NO_DEFAULT_PATH
          DOC "The .action -> 7 .msg expander (ros-actionlib-msgs)")
find_file(MECHSIM_GENPY_MSG_SCRIPT genmsg_py.py PATHS /usr/lib/genpy NO_DEFAULT_PATH
          DOC "genpy's .msg -> Python generator (python3-genpy); optional: without it no ros_python")
find_file(MECHSIM_GENPY_SRV_SCRIPT gensrv_py.py PATHS /usr/lib/genpy NO_DEFAULT_PATH
          DOC "genpy's .srv -> Python generator (python3-genpy)")
set(MECHSIM_ROS_SHARE_DIR "/usr/share" CACHE PATH
    "Where Debian's ros-*-msgs packages put <pkg>/msg/*.msg (the gencpp include paths)")
# ROS libraries through Debian's pkg-config files rather than find_package(roscpp): the catkin
# config files behind the latter run python3 from PATH too. Imported targets for the ROS layer:
#   PkgConfig::MECHSIM_ROSCPP_SERIALIZATION  message (de)serialization, ros::Time (used by the msgs)
#   PkgConfig::MECHSIM_ROSCPP                the node API
#   PkgConfig::MECHSIM_ACTIONLIB             action servers and clients
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(MECHSIM_ROSCPP_SERIALIZATION QUIET IMPORTED_TARGET roscpp_serialization)
  pkg_check_modules(MECHSIM_ROSCPP QUIET IMPORTED_TARGET roscpp)
  pkg_check_modules(MECHSIM_ACTIONLIB QUIET IMPORTED_TARGET actionlib)
endif()

set(_mechsim_ros_missing "")
foreach(var MECHSIM_ROS_INCLUDE_DIR MECHSIM_ROS_PYTHON MECHSIM_GENCPP_SCRIPT
            MECHSIM_GENCPP_TEMPLATE_DIR MECHSIM_GENACTION_SCRIPT)
  if(NOT ${var})
    list(APPEND _mechsim_ros_missing ${var})
  endif()
endforeach()
foreach(module ROSCPP_SERIALIZATION ROSCPP ACTIONLIB)
  if(NOT MECHSIM_${module}_FOUND)
    string(TOLOWER "${module}" pc_name)
    list(APPEND _mechsim_ros_missing "pkg-config ${pc_name}")
  endif()
endforeach()
# MECHSIM_ROS is AUTO, ON or OFF. AUTO (the default) follows what is installed at every configure:
# a build folder configured before `install-deps.sh --with-ros` gains the ROS layer at the next
# build instead of keeping a cached OFF (a plain option() cached the first answer for good).
# Build folders from before AUTO existed hold a BOOL option that was only ever a detection result:
# they become AUTO.
get_property(_mechsim_ros_type CACHE MECHSIM_ROS PROPERTY TYPE)
if(_mechsim_ros_type STREQUAL "BOOL")
  set(MECHSIM_ROS AUTO CACHE STRING "" FORCE)
endif()
set(MECHSIM_ROS AUTO CACHE STRING
    "Build the ROS 1 layer (src/ros): AUTO where Debian's ROS packages are found, ON (required) or OFF")
set_property(CACHE MECHSIM_ROS PROPERTY STRINGS AUTO ON OFF)
string(TOUPPER "${MECHSIM_ROS}" _mechsim_ros_request)
if(_mechsim_ros_request STREQUAL "AUTO")
  if(_mechsim_ros_missing)
    set(_mechsim_ros_enabled OFF)
    message(STATUS "mechsim: ROS 1 not found (missing: ${_mechsim_ros_missing}); "
                   "the ROS layer is left out until `scripts/install-deps.sh --with-ros` installs it")
  else()
    set(_mechsim_ros_enabled ON)
  endif()
elseif(_mechsim_ros_request MATCHES "^(ON|YES|TRUE|1)$")
  if(_mechsim_ros_missing)
    message(FATAL_ERROR "MECHSIM_ROS is ON but ROS 1 was not found (missing: ${_mechsim_ros_missing}). "
                        "Install it with `scripts/install-deps.sh --with-ros` or configure with -DMECHSIM_ROS=AUTO or OFF.")
  endif()
  set(_mechsim_ros_enabled ON)
elseif(_mechsim_ros_request MATCHES "^(OFF|NO|FALSE|0)$")
  set(_mechsim_ros_enabled OFF)
else()
  message(FATAL_ERROR "MECHSIM_ROS is '${MECHSIM_ROS}': expected AUTO, ON or OFF")
endif()
# From here on MECHSIM_ROS is the answer (a normal variable shadowing the cached request).
set(MECHSIM_ROS ${_mechsim_ros_enabled})
set(MECHSIM_ROS_ENABLED ${_mechsim_ros_enabled} CACHE INTERNAL "What MECHSIM_ROS resolved to (read by scripts/test.sh)")
message(STATUS "mechsim: ROS 1 layer ${MECHSIM_ROS}")

# mechsim_ros_use_cxx17(TARGET ...): compile targets whose sources include ROS message headers
# as C++17. gencpp's headers (Debian's own lib*-msgs-dev ones too) name string and vector types
# through std::allocator<void>::rebind, which C++20 removed, so a message with a string or array
# field does not compile as C++20. Such code must keep ROS includes in C++17 translation units
# and reach the C++20 layers through headers that also compile as C++17.
function(mechsim_ros_use_cxx17)
  foreach(t IN LISTS ARGN)
    get_target_property(type ${t} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      set_target_properties(${t} PROPERTIES CXX_STANDARD 17)
    endif()
  endforeach()
endfunction()

set(_mechsim_ros_python_env ${CMAKE_COMMAND} -E env --unset=PYTHONPATH --unset=PYTHONHOME)

# mechsim_ros_generate_messages(TARGET
#     PACKAGES_DIR <dir holding <pkg>/{msg,srv,action}/>
#     MSG_DEPENDS <Debian message packages the definitions use, e.g. std_msgs ...>)
# Generates <pkg>/<Name>.h for every .msg, .srv (also <Name>Request.h, <Name>Response.h) and the
# seven messages of every .action, under <binary dir>/ros_msgs/include, and makes TARGET an
# INTERFACE library with that include dir (as SYSTEM: gencpp's code is not ours to warn about).
# Sets <TARGET>_TYPES in the caller's scope: one "pkg/Name:kind" per generated type, with kind
# msg, srv (the service and its Request/Response) or action-msg, matching md5sums.tsv's kinds.
function(mechsim_ros_generate_messages target)
  cmake_parse_arguments(ARG "" "PACKAGES_DIR" "MSG_DEPENDS" ${ARGN})
  set(gen_root "${CMAKE_CURRENT_BINARY_DIR}/ros_msgs")
  set(include_root "${gen_root}/include")
  file(GLOB packages LIST_DIRECTORIES true RELATIVE "${ARG_PACKAGES_DIR}" "${ARG_PACKAGES_DIR}/*")
  list(SORT packages)

  # Include paths: ours (sources and action expansions) first, then Debian's definitions.
  set(iflags "")
  foreach(pkg IN LISTS packages)
    list(APPEND iflags "-I${pkg}:${ARG_PACKAGES_DIR}/${pkg}/msg" "-I${pkg}:${gen_root}/${pkg}/msg")
  endforeach()
  foreach(dep IN LISTS ARG_MSG_DEPENDS)
    set(dep_dir "${MECHSIM_ROS_SHARE_DIR}/${dep}/msg")
    if(NOT IS_DIRECTORY "${dep_dir}")
      message(FATAL_ERROR "mechsim_ros_generate_messages: message package '${dep}' not found at ${dep_dir} "
                          "(install ros-${dep} with `scripts/install-deps.sh --with-ros`; the Debian name uses dashes)")
    endif()
    list(APPEND iflags "-I${dep}:${dep_dir}")
  endforeach()

  # Pass 1: expand actions and collect every definition file, so that each header can depend on
  # all of them (a definition may use any other; regenerating all is cheap and always right).
  set(all_defs "")
  set(jobs "")   # "pkg|file|kind" per gencpp run
  set(types "")
  foreach(pkg IN LISTS packages)
    set(src "${ARG_PACKAGES_DIR}/${pkg}")
    file(GLOB msgs CONFIGURE_DEPENDS "${src}/msg/*.msg")
    file(GLOB srvs CONFIGURE_DEPENDS "${src}/srv/*.srv")
    file(GLOB actions CONFIGURE_DEPENDS "${src}/action/*.action")
    list(APPEND all_defs ${msgs} ${srvs})
    foreach(f IN LISTS msgs)
      get_filename_component(name "${f}" NAME_WE)
      list(APPEND jobs "${pkg}|${f}|msg")
      list(APPEND types "${pkg}/${name}:msg")
    endforeach()
    foreach(f IN LISTS srvs)
      get_filename_component(name "${f}" NAME_WE)
      list(APPEND jobs "${pkg}|${f}|srv")
      list(APPEND types "${pkg}/${name}:srv" "${pkg}/${name}Request:srv" "${pkg}/${name}Response:srv")
    endforeach()
    foreach(f IN LISTS actions)
      get_filename_component(name "${f}" NAME_WE)
      set(out_dir "${gen_root}/${pkg}/msg")
      set(expanded "")
      foreach(suffix Action ActionGoal ActionResult ActionFeedback Goal Result Feedback)
        list(APPEND expanded "${out_dir}/${name}${suffix}.msg")
        list(APPEND jobs "${pkg}|${out_dir}/${name}${suffix}.msg|action-msg")
        list(APPEND types "${pkg}/${name}${suffix}:action-msg")
      endforeach()
      add_custom_command(
        OUTPUT ${expanded}
        COMMAND ${_mechsim_ros_python_env} ${MECHSIM_ROS_PYTHON} ${MECHSIM_GENACTION_SCRIPT} "${f}" -o "${out_dir}"
        DEPENDS "${f}" "${MECHSIM_GENACTION_SCRIPT}"
        COMMENT "Expanding ROS action ${pkg}/${name}"
        VERBATIM)
      list(APPEND all_defs ${expanded})
    endforeach()
  endforeach()

  # Pass 2: one gencpp run per definition file.
  set(headers "")
  foreach(job IN LISTS jobs)
    string(REPLACE "|" ";" parts "${job}")
    list(GET parts 0 pkg)
    list(GET parts 1 file)
    list(GET parts 2 kind)
    get_filename_component(name "${file}" NAME_WE)
    set(out_dir "${include_root}/${pkg}")
    if(kind STREQUAL "srv")
      set(outputs "${out_dir}/${name}.h" "${out_dir}/${name}Request.h" "${out_dir}/${name}Response.h")
      set(template "${MECHSIM_GENCPP_TEMPLATE_DIR}/srv.h.template")
    else()
      set(outputs "${out_dir}/${name}.h")
      set(template "${MECHSIM_GENCPP_TEMPLATE_DIR}/msg.h.template")
    endif()
    add_custom_command(
      OUTPUT ${outputs}
      COMMAND ${_mechsim_ros_python_env} ${MECHSIM_ROS_PYTHON} ${MECHSIM_GENCPP_SCRIPT} "${file}"
              ${iflags} -p ${pkg} -o "${out_dir}" -e "${MECHSIM_GENCPP_TEMPLATE_DIR}"
      DEPENDS ${all_defs} "${MECHSIM_GENCPP_SCRIPT}" "${template}"
              "${MECHSIM_GENCPP_TEMPLATE_DIR}/msg.h.template"
      COMMENT "Generating C++ header for ROS type ${pkg}/${name}"
      VERBATIM)
    list(APPEND headers ${outputs})
  endforeach()

  # Python modules for Debian's rostopic/rosservice/rosmsg (genpy), laid out as importable
  # packages under <build>/ros_python: <pkg>/__init__.py, <pkg>/msg/{_Name.py,__init__.py},
  # <pkg>/srv/..., plus a package.xml stub per package so rospack (rosmsg, roslib's
  # load_manifest fallback) finds them when <build>/ros_python is on ROS_PACKAGE_PATH.
  if(MECHSIM_GENPY_MSG_SCRIPT AND MECHSIM_GENPY_SRV_SCRIPT)
    set(py_root "${PROJECT_BINARY_DIR}/ros_python")
    set(py_outputs "")
    set(py_dirs "")   # "pkg/msg" or "pkg/srv" that get an __init__.py
    foreach(job IN LISTS jobs)
      string(REPLACE "|" ";" parts "${job}")
      list(GET parts 0 pkg)
      list(GET parts 1 file)
      list(GET parts 2 kind)
      get_filename_component(name "${file}" NAME_WE)
      if(kind STREQUAL "srv")
        set(sub srv)
        set(script "${MECHSIM_GENPY_SRV_SCRIPT}")
      else()
        set(sub msg)
        set(script "${MECHSIM_GENPY_MSG_SCRIPT}")
      endif()
      set(out "${py_root}/${pkg}/${sub}/_${name}.py")
      add_custom_command(
        OUTPUT "${out}"
        COMMAND ${_mechsim_ros_python_env} ${MECHSIM_ROS_PYTHON} ${script} "${file}"
                ${iflags} -p ${pkg} -o "${py_root}/${pkg}/${sub}"
        DEPENDS ${all_defs} "${script}"
        COMMENT "Generating Python module for ROS type ${pkg}/${name}"
        VERBATIM)
      # The definition beside its module: rosmsg/rossrv read <pkg>/{msg,srv}/Name.{msg,srv}
      # (dangling until the build expands the actions).
      file(MAKE_DIRECTORY "${py_root}/${pkg}/${sub}")
      file(CREATE_LINK "${file}" "${py_root}/${pkg}/${sub}/${name}.${sub}" SYMBOLIC)
      list(APPEND py_outputs "${out}")
      list(APPEND py_dirs "${pkg}/${sub}")
      list(APPEND py_modules_${pkg}_${sub} "${out}")
    endforeach()
    list(REMOVE_DUPLICATES py_dirs)
    set(py_inits "")
    foreach(dir IN LISTS py_dirs)
      string(REPLACE "/" "_" key "${dir}")
      add_custom_command(
        OUTPUT "${py_root}/${dir}/__init__.py"
        COMMAND ${_mechsim_ros_python_env} ${MECHSIM_ROS_PYTHON} ${MECHSIM_GENPY_MSG_SCRIPT}
                --initpy -o "${py_root}/${dir}"
        DEPENDS ${py_modules_${key}}
        COMMENT "Generating Python package ${dir}"
        VERBATIM)
      list(APPEND py_inits "${py_root}/${dir}/__init__.py")
    endforeach()
    foreach(pkg IN LISTS packages)
      file(CONFIGURE OUTPUT "${py_root}/${pkg}/__init__.py" CONTENT "" @ONLY)
      file(CONFIGURE OUTPUT "${py_root}/${pkg}/package.xml" CONTENT
"<?xml version=\"1.0\"?>
<!-- Generated by cmake/MechsimRos.cmake: lets rospack find mechsim's Python message modules. -->
<package format=\"2\">
  <name>${pkg}</name>
  <version>0.0.0</version>
  <description>${pkg} as generated by mechsim (definitions in src/ros/msgs/${pkg})</description>
  <maintainer email=\"mechsim@example.invalid\">mechsim</maintainer>
  <license>BSD</license>
</package>
" @ONLY)
    endforeach()
    add_custom_target(${target}_python ALL DEPENDS ${py_outputs} ${py_inits})
  else()
    message(STATUS "mechsim: python3-genpy not found, no Python message modules (ros_python)")
  endif()

  add_custom_target(${target}_headers DEPENDS ${headers})
  add_library(${target} INTERFACE)
  target_include_directories(${target} SYSTEM INTERFACE "${include_root}")
  target_link_libraries(${target} INTERFACE PkgConfig::MECHSIM_ROSCPP_SERIALIZATION)
  # Interface-library dependencies are followed by every target that links it.
  add_dependencies(${target} ${target}_headers)
  set(${target}_TYPES ${types} PARENT_SCOPE)
endfunction()

# mechsim_ros_write_md5_table(OUTPUT <header> TYPES <pkg/Name:kind ...>)
# Writes a header with mechsim::ros::generatedTypeChecksums(): for every listed type, its name,
# kind, and the datatype and MD5 that its C++ header reports through the ROS traits (services
# through service_traits). C++ cannot enumerate types, so this list is what a test iterates.
function(mechsim_ros_write_md5_table)
  cmake_parse_arguments(ARG "" "OUTPUT" "TYPES" ${ARGN})
  set(includes "")
  set(rows "")
  foreach(entry IN LISTS ARG_TYPES)
    string(REPLACE ":" ";" parts "${entry}")
    list(GET parts 0 type)
    list(GET parts 1 kind)
    string(REPLACE "/" "::" cxx "${type}")
    string(APPEND includes "#include <${type}.h>\n")
    # A service's own row uses service_traits, its Request/Response parts message_traits. The
    # name alone cannot tell them apart (gazebo_msgs/JointRequest is a service): a part is a
    # name whose stem without the suffix is itself a listed service.
    set(traits "message_traits")
    if(kind STREQUAL "srv")
      set(traits "service_traits")
      if(type MATCHES "^(.*)(Request|Response)$")
        if("${CMAKE_MATCH_1}:srv" IN_LIST ARG_TYPES)
          set(traits "message_traits")
        endif()
      endif()
    endif()
    string(APPEND rows "      {\"${type}\", \"${kind}\", ::ros::${traits}::DataType< ::${cxx}>::value(),\n"
                       "       ::ros::${traits}::MD5Sum< ::${cxx}>::value()},\n")
  endforeach()
  list(LENGTH ARG_TYPES count)
  set(content "// Generated by cmake/MechsimRos.cmake (mechsim_ros_write_md5_table); do not edit.
#pragma once
#include <string>
#include <vector>

${includes}
namespace mechsim::ros {

// One ROS type mechsim builds against, with what its generated header reports.
struct TypeChecksum {
  std::string type;      // pkg/Name as listed in CMake
  std::string kind;      // msg, srv or action-msg
  std::string datatype;  // DataType trait of the header
  std::string md5;       // MD5Sum trait of the header (32 hex digits)
};

// The ${count} types listed at configure time.
inline std::vector<TypeChecksum> generatedTypeChecksums() {
  return {
${rows}  };
}

}  // namespace mechsim::ros
")
  file(CONFIGURE OUTPUT "${ARG_OUTPUT}" CONTENT "${content}" @ONLY)
endfunction()
