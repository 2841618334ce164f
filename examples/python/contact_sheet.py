#!/usr/bin/env python3
"""Renders 100 random poses of a robot, each joint within its limits, into numpy arrays with one
render_many call, and saves them as one contact sheet PNG (10 x 10 thumbnails).

usage: contact_sheet.py MODEL [-o SHEET.png] [--package NAME=DIR]... [--count N] [--size WxH] [--seed S]
e.g.   examples/python/contact_sheet.py models/mrm_description/urdf/mrm.urdf -o output/mrm_sheet.png
"""
import argparse
import math

import numpy as np

import urdfsnap


def random_poses(robot, count, rng):
    """count x len(robot.joint_names) values, uniform within each joint's limits (continuous joints
    over a full turn)."""
    joints = {joint.name: joint for joint in robot.joints}
    low = [joints[name].lower if joints[name].lower is not None else -math.pi for name in robot.joint_names]
    high = [joints[name].upper if joints[name].upper is not None else math.pi for name in robot.joint_names]
    return rng.uniform(low, high, size=(count, len(robot.joint_names)))


def contact_sheet(frames, columns):
    """N x H x W x 3 frames tiled row by row into one image (empty tiles black)."""
    count, height, width, _ = frames.shape
    rows = -(-count // columns)
    sheet = np.zeros((rows * height, columns * width, 3), np.uint8)
    for k, frame in enumerate(frames):
        row, column = divmod(k, columns)
        sheet[row * height:(row + 1) * height, column * width:(column + 1) * width] = frame
    return sheet


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model")
    parser.add_argument("-o", "--output", default="contact_sheet.png")
    parser.add_argument("--package", action="append", default=[], metavar="NAME=DIR")
    parser.add_argument("--count", type=int, default=100)
    parser.add_argument("--size", default="160x120")
    parser.add_argument("--seed", type=int, default=0)
    options = parser.parse_args(argv)
    packages = dict(p.split("=", 1) for p in options.package)
    width, height = map(int, options.size.split("x"))
    robot = urdfsnap.Robot(options.model, packages=packages)
    poses = random_poses(robot, options.count, np.random.default_rng(options.seed))
    frames = robot.render_many(poses, size=(width, height), fit=True)
    urdfsnap.write_png(contact_sheet(frames, columns=math.ceil(math.sqrt(options.count))), options.output)
    print(f"{options.output}: {options.count} poses of {robot.name}")


if __name__ == "__main__":
    main()
