#!/usr/bin/env python3
"""Peak memory of `urdfsnap snapshot check` against the number of cases in a suite.

For each count, writes a synthetic suite (make_suite.py --goldens shared: every case fails against
one shared golden, so every case has expected, actual and diff images for the report, the worst
case for memory), runs `snapshot check SUITE --report DIR --junit FILE [--results FILE]` once and
prints the process's peak resident set (from wait4) and wall time. Timings and sizes only; nothing
is asserted.

usage: suite_memory.py URDFSNAP [--cases 50,500,5000] [--work DIR] [--no-results]
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run_check(urdfsnap, suite_dir, with_results):
    command = [urdfsnap, "snapshot", "check", os.path.join(suite_dir, "suite.yaml"),
               "--report", os.path.join(suite_dir, "report"),
               "--junit", os.path.join(suite_dir, "junit.xml")]
    if with_results:
        command += ["--results", os.path.join(suite_dir, "results.json")]
    start = time.monotonic()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    if code not in (0, 1):
        sys.exit(f"suite_memory.py: {' '.join(command)} exited {code}: {process.stderr.read().decode()}")
    return usage.ru_maxrss / 1024.0, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("urdfsnap")
    parser.add_argument("--cases", default="50,500,5000")
    parser.add_argument("--work", help="folder for the suites (default: a temporary one, removed)")
    parser.add_argument("--no-results", action="store_true",
                        help="leave out --results (for binaries that do not have it)")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="urdfsnap_suite_memory.")
    print(f"load average before: {os.getloadavg()[0]:.2f} (2-core machine shared with other builds)")
    print(f"{'cases':>6} {'peak RSS':>10} {'wall':>8} {'per case':>9}")
    try:
        for count in (int(c) for c in args.cases.split(",")):
            suite_dir = os.path.join(work, f"cases_{count}")
            subprocess.run([sys.executable, os.path.join(HERE, "make_suite.py"), suite_dir,
                            str(count), "--goldens", "shared", "--urdfsnap", args.urdfsnap],
                           check=True, stdout=subprocess.DEVNULL)
            peak_mb, seconds = run_check(args.urdfsnap, suite_dir, not args.no_results)
            print(f"{count:>6} {peak_mb:>8.0f} MB {seconds:>7.1f}s {1000 * seconds / count:>7.1f}ms",
                  flush=True)
            shutil.rmtree(suite_dir)
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
