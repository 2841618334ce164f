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
               "an RViz .rviz config: background, fixed frame, Grid, RobotModel, TF and Orbit view "
               "(the options below override it; default none: RViz's built-in defaults)",
               &R::rviz, true},
    TextOption{"yaw", "orbit yaw about +Z in rad (RViz default 0.785398)", &R::yaw, false},
    TextOption{"pitch", "orbit pitch in rad (RViz default 0.785398)", &R::pitch, false},
    TextOption{"distance", "orbit distance in m (RViz default 10)", &R::distance, false},
    TextOption{"focal", "orbit focal point X,Y,Z in m (RViz default 0,0,0)", &R::focal, false},
    TextOption{"fov", "vertical field of view in degrees (RViz default 45)", &R::fov, false},
    TextOption{"fixed-frame",
               "link whose frame the scene is shown in (RViz default 'map', which a URDF has not: "
               "here the root link)",
               &R::fixed_frame, false},
    TextOption{"background", "background colour: R,G,B 0-255, #RRGGBB or a name such as white (RViz default 48,48,48)", &R::background,
               false},
    TextOption{"alpha", "RobotModel alpha, 0 to 1 (RViz default 1)", &R::alpha, false},
    TextOption{"tf-scale", "TF marker scale (RViz default 1)", &R::tf_scale, false},
};

const std::array kFlagOptions{
    FlagOption{"no-clamp",
               "do not clamp values to the joint limits (default clamped, as joint_state_publisher's "
               "sliders are)",
               &R::no_clamp},
    FlagOption{"fit",
               "choose the distance (and, without --focal, the focal point) so the robot fills "
               "the image (RViz has no such view: default off)",
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
