#!/usr/bin/python3
"""Takes the real RViz's screenshots of a reference manifest (the zoo format of
../shared/rviz-reference: urdf, package_path, fixed_frame, empty_scenes, images with joints, view,
size, tf, robot, robot_alpha, collision), so that urdfsnap can be scored against RViz on robots of
our own, as tests/data/texture_maps_description/rviz/ is. Each image and each empty scene is
written where the manifest names it, from RViz's render area only (its GL window, found with
xwininfo and read with xwd).

It runs Debian 12's RViz 1.14.19 (Ogre 1.12, Mesa llvmpipe) under Xvfb with a ROS master of its
own, robot_state_publisher and a /joint_states publisher, as the shared references were made;
measured: it remakes the Kinova Gen3 references with 1-3 pixels of 307,200 different and their
empty scenes identical, and its own screenshots byte for byte. Test tooling only, never needed to
build or run urdfsnap. Needs Debian's system python3 and:
  apt-get install rviz xvfb x11-apps xauth ros-core ros-robot-state-publisher python3-rospy \\
                  python3-sensor-msgs python3-numpy python3-pil

usage: scripts/rviz-screenshots.py [--no-aa] [--only SUBSTRING] MANIFEST.json
  --no-aa   RViz's --disable-anti-aliasing (for measuring; writes NAME.noaa.png beside NAME.png)
"""
import json
import os
import struct
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np
from PIL import Image

DISPLAY = os.environ.get("RVIZ_SCREENSHOTS_DISPLAY", ":77")
PORT = int(os.environ.get("RVIZ_SCREENSHOTS_PORT", "11377"))
# RViz's window around its render area with every panel hidden: menu bar, tool bar and status
# bar (91 px) and the two dock handles (32 px), measured on this RViz
CHROME = (32, 91)

CONFIG = """Panels: []
Visualization Manager:
  Class: ""
  Displays:
{displays}
  Enabled: true
  Global Options:
    Background Color: 48; 48; 48
    Default Light: true
    Fixed Frame: {fixed}
    Frame Rate: 30
  Name: root
  Tools:
    - Class: rviz/MoveCamera
  Value: true
  Views:
    Current:
      Class: rviz/Orbit
      Distance: {distance}
      Field of View: 0.785398
      Focal Point:
        X: {fx}
        Y: {fy}
        Z: {fz}
      Name: Current View
      Near Clip Distance: 0.01
      Pitch: {pitch}
      Target Frame: <Fixed Frame>
      Yaw: {yaw}
    Saved: ~
Window Geometry:
  Height: {height}
  Hide Left Dock: true
  Hide Right Dock: true
  Width: {width}
  X: 0
  Y: 0
"""
GRID = """    - Alpha: 0.5
      Cell Size: 1
      Class: rviz/Grid
      Color: 160; 160; 164
      Enabled: true
      Line Style:
        Line Width: 0.03
        Value: Lines
      Name: Grid
      Normal Cell Count: 0
      Offset: {X: 0, Y: 0, Z: 0}
      Plane: XY
      Plane Cell Count: 10
      Reference Frame: <Fixed Frame>
      Value: true
"""
ROBOT = """    - Alpha: {alpha}
      Class: rviz/RobotModel
      Collision Enabled: {collision}
      Enabled: true
      Name: RobotModel
      Robot Description: robot_description
      TF Prefix: ""
      Update Interval: 0
      Value: true
      Visual Enabled: {visual}
"""
TF = """    - Class: rviz/TF
      Enabled: true
      Frame Timeout: 15
      Marker Alpha: 1
      Marker Scale: 1
      Name: TF
      Show Arrows: true
      Show Axes: true
      Show Names: true
      Update Interval: 0
      Value: true
"""


def xwd_pixels(data):
    """The RGB pixels of an xwd dump (ZPixmap, 24 or 32 bits per pixel)."""
    header = struct.unpack(">25I", data[:100])
    header_size, width, height = header[0], header[4], header[5]
    byte_order, bits_per_pixel, bytes_per_line, colours = header[7], header[11], header[12], header[19]
    n = bits_per_pixel // 8
    start = header_size + 12 * colours
    rows = np.frombuffer(data[start:start + bytes_per_line * height], np.uint8).reshape(height, bytes_per_line)
    pixels = rows[:, :width * n].reshape(height, width, n)
    return pixels[:, :, [2, 1, 0]] if byte_order == 0 else pixels[:, :, [n - 3, n - 2, n - 1]]


