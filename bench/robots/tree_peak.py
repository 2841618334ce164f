#!/usr/bin/env python3
"""The wall time, CPU time and peak memory of a whole process tree (a command and its worker
processes): runs COMMAND, samples every 100 ms the resident memory of it and all its descendants
(/proc/PID/smaps_rollup: Rss, and Pss, which shares each page among the processes that map it, so
that libraries mapped by every worker count once), and writes "WALL_S CPU_S PEAK_RSS_MB
PEAK_PSS_MB" to OUT: CPU of the command and the descendants it waited for (wait4), not of this
sampler (~4% of a core). Exits with the command's status. usage: tree_peak.py OUT COMMAND..."""
import os
import subprocess
import sys
import time


def descendants(root):
    children = {}
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open(f"/proc/{name}/stat") as stat:
                ppid = int(stat.read().rsplit(")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        children.setdefault(ppid, []).append(int(name))
    tree, todo = [], [root]
    while todo:
        pid = todo.pop()
        tree.append(pid)
        todo.extend(children.get(pid, []))
    return tree


def memory_kb(pid):
    rss = pss = 0
    try:
        with open(f"/proc/{pid}/smaps_rollup") as rollup:
            for line in rollup:
                if line.startswith("Rss:"):
                    rss = int(line.split()[1])
                elif line.startswith("Pss:"):
                    pss = int(line.split()[1])
    except OSError:
        pass
    return rss, pss


def main():
    out, command = sys.argv[1], sys.argv[2:]
    start = time.monotonic()
    process = subprocess.Popen(command)
    peak_rss = peak_pss = 0
    while True:
        pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid:
            break
        sums = [sum(values) for values in zip(*(memory_kb(p) for p in descendants(process.pid)))]
        if sums:
            peak_rss, peak_pss = max(peak_rss, sums[0]), max(peak_pss, sums[1])
        time.sleep(0.1)
    wall = time.monotonic() - start
    with open(out, "w") as file:
        file.write(f"{wall:.2f} {usage.ru_utime + usage.ru_stime:.2f} {peak_rss / 1024:.0f} {peak_pss / 1024:.0f}\n")
    sys.exit(os.waitstatus_to_exitcode(status))


if __name__ == "__main__":
    main()
