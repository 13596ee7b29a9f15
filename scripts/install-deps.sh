#!/usr/bin/env bash
# Installs every Debian 12 package mechsim needs to build, test and run. Idempotent.
# Usage: scripts/install-deps.sh [--with-ros] [--with-fuzz]
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config git
  libmujoco-dev libqhull-dev libgl-dev libopengl-dev libegl-dev
  liburdfdom-dev liburdfdom-headers-dev libtinyxml2-dev libyaml-cpp-dev libcli11-dev
  libeigen3-dev nlohmann-json3-dev libtiff-dev libpng-dev libassimp-dev
  # src/live: the Foxglove WebSocket server (Boost.Beast and Boost.Asio, header-only).
  libboost-dev
  libsdformat-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox
  # mechsim view: the replay page's HTTP server (Boost.Beast, header-only) and the page's browser
  # test (Debian's Chromium, headless, software WebGL).
  libboost-dev chromium
  # mechsim sweep --slurm and its test (a single-node Slurm started by the test itself).
  slurm-wlm munge
  # The documentation site (scripts/docs.sh) and its test docs_site (mkdocs build --strict):
  # Debian's mkdocs with the Material theme; python3 runs the docs tests (test/docs).
  python3 mkdocs mkdocs-material
)
with_ros=0
for arg in "$@"; do
  case "$arg" in
    --with-ros) with_ros=1 ;;
    # scripts/fuzz.sh: Clang's libFuzzer and sanitizers.
    # libxmlrpcpp-dev: the parameter-server target (xmlrpc_fuzz) without the whole ROS layer.
    --with-fuzz) packages+=(clang libxmlrpcpp-dev) ;;
    *) echo "install-deps: unknown option '$arg' (--with-ros, --with-fuzz)" >&2; exit 2 ;;
  esac
done
if ((with_ros)); then
  # ROS 1 (Noetic-era, as Debian packages it) for src/ros: roscpp and actionlib, the C++ headers
  # of the message packages mechsim exchanges, their .msg definitions under /usr/share/<pkg>/msg
  # (gencpp's include paths), and the generators (genaction.py ships with ros-actionlib-msgs).
  packages+=(ros-core-dev libroscpp-dev libactionlib-dev libtf2-ros-dev
             libstd-msgs-dev libstd-srvs-dev libgeometry-msgs-dev libnav-msgs-dev libsensor-msgs-dev
             libtrajectory-msgs-dev libactionlib-msgs-dev libtf2-msgs-dev libros-rosgraph-msgs-dev
             ros-std-msgs ros-std-srvs ros-geometry-msgs ros-nav-msgs ros-sensor-msgs
             ros-trajectory-msgs ros-actionlib-msgs ros-tf2-msgs ros-rosgraph-msgs
             python3-genmsg python3-gencpp python3-empy
             libtopic-tools-dev
             # gazebo_ros' physics dynamic_reconfigure interface (/gazebo/set_parameters, ...): the
             # server library and its config generator; dynparam for the tests.
             libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
             # Python message modules (<build>/ros_python) for rostopic/rosservice: genpy, and
             # the Debian types the generated ones import.
             python3-genpy python3-std-msgs python3-geometry-msgs python3-trajectory-msgs
             python3-actionlib-msgs
             # The Debian types mechsim_node exchanges, for rostopic echo / rosservice call /
             # rospy (src/ros/test/integration/readme_commands_test.cpp checks this list against
             # the node's includes), actionlib's Python client, the tools (ros-core: roslaunch,
             # rostopic, rosservice, rosparam, ...; rostest) and rosbash for `rosrun`.
             python3-nav-msgs python3-sensor-msgs python3-std-srvs python3-tf2-msgs
             python3-rosgraph-msgs python3-actionlib python3-rostest rosbash
             # mechsim_node's launch files and scripts/rviz_screenshot.sh: RViz under Xvfb.
             rviz xvfb imagemagick
             # Gazebo users' launch files (the gazebo_ros / controller_manager compatibility
             # packages, src/ros/packages) run Debian's robot_state_publisher for TF, and
             # pr2_gazebo's bring-up Debian's image_proc, stereo_image_proc and
             # diagnostic_aggregator (rostest needs every node of a launch file to start; the -dev
             # packages hold diagnostic_aggregator's and stereo_image_proc's package.xml, which roslaunch
             # looks for).
             ros-robot-state-publisher ros-image-proc ros-stereo-image-proc libdiagnostic-aggregator-tools
             libdiagnostic-aggregator-dev libstereo-image-proc-dev
             # stereo_image_proc.launch runs its nodelets through the nodelet tool.
             libnodeletlib-tools
             # src/ros2 (ROS 2 on the wire, no ROS 2 installed): eProsima Fast DDS, the library
             # under rmw_fastrtps_cpp; its tests' peers on Eclipse Cyclone DDS (the library under
             # rmw_cyclonedds_cpp, with its IDL compiler idlc) and `ip` for the private network
             # namespace each test makes.
             libfastrtps-dev libfastcdr-dev cyclonedds-dev cyclonedds-tools libcycloneddsidl0 iproute2)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
install_web() {
# The replay page (web/): node and npm from Debian when the machine has none (a node from
# elsewhere, e.g. NodeSource's, which bundles npm, is kept), then the page's pinned packages
# (web/package-lock.json) into web/node_modules.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  SUDO=""
  if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
  echo "install-deps: installing nodejs npm" >&2
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi
web="$(cd "$(dirname "$0")/.." && pwd)/web"
if [[ ! -f "$web/node_modules/.package-lock.json" || "$web/package-lock.json" -nt "$web/node_modules/.package-lock.json" ]]; then
  echo "install-deps: npm ci in $web" >&2
  (cd "$web" && npm ci --no-audit --no-fund --loglevel=error)
fi
# The ROS 2 layer's @foxglove/ros2 test peer (src/ros2/test/peers/foxglove, its own package-lock).
if ((with_ros)); then
  peer="$(cd "$(dirname "$0")/.." && pwd)/src/ros2/test/peers/foxglove"
  if [[ -f "$peer/package-lock.json" && ( ! -f "$peer/node_modules/.package-lock.json" || "$peer/package-lock.json" -nt "$peer/node_modules/.package-lock.json" ) ]]; then
    echo "install-deps: npm ci in $peer" >&2
    (cd "$peer" && npm ci --no-audit --no-fund --loglevel=error)
  fi
fi
}
if ((${#missing[@]} == 0)); then
  install_web
  exit 0
fi
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
install_web
