#!/usr/bin/env python3
"""Speed and memory of `import urdfsnap` (the issue 24 figures), printed as a table:

- the whole process `python3 -c "import urdfsnap; urdfsnap.Robot(mrm).render()"` (median wall of
  RUNS runs), beside one `urdfsnap render` process of the same robot for scale;
- render_many of mrm at 640x480 into one reused numpy array (batches of 100 poses, no PNG):
  frames/s of wall time, and CPU ms per frame of all threads (the load-independent figure);
- peak resident memory after 100 and after 10,000 Robot.render calls (must not grow);
- with --franka DIR (franka_description, e.g. from github.com/frankaemika/franka_ros), the same
  frame rate for the Panda (robots/panda/panda.urdf.xacro, COLLADA meshes).

Timings only, no assertions; on a shared machine wall time follows the load (printed first).
usage: PYTHONPATH=build/python python3 bench/python/python_bench.py [--binary build/urdfsnap]
       [--franka DIR] [--frames N] [--runs N] [--renders N]
"""
import argparse
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import time

import numpy as np

import urdfsnap

ROOT = pathlib.Path(__file__).resolve().parents[2]
MRM = ROOT / "models" / "mrm_description" / "urdf" / "mrm.urdf"


def median_wall(command, runs):
    walls = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        walls.append(time.perf_counter() - start)
    return statistics.median(walls)


def frame_rate(robot, frames, size=(640, 480)):
    """(frames/s wall, CPU ms per frame) of render_many over `frames` random poses in batches."""
    batch = 100
    rng = np.random.default_rng(0)
    joints = {j.name: j for j in robot.joints}
    low = [joints[n].lower if joints[n].lower is not None else -np.pi for n in robot.joint_names]
    high = [joints[n].upper if joints[n].upper is not None else np.pi for n in robot.joint_names]
    poses = rng.uniform(low, high, size=(frames, len(robot.joint_names)))
    out = np.empty((batch, size[1], size[0], 3), np.uint8)
    robot.render_many(poses[:batch], size=size, out=out)  # GL context, meshes uploaded, out touched
    wall, cpu = time.perf_counter(), time.process_time()
    for start in range(0, frames, batch):
        chunk = poses[start:start + batch]
        robot.render_many(chunk, size=size, out=out[:len(chunk)])
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    return frames / wall, 1000 * cpu / frames


def peak_rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--binary", default=str(ROOT / "build" / "urdfsnap"))
    parser.add_argument("--franka", help="franka_description folder (Panda)")
    parser.add_argument("--frames", type=int, default=2000)
    parser.add_argument("--runs", type=int, default=11)
    parser.add_argument("--renders", type=int, default=10000)
    options = parser.parse_args()
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores; {sys.executable}; "
          f"URDFSNAP_GL_BACKEND={os.environ.get('URDFSNAP_GL_BACKEND', '')}")

    first = median_wall([sys.executable, "-c", "import sys, urdfsnap; urdfsnap.Robot(sys.argv[1]).render()", str(MRM)],
                        options.runs)
    print(f"import + Robot(mrm) + first 640x480 array, whole process: {1000 * first:.0f} ms (median of {options.runs})")
    if os.path.exists(options.binary):
        png = "/tmp/urdfsnap_python_bench.png"
        cli = median_wall([options.binary, "render", str(MRM), "-o", png], options.runs)
        os.remove(png)
        print(f"urdfsnap render mrm (PNG written), whole process, for scale: {1000 * cli:.0f} ms")

    mrm = urdfsnap.Robot(MRM)
    fps, cpu = frame_rate(mrm, options.frames)
    print(f"render_many mrm 640x480, {options.frames} frames: {fps:.0f} frames/s, {cpu:.2f} ms CPU per frame")

    for _ in range(100):
        mrm.render()
    after_100 = peak_rss_mb()
    for _ in range(options.renders - 100):
        mrm.render()
    print(f"peak resident memory after 100 renders: {after_100:.0f} MB; after {options.renders}: {peak_rss_mb():.0f} MB")

    if options.franka:
        panda = urdfsnap.Robot(pathlib.Path(options.franka) / "robots" / "panda" / "panda.urdf.xacro",
                               packages={"franka_description": options.franka})
        fps, cpu = frame_rate(panda, min(options.frames, 1000))
        print(f"render_many Panda 640x480: {fps:.0f} frames/s, {cpu:.2f} ms CPU per frame")


if __name__ == "__main__":
    main()
