#!/usr/bin/env python3
"""`render --keypoints` against OpenCV's own cv2.projectPoints (Debian's python3-opencv), for an
off-centre camera with non-square pixels, rectified and with plumb_bob and rational_polynomial
lenses. The robot's frames are at known places; each is turned into the camera's optical frame
with the pose the file reports and projected with its K and D. Exit 77 (skipped) without cv2.

usage: keypoints_opencv.py URDFSNAP
"""
import json
import os
import subprocess
import sys
import tempfile

try:
    import cv2
    import numpy as np
except ImportError:
    print("python3-opencv (cv2) is not installed: skipped")
    sys.exit(77)

ROBOT = """<robot name="frames">
  <link name="base"><visual><geometry><box size="0.3 0.3 0.1"/></geometry></visual></link>
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="base_a" type="fixed"><parent link="base"/><child link="a"/><origin xyz="0.4 -0.3 0.2"/></joint>
  <joint name="a_b" type="fixed"><parent link="a"/><child link="b"/><origin xyz="-0.9 0.1 0.3"/></joint>
  <joint name="b_c" type="fixed"><parent link="b"/><child link="c"/><origin xyz="0.2 0.8 -0.6"/></joint>
</robot>
"""
WORLD = {"base": (0, 0, 0), "a": (0.4, -0.3, 0.2), "b": (-0.5, -0.2, 0.5), "c": (-0.3, 0.6, -0.1)}
LENSES = {
    "none": ("plumb_bob", []),
    "plumb_bob": ("plumb_bob", [-0.28, 0.09, 0.0012, -0.0007, -0.015]),
    "rational_polynomial": ("rational_polynomial", [0.35, -0.12, 0.0011, 0.0009, 0.02, 0.62, -0.08, 0.03]),
}


def quaternion_matrix(x, y, z, w):
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def main():
    urdfsnap = sys.argv[1]
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        model = os.path.join(tmp, "frames.urdf")
        with open(model, "w") as f:
            f.write(ROBOT)
        for name, (model_name, d) in LENSES.items():
            info = os.path.join(tmp, name + ".yaml")
            with open(info, "w") as f:
                f.write("width: 640\nheight: 480\nk: [520.5, 0, 301.25, 0, 515.25, 247.75, 0, 0, 1]\n"
                        f"distortion_model: {model_name}\nd: {d}\n")
            out = os.path.join(tmp, name + ".json")
            command = [urdfsnap, "render", model, "-o", os.path.join(tmp, name + ".png"), "--camera-info", info,
                       "--camera-pose", "1.6,0.9,1.1,-0.440275,-0.660412,0.506126,0.337417", "--keypoints", out]
            if d:
                command.append("--distort")
            subprocess.run(command, check=True)
            with open(out) as f:
                keypoints = json.load(f)
            cam = keypoints["camera"]
            pose = cam["pose"]
            R_wc = quaternion_matrix(*pose[3:7])
            t_wc = np.array(pose[0:3])
            for frame in keypoints["frames"]:
                point = WORLD[frame["name"]] if frame["kind"] == "link" else None
                if point is None:
                    continue
                p_c = R_wc.T @ (np.array(point, dtype=float) - t_wc)
                uv, _ = cv2.projectPoints(p_c.reshape(1, 1, 3), np.zeros(3), np.zeros(3),
                                          np.array(cam["K"]).reshape(3, 3), np.array(cam["D"]))
                u, v = uv.reshape(2)
                error = max(abs(u - frame["u"]), abs(v - frame["v"]), abs(p_c[2] - frame["depth"]))
                status = "ok" if error < 1e-6 else "MISMATCH"
                failures += status != "ok"
                print(f"{name:20s} {frame['name']:5s} urdfsnap ({frame['u']:.6f}, {frame['v']:.6f}) "
                      f"opencv ({u:.6f}, {v:.6f}) {status}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
