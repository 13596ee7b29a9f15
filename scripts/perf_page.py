#!/usr/bin/env python3
"""The figures of docs/performance.md ("All robots in one run"), measured in one run of this script.

Runs `mechsim bench` on each robot (the PR2 in the empty world; the CC8 in the empty world and on
the Mars Yard) without sensors, with its usual sensors (lasers, IMUs, contacts; cameras render only
when asked) and with its cameras rendering at their rates (the CC8's ZED2 set at 1280x720 and at
640x360), then scripts/xacro_bench.py, and prints Markdown tables: bare step and full tick (thread
CPU time, timed in alternating blocks on the same states), their ratio, the real-time factor (CPU,
and wall-clock where cameras render on other threads), start-up, and the command of each row.

Usage: scripts/perf_page.py [--build build/release] [--python-xacro DIR] [--seconds S]
"""
import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

PR2 = ["robots/pr2/urdf/pr2.urdf.xacro", "--package", "mechsim_pr2=robots/pr2",
       "--controllers", "robots/pr2/config/controllers.yaml", "--namespace", "pr2"]
CC8 = ["robots/cc8/urdf/cc8.urdf.xacro", "--package", "mechsim_cc8=robots/cc8",
       "--controllers", "robots/cc8/config/controllers.yaml"]
YARD = ["--world", "mars_yard_2024"]


def cases(seconds):
    cams = str(max(1.0, seconds / 5))  # rendering is slow on a CPU: fewer simulated seconds
    s = str(seconds)
    return [
        ("PR2", "no sensors", PR2 + ["--sensors", "none", "--seconds", s]),
        ("PR2", "usual sensors (2 lasers, 6 contacts, IMU)", PR2 + ["--seconds", s]),
        ("PR2", "+ its 7 cameras", PR2 + ["--sensors", "cameras", "--seconds", cams]),
        ("CC8, flat", "no sensors", CC8 + ["--sensors", "none", "--seconds", s]),
        ("CC8, flat", "usual sensors (IMU)", CC8 + ["--seconds", s]),
        ("CC8, flat", "+ ZED2 set 1280x720 15 Hz", CC8 + ["--sensors", "cameras", "--seconds", cams]),
        ("CC8, flat", "+ ZED2 set 640x360 15 Hz", CC8 + ["--sensors", "cameras", "--camera-width", "640", "--seconds", cams]),
        ("CC8, Mars Yard", "no sensors", CC8 + YARD + ["--sensors", "none", "--seconds", s]),
        ("CC8, Mars Yard", "usual sensors (IMU)", CC8 + YARD + ["--seconds", s]),
        ("CC8, Mars Yard", "+ ZED2 set 1280x720 15 Hz", CC8 + YARD + ["--sensors", "cameras", "--seconds", cams]),
        ("CC8, Mars Yard", "+ ZED2 set 640x360 15 Hz",
         CC8 + YARD + ["--sensors", "cameras", "--camera-width", "640", "--seconds", cams]),
    ]


def number(pattern, text, group=1):
    m = re.search(pattern, text)
    if not m:
        raise RuntimeError("no match for %r in:\n%s" % (pattern, text))
    return float(m.group(group))


def bench(build, argv):
    out = subprocess.run([os.path.join(build, "bin", "mechsim"), "bench"] + argv, cwd=ROOT, check=True,
                         capture_output=True, text=True).stdout
    r = {
        "bare": number(r"bare physics step: +[0-9]+ steps/s \(([0-9.]+) us\)", out),
        "full": number(r"full tick: +[0-9]+ steps/s \(([0-9.]+) us\)", out),
        "rtf": number(r"real-time factor: +([0-9.]+)", out),
        "proc": number(r"full tick, process: ([0-9.]+) us CPU", out),
        "wall": number(r"us CPU \(all threads\), ([0-9.]+) us wall", out),
        "rtf_wall": number(r"real-time factor ([0-9.]+) \(wall\)", out),
        "start_wall": number(r"\n  total +([0-9.]+) +([0-9.]+)", out, 1),
        "start_cpu": number(r"\n  total +([0-9.]+) +([0-9.]+)", out, 2),
        "memory": number(r"peak memory at the first tick: ([0-9.]+) MB", out),
    }
    if "stage budget" in out:
        stages = {}
        for name in ("scene", "prep", "draw", "read", "convert", "resample", "noise", "points"):
            stages[name] = number(r"\n  %s +([0-9.]+) +([0-9.]+)" % name, out)
        r["stages"] = stages
    return r


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--python-xacro", help="folder holding ROS's Python `xacro` package (scripts/xacro_bench.py)")
    parser.add_argument("--seconds", type=float, default=5.0, help="simulated seconds per measurement without cameras")
    args = parser.parse_args()

    rows = []
    for robot, what, argv in cases(args.seconds):
        rows.append((robot, what, argv, bench(args.build, argv)))
        print("measured: %s, %s" % (robot, what), file=sys.stderr)
    load = os.getloadavg()[0]

    print("| robot | sensors | bare step | full tick | full / bare | RTF (CPU) | full tick, wall | RTF (wall) | start-up (wall, CPU) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for robot, what, argv, r in rows:
        print("| %s | %s | %.1f µs | %.1f µs | %.2f | %.2f | %.1f µs | %.2f | %.0f ms, %.0f ms |" % (
            robot, what, r["bare"], r["full"], r["full"] / r["bare"], r["rtf"], r["wall"], r["rtf_wall"],
            r["start_wall"], r["start_cpu"]))
    print()
    print("Cameras' stage budget (wall ms per simulated second; `draw` is the render itself):")
    print()
    print("| robot | cameras | draw | read | convert | resample | noise | points | scene + prep | all but draw / draw |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for robot, what, argv, r in rows:
        st = r.get("stages")
        if not st:
            continue
        rest = sum(v for k, v in st.items() if k != "draw")
        print("| %s | %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.2f |" % (
            robot, what, st["draw"], st["read"], st["convert"], st["resample"], st["noise"], st["points"],
            st["scene"] + st["prep"], rest / st["draw"]))
    print()
    print("Commands (from the repository root, `mechsim` = %s/bin/mechsim):" % os.path.relpath(args.build, ROOT))
    print()
    for robot, what, argv, r in rows:
        print("- %s, %s: `mechsim bench %s`" % (robot, what, " ".join(argv)))
    print()
    print("load average %.1f on %d cores at the end of the table" % (load, os.cpu_count()))
    sys.stdout.flush()
    xacro = [sys.executable, os.path.join(HERE, "xacro_bench.py"), "--build", args.build, "-n", "5"]
    if args.python_xacro:
        xacro += ["--python-xacro", args.python_xacro]
    print()
    print("```")
    sys.stdout.flush()
    subprocess.run(xacro, check=True)
    print("```")
    return 0


if __name__ == "__main__":
    sys.exit(main())
