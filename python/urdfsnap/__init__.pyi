# Type stub of the urdfsnap package for editors and type checkers: the extension module's classes
# and functions (src/python/module.cpp) with their keyword arguments and defaults, and the Python
# helpers of __init__.py.
import os
from typing import Iterable, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
DIFF_MAX_DELTA: int
DIFF_MAX_FRACTION: float
DIFF_MAX_MEAN: float

Path = Union[str, os.PathLike[str]]
ImageLike = Union[npt.NDArray[np.uint8], Path]

class Error(ValueError):
    """Bad input: the message the command line prints, naming the file, line, joint or keyword."""

class UrdfsnapWarning(UserWarning):
    """A warning the command line would print (clamped joint values, a mimic joint overridden, ...)."""

class Mimic:
    """A mimic joint's rule: value = multiplier * value of `joint` + offset."""
    joint: str
    multiplier: float
    offset: float

class Joint:
    """A joint of the robot, in URDF document order."""
    name: str
    type: str  # 'revolute', 'continuous', 'prismatic', 'fixed', 'floating' or 'planar'
    lower: Optional[float]  # rad or m; None for joints without limits
    upper: Optional[float]
    default: float  # the value a render takes when none is given (0, or mid-limits when 0 is outside)
    mimic: Optional[Mimic]

class RenderResult:
    """Robot.render's result when depth, labels, mask or keypoints are asked for (arrays get a
    leading N from render_many, keypoints become a list of N dicts)."""
    color: npt.NDArray[np.uint8]  # H×W×3 RGB
    depth: Optional[npt.NDArray[np.float32]]  # H×W metres along the viewing axis, NaN off the robot
    labels: Optional[npt.NDArray[np.uint16]]  # H×W, 1 + index into Robot.links, 0 off the robot
    mask: Optional[npt.NDArray[np.uint8]]  # H×W, 255 on the robot (grown by mask_dilate), 0 elsewhere
    # the `render --keypoints` file's contents: {"camera": {...}, "frames": [{"name", "kind", "u", "v",
    # "depth", "in_image", "visible"}, ...]} (docs/camera.md)
    keypoints: Optional[Union[dict, list[dict]]]
    label_names: list[str]  # label value -> link name ("" for 0)
    def _repr_png_(self) -> Optional[bytes]: ...