def render_window(width, height):
    """The id of the X window of exactly width x height pixels (RViz's Ogre window), or None."""
    tree = subprocess.run(["xwininfo", "-root", "-tree", "-display", DISPLAY], capture_output=True, text=True).stdout
    found = None
    for line in tree.splitlines():
        fields = line.split()
        if fields and fields[0].startswith("0x") and any(f.startswith("%dx%d+" % (width, height)) for f in fields):
            found = fields[0]
    return found


def shots(manifest_path, no_aa, only):
    manifest = json.load(open(manifest_path))
    folder = os.path.dirname(os.path.abspath(manifest_path))
    urdf = os.path.join(folder, manifest["urdf"])
    shots = []
    for image in manifest["images"]:
        if only not in image["file"]:
            continue
        out = os.path.join(folder, image["file"])
        shots.append((image, out[:-4] + ".noaa.png" if no_aa else out, True))
        empty = manifest.get("empty_scenes", {}).get(image["view_name"])
        if empty and not no_aa:
            shots.append((image, os.path.join(folder, empty), False))
    package_path = os.path.normpath(os.path.join(folder, manifest.get("package_path", ".")))
    return urdf, manifest.get("fixed_frame", "base_link"), package_path, shots


def main():
    args = sys.argv[1:]
    no_aa = "--no-aa" in args
    only = args[args.index("--only") + 1] if "--only" in args else ""
    urdf, fixed, package_path, todo = shots(args[-1], no_aa, only)
    env = dict(os.environ, DISPLAY=DISPLAY, ROS_MASTER_URI="http://localhost:%d" % PORT,
               ROS_PACKAGE_PATH=package_path, ROS_HOME=tempfile.mkdtemp(prefix="rviz-screenshots"))
    background = []
    try:
        for command in (["Xvfb", DISPLAY, "-screen", "0", "1600x1200x24", "-nolisten", "tcp"],
                        ["rosmaster", "--core", "-p", str(PORT)]):
            background.append(subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        time.sleep(1.5)
        os.environ.update(env)
        import rospy
        from sensor_msgs.msg import JointState
        rospy.init_node("rviz_screenshots", anonymous=True, disable_signals=True)
        rospy.set_param("/robot_description", open(urdf).read())
        publisher = rospy.Publisher("/joint_states", JointState, queue_size=1)
        joints = {}

        def publish():
            while not rospy.is_shutdown():
                message = JointState()
                message.header.stamp = rospy.Time.now()
                message.name, message.position = list(joints), list(joints.values())
                publisher.publish(message)
                time.sleep(0.05)

        threading.Thread(target=publish, daemon=True).start()
        background.append(subprocess.Popen(["/usr/lib/robot_state_publisher/robot_state_publisher"], env=env,
                                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        for image, out, with_robot in todo:
            joints.clear()
            joints.update(image["joints"])   # mimic joints too: robot_state_publisher ignores <mimic>
            view, width, height = image["view"], image["width"], image["height"]
            displays = GRID
            if with_robot and image.get("robot", True):
                collision = image.get("collision", False)
                displays += ROBOT.format(alpha=image.get("robot_alpha", 1.0), collision=str(collision).lower(),
                                         visual=str(not collision).lower())
            if image.get("tf", False):
                displays += TF
            config = os.path.join(env["ROS_HOME"], "screenshot.rviz")
            open(config, "w").write(CONFIG.format(
                displays=displays, fixed=fixed, distance=view["distance"], fx=view["focal"][0], fy=view["focal"][1],
                fz=view["focal"][2], pitch=view["pitch"], yaw=view["yaw"], width=width + CHROME[0],
                height=height + CHROME[1]))
            command = ["rviz", "-d", config, "--splash-screen", ""] + (["--disable-anti-aliasing"] if no_aa else [])
            rviz = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            try:
                time.sleep(4)
                window = render_window(width, height)
                if window is None:
                    sys.exit("rviz-screenshots: no %dx%d render window for %s" % (width, height, out))
                # the picture must hold still over four grabs (TF and meshes all arrived)
                grabs = []
                while len(grabs) < 4 or not all((g == grabs[-1]).all() for g in grabs[-4:]):
                    if len(grabs) > 40:
                        sys.exit("rviz-screenshots: the picture for %s never held still" % out)
                    dump = subprocess.run(["xwd", "-silent", "-id", window, "-display", DISPLAY], capture_output=True).stdout
                    grabs.append(xwd_pixels(dump))
                    time.sleep(0.25)
                os.makedirs(os.path.dirname(out), exist_ok=True)
                Image.fromarray(np.ascontiguousarray(grabs[-1])).save(out)
                print("wrote", out)
            finally:
                rviz.terminate()
                rviz.wait(timeout=20)
        rospy.signal_shutdown("done")
    finally:
        for process in reversed(background):
            process.terminate()
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()


if __name__ == "__main__":
    main()
