#!/usr/bin/env bash
# The CC8's base yaw while crabbing at 45 degrees, heading hold on the odometry's yaw (wheels) and
# on the ZED2 IMU's, in the shipped crab scenarios (left and right on flat ground, the Mars Yard):
# runs the six scenarios and draws docs/images/cc8_crab_heading_source.png (robots/cc8/README.md).
# The right-hand runs are crab_45 with vy and the direction check negated, as the Cc8Crab test runs them.
# Usage: scripts/crab_heading_plot.sh [BUILD (default build/release)] [OUT.png]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-docs/images/cc8_crab_heading_source.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scen=robots/cc8/scenarios
for f in crab_45 crab_45_imu; do
  # The scenario's relative paths are from its own folder: the mirrored copy lives beside it.
  sed -e 's/vy: 0.35355/vy: -0.35355/' -e 's/deg: 45,/deg: -45,/' "$scen/$f.yaml" >"$scen/.${f}_right.yaml"
done
trap 'rm -rf "$work" "$scen/.crab_45_right.yaml" "$scen/.crab_45_imu_right.yaml"' EXIT
runs=("crab_45:crab_45 left, wheels" "crab_45_imu:crab_45 left, IMU" ".crab_45_right:crab_45 right, wheels"
      ".crab_45_imu_right:crab_45 right, IMU" "crab_mars_yard:crab_mars_yard, wheels" "crab_mars_yard_imu:crab_mars_yard, IMU")
# One colour per run pair; the wheels' heading hold dashed, the IMU's solid.
colours=('#1f77b4' '#1f77b4' '#d62728' '#d62728' '#2ca02c' '#2ca02c')
plot=()
i=0
for r in "${runs[@]}"; do
  name=${r%%:*}
  title=${r#*:}
  "$build/bin/mechsim" run "$scen/$name.yaml" -o "$work/$name" --no-plots >"$work/$name.log" 2>&1 ||
    { echo "crab_heading_plot.sh: $name did not pass its checks (log: $work/$name.log):" >&2; tail -5 "$work/$name.log" >&2; }
  style="lc rgb '${colours[$i]}' lw 2 dt $([[ $title == *wheels ]] && echo 2 || echo 1)"
  plot+=("'$work/$name/base.csv' using 1:(column('yaw')*180/pi) with lines $style title '$title'")
  i=$((i + 1))
done
gnuplot <<GP
set terminal pngcairo size 900,420 font ',10' noenhanced
set output '$out'
set datafile separator ','
set datafile columnheaders
set key top left
set title "CC8 crabbing at 45 deg (command from 1 to 11 s): heading hold on the odometry's yaw vs the ZED2 IMU's"
set xlabel 'time (s)'
set ylabel 'base yaw (deg)'
set grid
plot $(IFS=,; echo "${plot[*]}")
GP
echo "$out"
