"""urdfsnap: RViz-like images of URDF/xacro robots as numpy arrays, headless (no display, GPU or ROS).

    import urdfsnap
    robot = urdfsnap.Robot("mrm.urdf")
    image = robot.render({"base_link__link_01": 0.5}, size=(320, 240))   # H×W×3 uint8
    frames = robot.render_many(poses)                                    # N×H×W×3 uint8

The pixels are those of `urdfsnap render` with the same options, drawn by the same C++ core in this
process. Errors raise urdfsnap.Error with the message the command line prints; warnings (clamped
joints, missing meshes allowed, ...) go through Python's warnings module as UrdfsnapWarning.

Threads: one Robot may be used from one thread at a time (calls from several threads on one Robot
wait for each other); several Robots render from several threads at once, the GIL released while
they draw. Each Robot keeps its own off-screen GL context.
"""

from urdfsnap._urdfsnap import (
    DIFF_MAX_DELTA,
    DIFF_MAX_FRACTION,
    DIFF_MAX_MEAN,
    Error,
    Joint,
    Mimic,
    RenderResult,
    Robot,
    UrdfsnapWarning,
    __version__,
    _compare,
    encode_png,
    read_png,
    write_png,
    xacro,
    _wait_for_gl,
)

# importing the extension started loading Mesa on a thread; numpy's import runs meanwhile (the
# arrays need it), and a fork waits for the load (the child would inherit the loader's lock)
import numpy  # noqa: E402,F401  pylint: disable=unused-import,wrong-import-position
import os as _os  # noqa: E402

_os.register_at_fork(before=_wait_for_gl)

# the extension's types show as urdfsnap.Robot, urdfsnap.Error, ... in reprs and tracebacks
for _type in (Error, Joint, Mimic, RenderResult, Robot):
    _type.__module__ = __name__
del _type

__all__ = [
    "DiffResult", "Error", "Joint", "Mimic", "RenderResult", "Robot", "UrdfsnapWarning", "__version__",
    "diff", "encode_png", "read_png", "show", "write_png", "xacro",
]


class DiffResult:
    """What diff() found: .passed, .fraction (of pixels over max_delta), .max_delta (the largest
    channel difference seen), .mean_delta, .pixels_over, .description (one line, as `urdfsnap diff`
    prints it) and .image (H×W×3: changed pixels magenta, faint changes yellow, the rest grey)."""

    def __init__(self, figures):
        self.passed = figures["passed"]
        self.fraction = figures["fraction"]
        self.max_delta = figures["max_delta"]
        self.mean_delta = figures["mean_delta"]
        self.pixels_over = figures["pixels_over"]
        self.description = figures["description"]
        self.image = figures["image"]

    def __bool__(self):
        return self.passed

    def __repr__(self):
        return f"DiffResult(passed={self.passed}, {self.description})"

    def _repr_png_(self):
        return encode_png(self.image)


def diff(expected, actual, max_delta=DIFF_MAX_DELTA, max_fraction=DIFF_MAX_FRACTION, max_mean=DIFF_MAX_MEAN):
    """Compares two images (H×W×3 uint8 arrays or PNG paths) as `urdfsnap diff` does: they match
    when at most max_fraction of the pixels differ by more than max_delta in a channel and the mean
    difference is at most max_mean. Returns a DiffResult; raises Error when the sizes differ."""
    return DiffResult(_compare(expected, actual, max_delta, max_fraction, max_mean))


class _Picture:
    """An image a notebook shows inline (IPython calls _repr_png_)."""

    def __init__(self, image):
        self.image = image

    def _repr_png_(self):
        return encode_png(self.image)


def show(image):
    """Shows an H×W×3 uint8 array inline in a Jupyter notebook. Outside IPython it returns an object
    with _repr_png_ instead (what a notebook would show)."""
    picture = _Picture(image)
    try:
        from IPython import get_ipython
        from IPython.display import display
    except ImportError:
        return picture
    if get_ipython() is None:
        return picture
    display(picture)
    return None
