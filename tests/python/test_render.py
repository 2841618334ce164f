# Robot.render and render_many: byte for byte the pixels of `urdfsnap render` with the same
# options, depth and labels against known geometry, batches, warnings and errors, and several
# Robots drawing from several threads at once.
import threading
import warnings

import numpy as np
import pytest

import urdfsnap
from conftest import MRM, run_cli

POSE = {"base_link__link_01": 0.4, "link_01__link_02": -0.7, "link_03__link_04": 1.1}


def cli_render(binary, tmp_path, model, joints, *options):
    output = tmp_path / "cli.png"
    words = [w for name, value in joints.items() for w in ("-j", f"{name}={value!r}")]
    done = run_cli(binary, "render", model, *words, *options, "-o", output)
    assert done.returncode == 0, done.stderr
    return urdfsnap.read_png(output)


@pytest.mark.parametrize("keywords, options", [
    ({}, []),
    ({"yaw": 1.3, "pitch": 0.3, "distance": 3.5, "focal": (0.1, -0.2, 0.4), "size": (320, 200)},
     ["--yaw", "1.3", "--pitch", "0.3", "--distance", "3.5", "--focal", "0.1,-0.2,0.4", "--size", "320x200"]),
    ({"fit": True, "tf": True, "alpha": 0.5, "background": (10, 200, 30), "grid": False, "size": (240, 160)},
     ["--fit", "--tf", "--alpha", "0.5", "--background", "10,200,30", "--no-grid", "--size", "240x160"]),
    ({"visual": False, "collision": True, "antialias": False, "fov": 60, "size": (200, 150)},
     ["--no-visual", "--collision", "--no-aa", "--fov", "60", "--size", "200x150"]),
    ({"fit": True, "focal": (0, 0, 0.5), "background": "white", "tf": True, "tf_scale": 0.5, "size": (200, 150)},
     ["--fit", "--focal", "0,0,0.5", "--background", "white", "--tf", "--tf-scale", "0.5", "--size", "200x150"]),
])
def test_the_same_pixels_as_urdfsnap_render(mrm, binary, tmp_path, keywords, options):
    image = mrm.render(POSE, **keywords)
    width, height = keywords.get("size", (640, 480))
    assert image.shape == (height, width, 3) and image.dtype == np.uint8
    assert np.mean(np.any(image != image[0, 0], axis=2)) > 0.01  # a picture, not a blank frame
    np.testing.assert_array_equal(image, cli_render(binary, tmp_path, MRM, POSE, *options))


def test_depth_is_the_commands_npy(mrm, binary, tmp_path):
    result = mrm.render(POSE, depth=True, size=(160, 120), fit=True)
    npy = tmp_path / "depth.npy"
    done = run_cli(binary, "render", MRM, *[w for n, v in POSE.items() for w in ("-j", f"{n}={v!r}")],
                   "--fit", "--size", "160x120", "--depth", npy, "-o", tmp_path / "c.png")
    assert done.returncode == 0, done.stderr
    np.testing.assert_array_equal(result.depth, np.load(npy))
    np.testing.assert_array_equal(result.color, urdfsnap.read_png(tmp_path / "c.png"))
    assert result.labels is None


def test_depth_and_labels_of_known_geometry(boxes_path):
    robot = urdfsnap.Robot(boxes_path)
    # looking along -x from x = 5 at the centre of the unit cube of "left" (y = 1): its face is at x = 0.5
    view = {"yaw": 0, "pitch": 0, "distance": 5, "size": (64, 48), "depth": True, "labels": True}
    result = robot.render({"lift": 0.3}, focal=(0, 1, 0.3), **view)
    assert result.color.shape == (48, 64, 3)
    assert result.depth.dtype == np.float32 and result.labels.dtype == np.uint16
    assert result.depth[24, 32] == pytest.approx(4.5, abs=1e-4)
    assert result.label_names == ["", "base", "left", "right", "follower"]
    assert result.label_names[result.labels[24, 32]] == "left"
    assert result.labels[0, 0] == 0 and np.isnan(result.depth[0, 0])
    # the cube spans 1 m of the 2·5·tan(22.5°) m the view shows at its face's distance
    rows = np.flatnonzero(result.labels[:, 32] == 2)
    assert len(rows) == pytest.approx(48 / (2 * 4.5 * np.tan(np.pi / 8)), abs=1.5)
    right = robot.render(focal=(0, -1, 0), **view)
    assert right.label_names[right.labels[24, 32]] == "right"
    assert right.depth[24, 32] == pytest.approx(4.5, abs=1e-4)


