# Source me: sets up a shell for Debian's ROS command-line tools (rostopic, rosservice, rosmsg,
# roslaunch) against a mechsim build folder configured with the ROS layer (MECHSIM_ROS AUTO or ON, ROS installed).
#   . scripts/ros_env.sh [BUILD_DIR]        (default: build/release beside this script)
# Prepends to ROS_PACKAGE_PATH: <repo>/robots (mechsim_cc8, mechsim_pr2), <build>/ros_package
# (the `mechsim` package of the node and spawner) and <build>/ros_python (the generated message
# packages, for rosmsg); prepends <build>/ros_python to PYTHONPATH (rostopic/rosservice import
# <pkg>.msg / <pkg>.srv from there); puts /usr/bin first on PATH so the tools run with Debian's
# python3, not a pyenv/venv one, and <build>/ros_bin before it (`xacro`, which launch files run
# by name, as a ROS install has it on PATH). Sets ROS_DISTRO=noetic (Debian 12 packages Noetic-era
# ROS 1; launch and CMake files test it), ROS_VERSION=1 and ROS_PYTHON_VERSION=3 where unset, as a
# Noetic shell has them.
_mechsim_repo="$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)"
_mechsim_build="$(cd "${1:-$_mechsim_repo/build/release}" 2>/dev/null && pwd)"
if [ -z "$_mechsim_build" ] || [ ! -d "$_mechsim_build/ros_python" ]; then
  echo "ros_env.sh: no ros_python in '${1:-$_mechsim_repo/build/release}': install ROS (scripts/install-deps.sh --with-ros) and build" >&2
  unset _mechsim_repo _mechsim_build
  return 1 2>/dev/null || exit 1
fi
export ROS_PACKAGE_PATH="$_mechsim_repo/robots:$_mechsim_build/ros_package:$_mechsim_build/ros_python${ROS_PACKAGE_PATH:+:$ROS_PACKAGE_PATH}"
export PYTHONPATH="$_mechsim_build/ros_python${PYTHONPATH:+:$PYTHONPATH}"
export PATH="$_mechsim_build/ros_bin:/usr/bin:$PATH"
export ROS_DISTRO="${ROS_DISTRO:-noetic}" ROS_VERSION="${ROS_VERSION:-1}" ROS_PYTHON_VERSION="${ROS_PYTHON_VERSION:-3}"
unset _mechsim_repo _mechsim_build
