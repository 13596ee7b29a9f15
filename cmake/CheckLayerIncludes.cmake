# Checks that every #include under src/ follows ../shared/DESIGN.md's layer map: a layer includes
# itself and the layers below it only; only physics/ includes MuJoCo; only ros/ includes ROS; only
# ros2/ includes DDS.
# Run by CTest (test `layer_includes`) and by hand:
#   cmake -DSRC=src -P cmake/CheckLayerIncludes.cmake
# Tests and benchmarks of a layer count as that layer. A folder under src/ that is not in the
# table below is an error: a new layer is added here when DESIGN.md gains it.

cmake_minimum_required(VERSION 3.22)

if(NOT SRC)
  message(FATAL_ERROR "CheckLayerIncludes: pass -DSRC=<the src folder>")
endif()
get_filename_component(SRC "${SRC}" ABSOLUTE)

# Direct dependencies, as DESIGN.md's "Layers" map draws them (the arrows).
set(deps_description "")
set(deps_mechanism description)
set(deps_control mechanism)
set(deps_controllers control)
set(deps_physics description)
set(deps_sensors physics description)
set(deps_sim physics sensors controllers)
set(deps_batch sim)
set(deps_live sim sensors)
# web/: `mechsim view`, the replay page's server and export (the replay half of live/'s row).
set(deps_web sim)
# bridge/: the Gazebo world and controller-manager API both ROS bindings map their messages onto.
set(deps_bridge sim sensors controllers live)
set(deps_ros bridge sim sensors controllers live)
# ros2/: ROS 2 on the wire (DDS), a binding of bridge/ as ros/ is.
set(deps_ros2 bridge sim sensors controllers live)
set(deps_apps description mechanism control controllers physics sensors sim batch live web bridge ros ros2)
set(layers description mechanism control controllers physics sensors sim batch live web bridge ros ros2 apps)

# What each layer may include: itself and everything its dependencies reach.
foreach(layer IN LISTS layers)
  set(reach ${layer})
  set(todo ${deps_${layer}})
  while(todo)
    list(POP_FRONT todo next)
    if(NOT next IN_LIST reach)
      list(APPEND reach ${next})
      list(APPEND todo ${deps_${next}})
    endif()
  endwhile()
  set(allowed_${layer} ${reach})
  list(JOIN reach ", " allowed_text_${layer})
endforeach()

# Third-party headers only one layer may include (by the include's first path component).
set(ros_roots ros actionlib actionlib_msgs control_msgs controller_manager_msgs geometry_msgs
    nav_msgs pr2_controllers_msgs pr2_mechanism_msgs rosgraph_msgs sensor_msgs std_msgs std_srvs
    tf tf2 tf2_msgs tf2_ros topic_tools trajectory_msgs xmlrpcpp)
# DDS: Fast DDS (fastdds, fastrtps, fastcdr), Cyclone DDS (dds, ddsc, idl: the test peers), and
# the ROS 2 message code generated from src/ros2/msgs (mechsim_ros2_msgs).
set(dds_roots fastdds fastrtps fastcdr foonathan dds ddsc idl mechsim_ros2_msgs)

set(violations "")  # one line each
set(count 0)
set(checked 0)
file(GLOB_RECURSE files RELATIVE "${SRC}" "${SRC}/*.cpp" "${SRC}/*.hpp" "${SRC}/*.h")
foreach(rel IN LISTS files)
  string(REGEX MATCH "^[^/]+" layer "${rel}")
  if(NOT layer IN_LIST layers)
    string(APPEND violations "\nsrc/${rel}: src/${layer}/ is not a layer of DESIGN.md's map (add it to cmake/CheckLayerIncludes.cmake)")
    math(EXPR count "${count} + 1")
    continue()
  endif()
  get_filename_component(file_dir "${SRC}/${rel}" DIRECTORY)
  file(STRINGS "${SRC}/${rel}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  math(EXPR checked "${checked} + 1")
  foreach(line IN LISTS lines)
    string(REGEX MATCH "[<\"]([^>\"]+)[>\"]" _ "${line}")
    set(target "${CMAKE_MATCH_1}")
    if(line MATCHES "#[ \t]*include[ \t]*\"")
      # A quoted include: mechsim's own header, from src/ ("layer/...") or beside the file.
      if(EXISTS "${file_dir}/${target}")
        get_filename_component(resolved "${file_dir}/${target}" ABSOLUTE)
        file(RELATIVE_PATH target "${SRC}" "${resolved}")
      endif()
      string(REGEX MATCH "^[^/]+" to "${target}")
      if(to IN_LIST layers AND NOT to IN_LIST allowed_${layer})
        string(APPEND violations "\nsrc/${rel}: includes \"${target}\"; ${layer}/ may include ${allowed_text_${layer}}")
        math(EXPR count "${count} + 1")
      endif()
    else()
      string(REGEX MATCH "^[^/.]+" root "${target}")
      if(root STREQUAL "mujoco" AND NOT layer STREQUAL "physics")
        string(APPEND violations "\nsrc/${rel}: includes <${target}>; only physics/ includes MuJoCo")
        math(EXPR count "${count} + 1")
      elseif(root IN_LIST ros_roots AND NOT layer STREQUAL "ros")
        string(APPEND violations "\nsrc/${rel}: includes <${target}>; only ros/ includes ROS headers")
        math(EXPR count "${count} + 1")
      elseif(root IN_LIST dds_roots AND NOT layer STREQUAL "ros2")
        string(APPEND violations "\nsrc/${rel}: includes <${target}>; only ros2/ includes DDS headers")
        math(EXPR count "${count} + 1")
      endif()
    endif()
  endforeach()
endforeach()

if(count GREATER 0)
  message(FATAL_ERROR "${count} include(s) against the layer map (../shared/DESIGN.md, Layers):${violations}")
endif()
message(STATUS "layer includes: ${checked} files follow the layer map")
