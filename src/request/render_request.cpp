// The table of `render`'s view and display options, with RViz's defaults in the help texts.
#include "request/render_request.h"

#include <array>

namespace urdfsnap::request {

namespace {

using R = RenderRequest;

const std::array kTextOptions{
    TextOption{"size",
               "image size WxH in pixels, up to 16384x16384 (default 640x480, the RViz reference "
               "images' render area)",
               &R::size, false},
    TextOption{"rviz",
               "an RViz 1 or RViz 2 .rviz config: background, fixed frame, Grid, RobotModel, TF and "
               "Orbit view (the options below override it; default none: RViz's built-in "
               "defaults); one with none of these is an error",
               &R::rviz, true},
    TextOption{"yaw", "orbit yaw about +Z in rad (RViz default 0.785398)", &R::yaw, false},
    TextOption{"pitch", "orbit pitch in rad (RViz default 0.785398)", &R::pitch, false},
    TextOption{"distance", "orbit distance in m (RViz default 10)", &R::distance, false},
    TextOption{"focal", "orbit focal point X,Y,Z in m (RViz default 0,0,0)", &R::focal, false},
    TextOption{"fov", "vertical field of view in degrees (RViz default 45)", &R::fov, false},
    TextOption{"fit-margin",
               "with --fit, the empty border on each side: a fraction of the side (0.05) or pixels "
               "(12px) (default 0.05)",
               &R::fit_margin, false},
    TextOption{"fixed-frame",
               "link whose frame the scene is shown in (RViz default 'map', which a URDF has not: "
               "here the root link)",
               &R::fixed_frame, false},
    TextOption{"follow",
               "frame the orbit view's focal point follows (RViz's Target Frame): the focal point is "
               "taken relative to the frame's origin (not its rotation), which animate and render "
               "--bag move over time; a link, or with a bag any frame its TF names (default: the "
               "fixed frame)",
               &R::follow, false},
    TextOption{"background", "background colour: R,G,B 0-255, #RRGGBB or a name such as white (RViz default 48,48,48)", &R::background,
               false},
    TextOption{"alpha", "RobotModel alpha, 0 to 1 (RViz default 1)", &R::alpha, false},
    TextOption{"tf-scale", "TF marker scale (RViz default 1)", &R::tf_scale, false},
    TextOption{"camera-info",
               "see the robot through this calibrated camera: camera_calibration's YAML file or a "
               "CameraInfo message as `ros2 topic echo` prints it; the image is its size, with P's "
               "intrinsics (rectified, as RViz's Camera display draws) (default: the orbit view)",
               &R::camera_info, true},
    TextOption{"camera-frame",
               "link the camera is attached to, in ROS's optical convention: z forward, x right, y "
               "down; with a bag also a frame of its TF (default: the fixed frame)",
               &R::camera_frame, false},
    TextOption{"camera-pose",
               "camera pose X,Y,Z,QX,QY,QZ,QW in m (optical convention) in the camera frame, or in "
               "the fixed frame without --camera-frame (default 0,0,0,0,0,0,1)",
               &R::camera_pose, false},
    TextOption{"near", "camera near clipping distance in m (default 0.01, RViz's Camera display's)", &R::near, false},
    TextOption{"far", "camera far clipping distance in m (default 100, RViz's Camera display's)", &R::far, false},
    TextOption{"underlay",
               "a camera image (PNG, the camera's size) drawn behind the robot with the robot "
               "over it at --underlay-alpha, as RViz's Camera display overlays (default none)",
               &R::underlay, true},
    TextOption{"underlay-alpha",
               "how much of the camera image shows through the robot, 0 to 1 (RViz's Overlay "
               "Alpha, default 0.5)",
               &R::underlay_alpha, false},
};

const std::array kFlagOptions{
    FlagOption{"no-clamp",
               "do not clamp values to the joint limits (default clamped, as joint_state_publisher's "
               "sliders are)",
               &R::no_clamp},
    FlagOption{"fit",
               "choose the distance (and, without --focal, the focal point) so the robot's silhouette "
               "fills the image up to --fit-margin, centred (RViz has no such view: default off)",
               &R::fit},
    FlagOption{"collision", "show collision geometry (RViz default off)", &R::collision},
    FlagOption{"no-visual", "hide visual geometry (RViz default shown)", &R::no_visual},
    FlagOption{"no-grid", "hide the grid (RViz default shown)", &R::no_grid},
    FlagOption{"tf", "show the TF display: frame names, axes and parent arrows (RViz default off)",
               &R::tf},
    FlagOption{"no-tf-names", "TF display without frame names (RViz default shown)", &R::no_tf_names},
    FlagOption{"no-tf-axes", "TF display without axes (RViz default shown)", &R::no_tf_axes},
    FlagOption{"no-tf-arrows", "TF display without parent arrows (RViz default shown)",
               &R::no_tf_arrows},
    FlagOption{"no-aa", "no multisampling (RViz default 4x)", &R::no_aa},
    FlagOption{"distort",
               "apply --camera-info's lens distortion (plumb_bob, rational_polynomial) with its K, "
               "so the image lines up with the raw camera image (default: rectified, no distortion)",
               &R::distort},
    FlagOption{"allow-missing-meshes",
               "draw the rest of the robot when a mesh or texture file cannot be found, one "
               "warning each (RViz draws the rest, a texture as Ogre's yellow and black warning "
               "texture, and logs an error; default: an error)",
               &R::allow_missing_meshes},
};

}  // namespace

std::span<const TextOption> TextOptions() { return kTextOptions; }
std::span<const FlagOption> FlagOptions() { return kFlagOptions; }

}  // namespace urdfsnap::request
