#!/usr/bin/env bash
# Soak: long runs of both robots with `mechsim run --timing 60`, then a table and a plot of tick
# time and resident memory per simulated minute.
#   CC8: drives the Mars Yard's main route out and back, a new route every 60 s.
#   PR2: the right arm to random reachable goals every 4 s (seeded), the gripper opening and
#        closing every 6 s, the base forward and back every 10 s, both lasers and the IMU on.
# Usage: scripts/soak.sh [MINUTES of simulated time, default 60] [OUT, default out/soak] [BUILD]
# Writes OUT/<robot>/timing.csv (+ the run's report), OUT/soak.md and OUT/soak.png.
set -euo pipefail
cd "$(dirname "$0")/.."
minutes=${1:-60}
out=${2:-out/soak}
build=${3:-build/release}
mechsim="$build/bin/mechsim"
[[ -x "$mechsim" ]] || { echo "soak.sh: no $mechsim (scripts/build.sh release first)" >&2; exit 1; }
[[ "$minutes" =~ ^[0-9]+$ && "$minutes" -ge 2 ]] || { echo "soak.sh: MINUTES must be a whole number >= 2, got '$minutes'" >&2; exit 1; }
mkdir -p "$out"
root=$(pwd)
seconds=$((minutes * 60))

# The scenarios, written next to the results (absolute paths: they refer to the robots here).
/usr/bin/python3 - "$root" "$out" "$seconds" <<'PY'
import random, sys
root, out, seconds = sys.argv[1], sys.argv[2], int(sys.argv[3])
route = [[-13.0, -0.5], [-11.0, -2.2], [-6.0, -1.9], [-2.0, -2.8], [2.0, -3.2], [6.0, -1.0]]
back = list(reversed(route[:-1])) + [[-16.0, 0.65]]
with open(f"{out}/cc8_soak.yaml", "w") as f:
    f.write(f"""name: cc8_soak
robot: {{description: {root}/robots/cc8/urdf/cc8.urdf.xacro, packages: {{mechsim_cc8: {root}/robots/cc8}}}}
world: {{name: mars_yard_2024, seed: 2024}}
spawn: {{x: -16.25, y: 0.65, z: 0.05, yaw: 0}}
controllers:
  file: {root}/robots/cc8/config/controllers.yaml
  namespace: cc8
  start: [joint_state_controller, rover_drive_controller]
duration: {seconds}
record_rate: 1
timeline:
""")
    for k, t in enumerate(range(0, seconds, 60)):
        wps = route if k % 2 == 0 else back
        f.write(f"  - {{at: {t + 0.5}, controller: rover_drive_controller, route: {{waypoints: {wps}, speed: 0.45, "
                "tolerance: 0.4, lookahead: 1.0, max_yaw_rate: 0.5}}\n")
    f.write("checks:\n  - {upright: {max_tilt_deg: 35}}\n")

rng = random.Random(2024)
# Around the arm's tucked-forward pose, inside every joint's soft limits.
lo = [-0.6, -0.2, -0.8, -1.2, -0.8, -1.0, -1.0]
hi = [0.2, 0.5, 0.2, -0.3, 0.8, -0.2, 1.0]
joints = ["r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint", "r_elbow_flex_joint",
          "r_forearm_roll_joint", "r_wrist_flex_joint", "r_wrist_roll_joint"]
events = []
for t in range(0, seconds, 4):
    goal = [round(rng.uniform(a, b), 3) for a, b in zip(lo, hi)]
    events.append((t + 0.2, f"{{at: {t + 0.2}, controller: r_arm_controller, trajectory: {{joints: {joints}, "
                            f"points: [{{time: 2.0, positions: {goal}, velocities: [0, 0, 0, 0, 0, 0, 0]}}]}}}}"))
for k, t in enumerate(range(0, seconds, 6)):
    events.append((t + 0.3, f"{{at: {t + 0.3}, controller: r_gripper_controller, gripper: "
                            f"{{position: {0.08 if k % 2 == 0 else 0.0}, max_effort: 50}}}}"))
for k, t in enumerate(range(0, seconds, 10)):
    vx = [0.2, 0.0, -0.2, 0.0][k % 4]
    events.append((t + 0.4, f"{{at: {t + 0.4}, controller: base_controller, twist: {{vx: {vx}}}}}"))