class Robot:
    """A robot loaded from a URDF or xacro file, ready to render.

    One Robot may be used from one thread at a time (calls on one Robot from several threads wait
    for each other); several Robots render from several threads at once, the GIL released while
    they draw."""

    def __init__(self, path: Path, args: Optional[Mapping[str, object]] = None,
                 packages: Optional[Mapping[str, Path]] = None, xacro_ns: bool = False) -> None:
        """Loads `path` (xacro expanded when its name ends in .xacro, args are given or it declares
        the xacro namespace). args: xacro arguments NAME -> VALUE (NAME:=VALUE); packages: package
        name -> folder, for $(find) and package:// URIs; xacro_ns: modern xacro's rule that only
        xacro:-prefixed tags are macro calls. Raises Error as `urdfsnap render` would."""
    name: str
    path: str
    links: list[str]  # in tree order, root first (the label image's order)
    joints: list[Joint]
    joint_names: list[str]  # the joints a value moves (not mimic): render_many's columns
    def default_positions(self) -> dict[str, float]:
        """The value of each of joint_names when none is given, as joint_state_publisher starts."""
    @overload
    def render(self, joints: Optional[Mapping[str, float]] = None, *, yaw: float = 0.785398,
               pitch: float = 0.785398, distance: float = 10.0,
               focal: Tuple[float, float, float] = (0, 0, 0), size: Tuple[int, int] = (640, 480),
               fit: bool = False, tf: bool = False, alpha: float = 1.0,
               background: Union[Tuple[int, int, int], str] = (48, 48, 48), grid: bool = True, visual: bool = True,
               collision: bool = False, depth: bool = False, labels: bool = False,
               gl_backend: str = "auto", fov: float = 45.0, fixed_frame: str = "",
               antialias: bool = True, clamp: bool = True, tf_scale: float = 1.0,
               allow_missing_meshes: bool = False, camera_info: Optional[Path] = None,
               camera_frame: str = "", camera_pose: Optional[Sequence[float]] = None,
               near: float = 0.01, far: float = 100.0, distort: bool = False,
               underlay: Optional[ImageLike] = None, underlay_alpha: float = 0.5,
               mask: bool = False, mask_dilate: int = 0,
               keypoints: bool = False) -> Union[npt.NDArray[np.uint8], RenderResult]:
        """Renders the robot with `joints` (name -> rad or m; other joints at their defaults).

        Returns an H×W×3 uint8 array, or with depth, labels, mask or keypoints a RenderResult. The same
        pixels as `urdfsnap render` with the same options (parsed and checked by the same code):
        yaw, pitch (rad), distance (m, 0.01 to 1e6), focal (m), fov (degrees, vertical), size
        (width, height), fit (frame the robot, --fit; with focal given, around that point), tf
        (TF markers), tf_scale, alpha (robot opacity 0..1), background (R, G, B 0..255, or
        "white", "#RRGGBB" as --background), grid, visual, collision, fixed_frame (a link; "" =
        the root), antialias (False = --no-aa), clamp (False = --no-clamp), allow_missing_meshes. gl_backend: "auto" (URDFSNAP_GL_BACKEND
        when set, else OSMesa then EGL), "osmesa" or "egl".

        A calibrated camera instead of the orbit view (docs/camera.md), as render's --camera-*
        options: camera_info (a camera_calibration YAML or an echoed CameraInfo; the image is its
        size), camera_frame (a link, in ROS's optical convention), camera_pose (X, Y, Z, QX, QY, QZ,
        QW in camera_frame, or in the fixed frame), near, far, distort (the raw image through the
        lens), underlay (a camera image behind the robot: an H×W×3 array or a PNG path) and
        underlay_alpha. mask=True adds RenderResult.mask (mask_dilate grows it), keypoints=True
        RenderResult.keypoints (through the orbit view as a camera when none is given).

        Raises Error for an unknown joint, a keyword out of range, an unknown fixed frame or camera
        frame, a mesh or camera info that cannot be read."""
    def render_many(self, positions: Union[npt.ArrayLike, Iterable[Mapping[str, float]]], *,
                    out: Optional[npt.NDArray[np.uint8]] = None,
                    **view: object) -> Union[npt.NDArray[np.uint8], RenderResult]:
        """Renders N poses with one GL context and one prepared robot, into one N×H×W×3 array (or a
        RenderResult of N×... arrays with depth/labels). positions: an N×J array in joint_names
        order, or a list of dicts as render's joints. out: an N×H×W×3 uint8 array to fill instead of
        a new one (reuse it to render in batches without allocating). **view: render's keywords;
        fit=True frames all poses with one camera, as `urdfsnap animate --fit`."""
    def _repr_png_(self) -> bytes:
        """The default view as PNG bytes (a notebook shows the robot inline)."""

class DiffResult:
    passed: bool
    fraction: float  # of the pixels, those over max_delta
    max_delta: int  # the largest channel difference seen (0..255)
    mean_delta: float
    pixels_over: int
    description: str  # one line with the figures, as `urdfsnap diff` prints it
    image: npt.NDArray[np.uint8]  # changed pixels magenta, faint changes yellow, the rest grey
    def __bool__(self) -> bool: ...
    def _repr_png_(self) -> bytes: ...

def diff(expected: ImageLike, actual: ImageLike, max_delta: int = ..., max_fraction: float = ...,
         max_mean: float = ...) -> DiffResult:
    """Compares two images (arrays or PNG paths) with `urdfsnap diff`'s tolerance (8, 0.0001, 0.1)."""

def xacro(path: Path, args: Optional[Mapping[str, object]] = None,
          packages: Optional[Mapping[str, Path]] = None, xacro_ns: bool = False) -> str:
    """Expands a xacro file to URDF text, as `urdfsnap xacro` prints it."""

def read_png(path: Path) -> npt.NDArray[np.uint8]: ...
def write_png(image: npt.NDArray[np.uint8], path: Path) -> None: ...
def encode_png(image: npt.NDArray[np.uint8]) -> bytes: ...
def show(image: npt.NDArray[np.uint8]) -> object:
    """Shows an image inline in a notebook."""
