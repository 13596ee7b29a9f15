#!/usr/bin/env bash
# Shows the simulated CC8 in RViz on a virtual X display and saves a screenshot:
#   scripts/rviz_screenshot.sh [OUT.png] [BUILD_DIR] [SECONDS]
# defaults: /tmp/mechsim_cc8_rviz.png, build/release, 20 s of settling before the shot.
# Runs `roslaunch mechsim_cc8 cc8_display.launch sim:=true` (mechsim_node + spawner + RViz) with
# its own master on a free loopback port, under Xvfb (software OpenGL), then `import` (ImageMagick)
# grabs the screen. Everything it started is stopped on exit, also on failure or Ctrl-C.
# Needs `scripts/install-deps.sh --with-ros` (rviz, xvfb, imagemagick) and a built tree.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
out=${1:-/tmp/mechsim_cc8_rviz.png}
build=$(cd "${2:-build/release}" && pwd)
settle=${3:-20}

for tool in Xvfb import roslaunch rviz; do
  command -v "$tool" >/dev/null || { echo "rviz_screenshot.sh: $tool not found (scripts/install-deps.sh --with-ros)" >&2; exit 1; }
done
[[ -x "$build/ros_package/mechsim/mechsim_node" ]] ||
  { echo "rviz_screenshot.sh: no mechsim_node in $build/ros_package/mechsim (build with MECHSIM_ROS)" >&2; exit 1; }

work=$(mktemp -d /tmp/mechsim_rviz.XXXXXX)
xvfb_pid="" launch_pid=""
cleanup() {
  set +e
  if [[ -n "$launch_pid" ]] && kill -INT "$launch_pid" 2>/dev/null; then
    for _ in $(seq 100); do kill -0 "$launch_pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$launch_pid" 2>/dev/null
  fi
  if [[ -n "$xvfb_pid" ]]; then kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; fi
}
trap cleanup EXIT INT TERM

# A free display (Xvfb writes its number to fd 3) and a free port for the master.
exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 100); do [[ -s "$work/display" ]] && break; sleep 0.1; done
display=":$(head -1 "$work/display")"
port=""
for candidate in $(shuf -i 20000-40000 -n 20); do
  if ! (exec 4<>"/dev/tcp/127.0.0.1/$candidate") 2>/dev/null; then port=$candidate; break; fi
done
[[ -n "$port" ]] || { echo "rviz_screenshot.sh: no free port" >&2; exit 1; }

export DISPLAY=$display LIBGL_ALWAYS_SOFTWARE=1
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_IP=127.0.0.1 ROS_HOSTNAME=127.0.0.1
export ROS_PACKAGE_PATH="$repo/robots:$build/ros_package" ROS_LOG_DIR="$work/log" ROS_HOME="$work"
unset PYTHONPATH PYTHONHOME
PATH="/usr/bin:$PATH" roslaunch -p "$port" mechsim_cc8 cc8_display.launch sim:=true >"$work/launch.log" 2>&1 &
launch_pid=$!
echo "rviz_screenshot.sh: RViz on $display, master on port $port, logs in $work; waiting ${settle} s"
sleep "$settle"
kill -0 "$launch_pid" 2>/dev/null || { echo "rviz_screenshot.sh: roslaunch exited:" >&2; tail -30 "$work/launch.log" >&2; exit 1; }
import -display "$display" -window root "$out"
echo "rviz_screenshot.sh: wrote $out"
