#!/usr/bin/env python3
"""How a snapshot suite scales over shards: a synthetic suite (make_suite.py, passing cases with
their own goldens) checked as 1, 2, 4, 8 (and more) shards, the shards run one after another so
that each one's wall time is its own, then merged.

Per shard count it prints the slowest shard's wall time, the mean and the sum over shards (wall
and CPU: user + system of all threads), the balance (largest shard against the mean, in cases and
in time) and the merge time. A least-squares line through every shard run,
wall = start-up + cases x per-case, gives the start-up cost of a shard (process start, Mesa, the
suite file, the first load of each model, writing the reports) and the cost of a case; with the
actual assignment of the suite's names to 100 shards it predicts a 100-worker fleet. Timings
only; nothing is asserted. The machine's load average is printed beside each row.

usage: shard_scale.py URDFSNAP [--cases 1000] [--shards 1,2,4,8] [--work DIR]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MASK = (1 << 64) - 1


def stable_hash(name):
    """The shard assignment's hash (src/common/stable_hash.cpp): FNV-1a 64, SplitMix64 finalizer."""
    h = 0xcbf29ce484222325
    for byte in name.encode():
        h = ((h ^ byte) * 0x100000001b3) & MASK
    h ^= h >> 30
    h = (h * 0xbf58476d1ce4e5b9) & MASK
    h ^= h >> 27
    h = (h * 0x94d049bb133111eb) & MASK
    return h ^ (h >> 31)


def timed(command):
    """Runs `command`; returns its wall seconds and CPU seconds (user + system, all threads)."""
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        sys.exit(f"shard_scale.py: {' '.join(command)} exited {code}: {process.stderr.read().decode()}")
    return seconds, usage.ru_utime + usage.ru_stime


def run_split(urdfsnap, suite, count, work):
    """Checks shards 1..count one after another; returns per-shard (wall, cases, CPU seconds)
    and the merge's wall time."""
    shards, files = [], []
    for index in range(1, count + 1):
        out = os.path.join(work, f"split{count}", f"shard{index}")
        os.makedirs(out)
        files.append(os.path.join(out, "results.json"))
        wall, cpu = timed([urdfsnap, "snapshot", "check", suite, "--shard", f"{index}/{count}",
                      "--results", files[-1], "--junit", os.path.join(out, "junit.xml"),
                      "--report", os.path.join(out, "report")])
        with open(files[-1]) as f:
            cases = json.load(f)["cases"]
        shards.append((wall, len(cases), cpu))
    merged = os.path.join(work, f"split{count}", "merged")
    merge_wall, _ = timed([urdfsnap, "snapshot", "merge", *files, "--report", merged,
                           "--junit", merged + ".xml"])
    return shards, merge_wall


def fit(points):
    """Least-squares line y = a + b x through (x, y) points; returns (a, b)."""
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    b = sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)
    return my - b * mx, b


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("urdfsnap")
    parser.add_argument("--cases", type=int, default=1000)
    parser.add_argument("--shards", default="1,2,4,8")
    parser.add_argument("--work", help="folder for the suite and results (default: temporary, removed)")
    args = parser.parse_args()
    urdfsnap = os.path.abspath(args.urdfsnap)
    work = args.work or tempfile.mkdtemp(prefix="urdfsnap_shard_scale.")
    try:
        suite_dir = os.path.join(work, "suite")
        subprocess.run([sys.executable, os.path.join(HERE, "make_suite.py"), suite_dir,
                        str(args.cases), "--goldens", "own"], check=True, stdout=subprocess.DEVNULL)
        suite = os.path.join(suite_dir, "suite.yaml")
        update, _ = timed([urdfsnap, "snapshot", "update", suite, "--no-shard"])
        print(f"{args.cases} cases (mrm, looks, meshbot at 640x480); goldens made in {update:.1f} s")
        print(f"{'shards':>6} {'slowest':>8} {'mean':>7} {'sum':>7} {'cpu sum':>8} {'cases max/mean':>15}"
              f" {'time max/mean':>14} {'merge':>6} {'load':>5}")
        points, cpu_points = [], []
        for count in (int(c) for c in args.shards.split(",")):
            shards, merge_wall = run_split(urdfsnap, suite, count, work)
            points += [(cases, wall) for wall, cases, _ in shards]
            cpu_points += [(cases, cpu) for _, cases, cpu in shards]
            walls = [wall for wall, _, _ in shards]
            mean_wall = sum(walls) / count
            mean_cases = args.cases / count
            print(f"{count:>6} {max(walls):>7.2f}s {mean_wall:>6.2f}s {sum(walls):>6.1f}s "
                  f"{sum(cpu for _, _, cpu in shards):>7.1f}s "
                  f"{max(c for _, c, _ in shards) / mean_cases:>15.2f} {max(walls) / mean_wall:>14.2f} "
                  f"{merge_wall:>5.2f}s {os.getloadavg()[0]:>5.2f}", flush=True)
            shutil.rmtree(os.path.join(work, f"split{count}"))
        startup, per_case = fit(points)
        cpu_startup, cpu_per_case = fit(cpu_points)
        print(f"fit over {len(points)} shard runs: wall = {startup:.2f} s start-up + "
              f"{1000 * per_case:.1f} ms per case; CPU = {cpu_startup:.2f} s + {1000 * cpu_per_case:.1f} ms per case")
        for fleet in (100, 1000):
            sizes = [0] * fleet
            for index in range(args.cases):
                sizes[stable_hash(f"case_{index:05d}") % fleet] += 1
            largest = max(sizes)
            print(f"{fleet} workers: largest shard {largest} cases (mean {args.cases / fleet:g}), "
                  f"predicted slowest shard {startup + largest * per_case:.2f} s against "
                  f"{startup + args.cases * per_case:.1f} s on one")
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