def test_render_many_equals_single_renders(mrm):
    rng = np.random.default_rng(1)
    positions = rng.uniform(-1, 1, size=(3, len(mrm.joint_names)))
    frames = mrm.render_many(positions, size=(96, 72), yaw=0.5)
    assert frames.shape == (3, 72, 96, 3)
    for row, frame in zip(positions, frames):
        np.testing.assert_array_equal(frame, mrm.render(dict(zip(mrm.joint_names, row)), size=(96, 72), yaw=0.5))
    as_dicts = mrm.render_many([dict(zip(mrm.joint_names, row)) for row in positions], size=(96, 72), yaw=0.5)
    np.testing.assert_array_equal(as_dicts, frames)
    out = np.zeros_like(frames)
    assert mrm.render_many(positions, size=(96, 72), yaw=0.5, out=out) is not None
    np.testing.assert_array_equal(out, frames)
    both = mrm.render_many(positions, size=(96, 72), yaw=0.5, depth=True, labels=True)
    assert both.depth.shape == (3, 72, 96) and both.labels.shape == (3, 72, 96)
    np.testing.assert_array_equal(both.color, frames)
    assert mrm.render_many(np.zeros((0, len(mrm.joint_names))), size=(8, 8)).shape == (0, 8, 8, 3)
    # one pose as values in joint_names order, as render_many's rows
    np.testing.assert_array_equal(mrm.render(list(positions[1]), size=(96, 72), yaw=0.5), frames[1])


def test_render_many_fit_frames_every_pose_with_one_camera(mrm):
    poses = [{"link_01__link_02": 0}, {"link_01__link_02": 1.5}]
    frames = mrm.render_many(poses, fit=True, size=(64, 48))
    fitted_alone = mrm.render(poses[0], fit=True, size=(64, 48))
    assert not np.array_equal(frames[0], fitted_alone)  # the camera frames both poses, not just the first


@pytest.mark.parametrize("call, message", [
    (lambda r: r.render({"no_such_joint": 1}), "no_such_joint"),
    (lambda r: r.render({"base_link__link_01": float("nan")}), "base_link__link_01"),
    (lambda r: r.render(distance=0), "distance"),
    (lambda r: r.render(alpha=2), "alpha"),
    (lambda r: r.render(size=(0, 10)), "size"),
    (lambda r: r.render(background=(0, 0, 300)), "background"),
    (lambda r: r.render(focal=(0, 0)), "focal"),
    (lambda r: r.render(fixed_frame="map"), "map"),
    (lambda r: r.render(gl_backend="vulkan"), "vulkan"),
    (lambda r: r.render_many(np.zeros((2, 3))), "joint_names"),
    (lambda r: r.render([0.1, 0.2]), "joint_names"),
    (lambda r: r.render_many(np.zeros((1, len(r.joint_names))), size=(8, 8), out=np.zeros((2, 8, 8, 3), np.uint8)), "out"),
])
def test_bad_arguments_raise_error(mrm, call, message):
    with pytest.raises(urdfsnap.Error, match=message):
        call(mrm)


def test_an_unknown_keyword_is_a_type_error(mrm):
    with pytest.raises(TypeError, match="yawn"):
        mrm.render(yawn=1)


def test_a_clamped_joint_warns_as_the_command_does(boxes_path):
    robot = urdfsnap.Robot(boxes_path)
    with pytest.warns(urdfsnap.UrdfsnapWarning, match="lift"):
        clamped = robot.render({"lift": 5}, size=(32, 24))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        np.testing.assert_array_equal(clamped, robot.render({"lift": 1}, size=(32, 24)))


def test_several_robots_in_several_threads(boxes_path):
    poses = [{"base_link__link_01": 0.3 * k} for k in range(4)]
    expected = [urdfsnap.Robot(MRM).render(p, size=(120, 90)) for p in poses]
    results = [None] * len(poses)

    def draw(k):
        robot = urdfsnap.Robot(MRM)
        results[k] = [robot.render(poses[k], size=(120, 90)) for _ in range(3)]

    threads = [threading.Thread(target=draw, args=(k,)) for k in range(len(poses))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for k, frames in enumerate(results):
        for frame in frames:
            np.testing.assert_array_equal(frame, expected[k])


def test_one_robot_shared_by_threads_draws_one_call_at_a_time(mrm):
    expected = mrm.render(size=(64, 48))
    results = []
    threads = [threading.Thread(target=lambda: results.append(mrm.render(size=(64, 48)))) for _ in range(3)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert len(results) == 3
    for frame in results:
        np.testing.assert_array_equal(frame, expected)


def test_notebooks_show_robots_and_results(mrm):
    assert mrm._repr_png_().startswith(b"\x89PNG")
    assert mrm.render(size=(32, 24), labels=True)._repr_png_().startswith(b"\x89PNG")
