#!/usr/bin/env python3
"""Whole-process xacro timings: mechsim's `xacro` and `mechsim xacro` against ROS's Python xacro.

Each program expands the same file (default: the PR2 of ../shared) to a file, as roslaunch runs
xacro: a fresh process each time (start-up, dynamic linking, reading, expanding, writing). The
programs run in turns (A B C A B C ...) so a machine whose load changes treats them alike; the
figure per program is the best of N runs (wall time, and CPU time user + system from wait4), and
the ratios are Python's best over each program's best, from the same run.

ROS's Python xacro is not a Debian package: give the folder holding its `xacro` Python package
(ros/xacro's src/ at a Noetic release) with --python-xacro; it runs with Debian's python3 and
python3-roslaunch/python3-rospkg (install-deps.sh --with-ros), finding packages through
ROS_PACKAGE_PATH. Without it only mechsim's two programs are timed.

Usage: scripts/xacro_bench.py [--build build/release] [--python-xacro DIR] [-n 5] [FILE ...]
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run_once(argv, env):
    """Wall time and CPU time (user + sys) of one process, s; raises on failure."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise RuntimeError("%s failed (exit %d): %s" % (" ".join(argv), proc.returncode, err.strip()))
    return wall, usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("files", nargs="*", help="xacro files (default: ../shared's PR2)")
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--shared", default=os.path.join(os.path.dirname(ROOT), "shared"))
    parser.add_argument("--python-xacro", help="folder holding ROS's Python `xacro` package")
    parser.add_argument("-n", type=int, default=5, help="runs per program (best of)")
    args = parser.parse_args()

    robots = os.path.join(args.shared, "robots")
    files = args.files or [os.path.join(robots, "pr2_description", "robots", "pr2.urdf.xacro")]
    env = dict(os.environ)
    env["ROS_PACKAGE_PATH"] = robots + (":" + env["ROS_PACKAGE_PATH"] if env.get("ROS_PACKAGE_PATH") else "")
    out_dir = tempfile.mkdtemp(prefix="xacro_bench_")
    bin_dir = os.path.join(args.build, "bin")
    for f in files:
        out = os.path.join(out_dir, "out.urdf")
        programs = [("bin/xacro", [os.path.join(bin_dir, "xacro"), f, "-o", out]),
                    ("mechsim xacro", [os.path.join(bin_dir, "mechsim"), "xacro", f, "-o", out])]
        if args.python_xacro:
            runner = os.path.join(out_dir, "run_xacro.py")
            with open(runner, "w") as r:
                r.write("import sys\nsys.path.insert(0, %r)\nimport xacro\nxacro.main()\n" % args.python_xacro)
            programs.append(("python xacro", ["/usr/bin/python3", runner, f, "-o", out]))
        best = {name: [float("inf"), float("inf")] for name, _ in programs}
        for _ in range(args.n):
            for name, argv in programs:
                wall, cpu = run_once(argv, env)
                best[name][0] = min(best[name][0], wall)
                best[name][1] = min(best[name][1], cpu)
        load = os.getloadavg()[0]
        print("%s (best of %d, load average %.1f on %d cores)" % (f, args.n, load, os.cpu_count()))
        ref = best.get("python xacro")
        for name, _ in programs:
            wall, cpu = best[name]
            line = "  %-14s wall %8.1f ms  cpu %8.1f ms" % (name, 1e3 * wall, 1e3 * cpu)
            if ref and name != "python xacro":
                line += "  python/this: wall %.1fx  cpu %.1fx" % (ref[0] / wall, ref[1] / max(cpu, 1e-4))
            print(line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
