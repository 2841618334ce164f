#!/usr/bin/env python3
"""Writes a synthetic snapshot suite of N cases for the scale and memory benchmarks.

Each case is one of the project's robots (mrm, the looks robot, meshbot, in turn) in a pose and a
view drawn from a seeded random generator, so the same arguments give the same suite. Case names
are case_00000, case_00001, ...; the models are referred to by absolute path, so the suite can be
written anywhere.

  --goldens own     each case has its own golden NAME.png beside the suite (made by
                    `urdfsnap snapshot update`): a suite that passes, as in CI
  --goldens shared  every case is compared with one image, shared.png (made by this script with
                    `urdfsnap render` when --urdfsnap is given): almost every case fails, so a
                    check keeps and writes all three report images, the worst case for memory

usage: make_suite.py OUT_DIR CASES [--goldens own|shared] [--seed S] [--size WxH]
                     [--urdfsnap BINARY]
"""
import argparse
import os
import random
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MRM = os.path.join(ROOT, "models/mrm_description/urdf/mrm.urdf")
LOOKS = os.path.join(ROOT, "tests/data/looks/looks.urdf")
MESHBOT = os.path.join(ROOT, "models/meshbot_description/urdf/meshbot.urdf")

# (model, {joint: (low, high)}, orbit distance)
ROBOTS = [
    (MRM, {"base_link__link_01": (-3.1, 3.1), "link_01__link_02": (-1.5, 1.5),
           "link_02__link_03": (-2.0, 2.0), "link_03__link_04": (-2.0, 2.0),
           "link_04__link_05": (-3.1, 3.1)}, None),
    (LOOKS, {"wheel_joint": (-3.1, 3.1), "lift": (0.0, 0.3), "shoulder": (-1.5, 1.5)}, 2.5),
    (MESHBOT, {"column_yaw": (-3.1, 3.1), "head_tilt": (-0.8, 0.8)}, None),
]


def case_lines(index, rng):
    model, joints, distance = ROBOTS[index % len(ROBOTS)]
    values = ", ".join(f"{name}: {rng.uniform(*span):.4f}" for name, span in joints.items())
    lines = [f"  - name: case_{index:05d}", f"    model: {model}", f"    joints: {{{values}}}",
             f"    yaw: {rng.uniform(-3.1, 3.1):.4f}", f"    pitch: {rng.uniform(0.1, 1.2):.4f}"]
    lines.append(f"    distance: {distance}" if distance else "    fit: true")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out_dir")
    parser.add_argument("cases", type=int)
    parser.add_argument("--goldens", choices=["own", "shared"], default="own")
    parser.add_argument("--seed", type=int, default=15)
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--urdfsnap", help="binary that renders shared.png (--goldens shared)")
    args = parser.parse_args()
    if args.cases < 1:
        sys.exit("make_suite.py: CASES must be at least 1")
    os.makedirs(args.out_dir, exist_ok=True)
    rng = random.Random(args.seed)
    lines = [f"# synthetic suite: {args.cases} cases, seed {args.seed}, goldens {args.goldens}",
             "defaults:", f"  size: {args.size}"]
    lines.append("cases:")
    for index in range(args.cases):
        lines += case_lines(index, rng)
        if args.goldens == "shared":
            lines.append("    golden: shared.png")
    suite = os.path.join(args.out_dir, "suite.yaml")
    with open(suite, "w") as f:
        f.write("\n".join(lines) + "\n")
    if args.goldens == "shared" and args.urdfsnap:
        subprocess.run([args.urdfsnap, "render", MRM, "--size", args.size, "-o",
                        os.path.join(args.out_dir, "shared.png")], check=True)
    print(suite)


if __name__ == "__main__":
    main()
