#!/usr/bin/env bash
# The ROS 2 layer's cost, as a ratio in one run: the CC8 on the Mars Yard as fast as it goes, with
# `mechsim ros2` publishing its topics to a Cyclone DDS peer subscribed to them (/clock every tick,
# /tf, /tf_static, joint states, the rover drive's odometry, the ZED2 IMU) and without publishing,
# in alternating blocks (`mechsim ros2 --bench-rtf`). Runs in a private network namespace (root;
# discovery never leaves it).
#   scripts/ros2_rtf_bench.sh [BUILD_DIR] [SECONDS]      (default build/release, 20)
# MECHSIM_ROS2_BENCH_ARGS adds `mechsim ros2` arguments (e.g. --clock-rate 100), MECHSIM_ROS2_BENCH_SUBS
# replaces the peer's --sub arguments.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
seconds=${2:-20}
if [[ $(id -u) -ne 0 ]]; then echo "ros2_rtf_bench.sh: needs root for its network namespace (unshare -n)" >&2; exit 1; fi
exec unshare -n bash -s "$build" "$seconds" <<'SCRIPT'
set -euo pipefail
build=$1 seconds=$2
ip link set lo up multicast on
ip route add 224.0.0.0/4 dev lo
export CYCLONEDDS_URI='<CycloneDDS><Domain><General><Interfaces><NetworkInterface name="lo" multicast="true"/></Interfaces></General></Domain></CycloneDDS>'
log=$(mktemp -d)
subs=${MECHSIM_ROS2_BENCH_SUBS:-"--sub /clock=clock --sub /tf=tf --sub /tf_static=tf_static --sub /cc8/joint_states=joint_state
  --sub /cc8/rover_drive_controller/odom=odometry --sub /cc8/zed2/imu/data=imu"}
# shellcheck disable=SC2086
# The peer counts without decoding, in a session of its own (its CPU is not the layer's: the
# kernel's autogroup would otherwise share one CPU slice between it and mechsim).
setsid "$build/bin/cyclone_peer_jazzy" --count-only --seconds $((seconds * 4 + 120)) $subs > "$log/peer.log" 2>&1 &
peer=$!
"$build/bin/mechsim" ros2 robots/cc8/urdf/cc8.urdf.xacro --package mechsim_cc8=robots/cc8 \
  --controllers robots/cc8/config/controllers.yaml --world mars_yard_2024 --bench-rtf "$seconds" ${MECHSIM_ROS2_BENCH_ARGS:-} | grep -v "topic "
kill "$peer" 2>/dev/null || true
wait "$peer" 2>/dev/null || true
rm -rf "$log"
SCRIPT