events.sort()
with open(f"{out}/pr2_soak.yaml", "w") as f:
    f.write(f"""name: pr2_soak
robot: {{description: {root}/robots/pr2/urdf/pr2.urdf.xacro, packages: {{mechsim_pr2: {root}/robots/pr2}}}}
world: {{name: empty}}
spawn: {{x: 0, y: 0, z: 0.01, yaw: 0}}
controllers:
  file: {root}/robots/pr2/config/controllers.yaml
  namespace: pr2
  start: [r_arm_controller, l_arm_controller, torso_controller, head_traj_controller, base_controller, base_odometry,
          r_gripper_controller, l_gripper_controller, laser_tilt_controller]
duration: {seconds}
record_rate: 1
timeline:
""")
    for _, e in events:
        f.write(f"  - {e}\n")
    f.write("checks:\n  - {upright: {max_tilt_deg: 10}}\n")
PY

for robot in cc8 pr2; do
  echo "soak: $robot, $seconds s of simulated time" >&2
  "$mechsim" run "$out/${robot}_soak.yaml" -o "$out/$robot" --no-plots --timing 60 > "$out/$robot.log" 2>&1 || {
    echo "soak.sh: the $robot run failed (see $out/$robot.log):" >&2
    tail -5 "$out/$robot.log" >&2
    exit 1
  }
done

# Table: per 10 simulated minutes, the median of the per-minute p50s and the largest p99 and RSS;
# RSS growth between minute 10 and the end (minute 60 in a full soak).
/usr/bin/python3 - "$out" "$minutes" <<'PY'
import csv, sys
out, minutes = sys.argv[1], int(sys.argv[2])
lines = ["| robot | minutes | tick p50 (us) | tick p99 (us), worst minute | CPU per sim minute (s) | RSS (MB) |", "|---|---|---|---|---|---|"]
growth = []
for robot in ["cc8", "pr2"]:
    rows = list(csv.DictReader(open(f"{out}/{robot}/timing.csv")))
    for start in range(0, len(rows), 10):
        block = rows[start:start + 10]
        p50 = sorted(float(r["tick_p50_us"]) for r in block)[len(block) // 2]
        p99 = max(float(r["tick_p99_us"]) for r in block)
        cpu = sum(float(r["cpu_s"]) for r in block) / len(block)
        rss = max(int(r["rss_kb"]) for r in block) / 1024
        lines.append(f"| {robot} | {start + 1}-{start + len(block)} | {p50:.1f} | {p99:.1f} | {cpu:.2f} | {rss:.1f} |")
    first = int(rows[min(9, len(rows) - 1)]["rss_kb"])
    last = int(rows[-1]["rss_kb"])
    growth.append(f"{robot}: RSS {first / 1024:.1f} MB at minute {min(10, len(rows))}, {last / 1024:.1f} MB at minute "
                  f"{len(rows)}: {100.0 * (last - first) / first:+.2f} %")
summary = [l for l in open(f"{out}/cc8.log") if l.startswith(("distance", "did not", "  PASS", "  FAIL"))]
summary += [l for l in open(f"{out}/pr2.log") if l.startswith(("distance", "did not", "  PASS", "  FAIL"))]
import json
goals = json.load(open(f"{out}/pr2/summary.json")).get("trajectory_goals", [])
ok = sum(1 for g in goals if g.get("result") == "SUCCESSFUL")
summary.append(f"PR2 arm goals: {ok} of {len(goals)} SUCCESSFUL\n")
with open(f"{out}/soak.md", "w") as f:
    f.write("\n".join(lines) + "\n\n" + "\n".join(growth) + "\n\n" + "".join(summary))
print(open(f"{out}/soak.md").read())
PY

if command -v gnuplot > /dev/null; then
  gnuplot <<GP
set terminal pngcairo size 1000,700 font ",10"
set output "$out/soak.png"
set datafile separator ","
set key top left
set multiplot layout 2,1 title "mechsim soak: $minutes min of simulated time per robot"
set ylabel "tick time (us)"
set logscale y
plot "$out/cc8/timing.csv" using (\$1/60):3 skip 1 with linespoints title "CC8 p50", \
     "$out/cc8/timing.csv" using (\$1/60):4 skip 1 with lines title "CC8 p99", \
     "$out/pr2/timing.csv" using (\$1/60):3 skip 1 with linespoints title "PR2 p50", \
     "$out/pr2/timing.csv" using (\$1/60):4 skip 1 with lines title "PR2 p99"
unset logscale y
set ylabel "resident memory (MB)"
set xlabel "simulated time (min)"
plot "$out/cc8/timing.csv" using (\$1/60):(\$8/1024) skip 1 with linespoints title "CC8", \
     "$out/pr2/timing.csv" using (\$1/60):(\$8/1024) skip 1 with linespoints title "PR2"
unset multiplot
GP
  echo "plot: $out/soak.png"
fi
