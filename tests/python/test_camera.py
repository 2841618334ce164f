# Robot.render through a calibrated camera (camera_info, camera_pose, camera_frame, distort,
# underlay) and the mask and keypoints it returns: the same images and the same keypoints file as
# `urdfsnap render` with the same options, and silhouettes and pixels of known geometry.
import json

import numpy as np
import pytest

import urdfsnap
from conftest import MRM, ROOT, run_cli

CAMERA_INFO = ROOT / "tests" / "data" / "camera" / "ost.yaml"
POSE = {"base_link__link_01": 0.4, "link_01__link_02": -0.7, "link_03__link_04": 1.1}
# the optical frame 5 m in front of the arm along +x, looking back along -x (x right = +y, y down = -z)
LOOKING_BACK = (5, 0.05, 1.0, -0.5, -0.5, 0.5, 0.5)


def cli_outputs(binary, tmp_path, *options):
    """`urdfsnap render MRM` with the pose and options: colour, mask and keypoints it wrote."""
    words = [w for name, value in POSE.items() for w in ("-j", f"{name}={value!r}")]
    files = {name: tmp_path / name for name in ("c.png", "m.png", "k.json")}
    done = run_cli(binary, "render", MRM, *words, *options, "-o", files["c.png"], "--mask", files["m.png"],
                   "--keypoints", files["k.json"])
    assert done.returncode == 0, done.stderr
    return (urdfsnap.read_png(files["c.png"]), urdfsnap.read_png(files["m.png"])[..., 0],
            json.loads(files["k.json"].read_text()))


@pytest.mark.parametrize("keywords, options", [
    ({"camera_info": CAMERA_INFO, "camera_pose": LOOKING_BACK},
     ["--camera-info", CAMERA_INFO, "--camera-pose", ",".join(map(str, LOOKING_BACK))]),
    ({"camera_info": CAMERA_INFO, "camera_pose": LOOKING_BACK, "distort": True, "mask_dilate": 3, "near": 0.5},
     ["--camera-info", CAMERA_INFO, "--camera-pose", ",".join(map(str, LOOKING_BACK)), "--distort",
      "--mask-dilate", "3", "--near", "0.5"]),
    ({"camera_frame": "link_04", "camera_pose": (0, 0, -0.8, 0, 0, 0, 1), "size": (160, 120), "fov": 70},
     ["--camera-frame", "link_04", "--camera-pose", "0,0,-0.8,0,0,0,1", "--size", "160x120", "--fov", "70"]),
    ({"size": (200, 150), "yaw": 1.1}, ["--size", "200x150", "--yaw", "1.1"]),   # the orbit view as a camera
])
def test_the_commands_images_mask_and_keypoints(mrm, binary, tmp_path, keywords, options):
    result = mrm.render(POSE, mask=True, keypoints=True, **keywords)
    color, mask, keypoints = cli_outputs(binary, tmp_path, *options)
    assert np.mean(result.mask > 0) > 0.005   # the robot is in the picture
    np.testing.assert_array_equal(result.color, color)
    assert result.mask.dtype == np.uint8 and result.mask.shape == color.shape[:2]
    np.testing.assert_array_equal(result.mask, mask)
    assert result.keypoints == keypoints
    assert result.depth is None and result.labels is None


def test_a_box_seen_by_the_camera_covers_the_pixels_its_geometry_says(boxes_path):
    robot = urdfsnap.Robot(boxes_path)
    # 5 m in front of the unit cube "left" (centre at y = 1), looking along -x: its near face is
    # at depth 4.5, half a metre each way; fov 45° at 64x48 gives f = 24 / tan(22.5°)
    result = robot.render(camera_pose=(5, 1, 0, -0.5, -0.5, 0.5, 0.5), size=(64, 48), mask=True, labels=True,
                          keypoints=True, depth=True)
    f = 24 / np.tan(np.radians(22.5))
    low, high = 31.5 - 0.5 / 4.5 * f, 31.5 + 0.5 / 4.5 * f
    columns = np.flatnonzero(np.any(result.labels == 2, axis=0))
    rows = np.flatnonzero(np.any(result.labels == 2, axis=1))
    assert (columns[0], columns[-1]) == (int(np.ceil(low)), int(np.floor(high)))
    assert (rows[0], rows[-1]) == (int(np.ceil(low - 8)), int(np.floor(high - 8)))
    np.testing.assert_array_equal(result.mask, np.where(result.labels > 0, 255, 0))
    frames = {frame["name"]: frame for frame in result.keypoints["frames"]}
    left = frames["left"]
    assert (left["u"], left["v"], left["depth"]) == pytest.approx((31.5, 23.5, 5.0))
    assert left["in_image"] and left["visible"] and left["kind"] == "link"
    assert result.keypoints["camera"]["K"] == pytest.approx([f, 0, 31.5, 0, f, 23.5, 0, 0, 1])
    grown = robot.render(camera_pose=(5, 1, 0, -0.5, -0.5, 0.5, 0.5), size=(64, 48), mask=True, mask_dilate=2)
    assert np.all(grown.mask[result.mask > 0] == 255) and np.sum(grown.mask > 0) > np.sum(result.mask > 0)


def test_render_many_returns_a_mask_and_keypoints_per_pose(mrm):
    poses = [POSE, {"base_link__link_01": -0.6}, {}]
    view = {"camera_info": CAMERA_INFO, "camera_pose": LOOKING_BACK, "mask": True, "keypoints": True}
    many = mrm.render_many(poses, **view)
    assert many.color.shape == (3, 480, 640, 3) and many.mask.shape == (3, 480, 640)
    assert isinstance(many.keypoints, list) and len(many.keypoints) == 3
    for k, pose in enumerate(poses):
        one = mrm.render(pose, **view)
        np.testing.assert_array_equal(many.color[k], one.color)
        np.testing.assert_array_equal(many.mask[k], one.mask)
        assert many.keypoints[k] == one.keypoints


def test_an_underlay_array_is_the_same_as_its_file(mrm, tmp_path):
    rng = np.random.default_rng(3)
    underlay = rng.integers(0, 256, size=(480, 640, 3), dtype=np.uint8)
    urdfsnap.write_png(underlay, tmp_path / "u.png")
    view = {"camera_info": CAMERA_INFO, "camera_pose": LOOKING_BACK, "underlay_alpha": 0.3}
    from_array = mrm.render(POSE, underlay=underlay, **view)
    np.testing.assert_array_equal(from_array, mrm.render(POSE, underlay=tmp_path / "u.png", **view))
    np.testing.assert_array_equal(from_array[0, 0], underlay[0, 0])   # the image where no robot is


@pytest.mark.parametrize("call, message", [
    ({"mask": True, "mask_dilate": -1}, "mask_dilate -1: expected a number of pixels from 0 to 1000"),
    ({"distort": True, "camera_pose": LOOKING_BACK}, "distort needs camera_info"),
    ({"near": 0.5}, "near needs a camera: camera_info, camera_frame or camera_pose"),
    ({"underlay": np.zeros((48, 64, 3), np.uint8)}, "underlay needs a camera"),
    ({"camera_pose": (1, 2, 3)}, "camera_pose '1,2,3': expected seven finite numbers"),
    ({"camera_frame": "nowhere"}, "camera frame 'nowhere' is not a link"),
    ({"camera_info": CAMERA_INFO, "camera_pose": LOOKING_BACK, "underlay": np.zeros((48, 64, 3), np.uint8)},
     "underlay"),
])
def test_bad_camera_keywords_raise_error(mrm, call, message):
    with pytest.raises(urdfsnap.Error, match=message):
        mrm.render(**call)
