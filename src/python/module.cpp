// The pybind11 glue of `import urdfsnap` (the extension module urdfsnap._urdfsnap): Python values
// to the typed core and back (numpy arrays in, numpy arrays out), urdfsnap::Error as
// urdfsnap.Error, warnings as Python warnings. The work is RobotSession's (robot_session.h) and
// the image stage's; python/urdfsnap/__init__.py re-exports this with a few Python helpers, and
// __init__.pyi documents it for editors.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <future>
#include <memory>

#include "common/error.h"
#include "common/number_text.h"
#include "common/version.h"
#include "gl/gl_context.h"
#include "image/image_diff.h"
#include "image/image_file_names.h"
#include "image/png_reader.h"
#include "image/png_writer.h"
#include "python/robot_session.h"
#include "xacro/xacro.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace urdfsnap::python {

namespace {

// A path argument: str or os.PathLike.
std::string PathText(const py::object& path) { return py::str(py::module_::import("os").attr("fspath")(path)); }

// Xacro arguments: a dict NAME → value (str() of it: 0.5 → "0.5"), or None.
std::vector<std::pair<std::string, std::string>> XacroArgs(const py::object& args) {
  std::vector<std::pair<std::string, std::string>> pairs;
  if (args.is_none()) return pairs;
  for (const auto& [name, value] : args.cast<py::dict>()) pairs.emplace_back(py::str(name), py::str(value));
  return pairs;
}

// Package folders: a dict NAME → str or os.PathLike, or None.
std::map<std::string, std::string> Packages(const py::object& packages) {
  std::map<std::string, std::string> folders;
  if (packages.is_none()) return folders;
  for (const auto& [name, folder] : packages.cast<py::dict>()) {
    folders[py::str(name)] = PathText(py::reinterpret_borrow<py::object>(folder));
  }
  return folders;
}

request::ModelRequest ModelFrom(const py::object& path, const py::object& args, const py::object& packages,
                                bool xacro_ns) {
  return {PathText(path), XacroArgs(args), Packages(packages), xacro_ns};
}

// Each warning once through Python's warnings module, as urdfsnap.UrdfsnapWarning.
void Warn(const Warnings& warnings) {
  if (warnings.empty()) return;
  const py::object category = py::module_::import("urdfsnap._urdfsnap").attr("UrdfsnapWarning");
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& message : warnings.messages()) warn(message, category, "stacklevel"_a = 2);
}

// An H×W×3 uint8 array (or a PNG file's path) as an image; throws urdfsnap::Error naming `role`.
bool IsPath(const py::object& value) { return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"); }

image::Image ImageFrom(const py::object& value, const char* role) {
  if (IsPath(value)) return image::ReadPng(PathText(value));
  const auto array = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.ndim() != 3 || array.shape(2) != 3) {
    throw Error(std::string(role) + ": expected an H×W×3 uint8 array (or a PNG file's path)");
  }
  image::Image image{static_cast<int>(array.shape(1)), static_cast<int>(array.shape(0)), {}};
  image::CheckImageSize(image.width, image.height, role);
  image.rgb.assign(array.data(), array.data() + array.size());
  return image;
}

// Moves `pixels` into a new array of `shape` without copying them.
template <typename T>
py::array_t<T> ArrayOf(std::vector<T>&& pixels, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(pixels));
  py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), free);
}

py::bytes PngBytes(const image::Image& image) {
  const std::vector<std::uint8_t> png = image::EncodePng(image);
  return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
}

// Robot.render's result with depth, labels, mask or keypoints: the arrays, label index → link
// name, and the keypoints file's contents.
struct RenderResult {
  py::object color, depth, labels, mask, keypoints;
  py::list label_names;
};

struct Mimic {
  std::string joint;
  double multiplier, offset;
};

struct Joint {
  std::string name, type;
  py::object lower, upper;   // None without limits
  double default_value;
  py::object mimic;          // a Mimic, or None
};

// A urdfsnap.Robot: its session, shared with nothing else.
class Robot {
 public:
  Robot(const py::object& path, const py::object& args, const py::object& packages, bool xacro_ns)
      : session_(std::make_unique<RobotSession>(ModelFrom(path, args, packages, xacro_ns))) {
    Warn(session_->load_warnings());
  }

  const RobotSession& session() const { return *session_; }

  py::dict DefaultPositions() const {
    Warnings ignored;
    const std::vector<double> positions = session_->Positions({}, true, ignored);
    py::dict defaults;
    for (const std::string& name : session_->movable_joints()) {
      defaults[py::str(name)] = positions[session_->robot().FindJoint(name)];
    }
    return defaults;
  }

  std::vector<Joint> Joints() const {
    const model::Robot& robot = session_->robot();
    Warnings ignored;
    const std::vector<double> defaults = session_->Positions({}, true, ignored);
    std::vector<Joint> joints;
    for (size_t j = 0; j < robot.joints().size(); ++j) {
      const model::Joint& joint = robot.joints()[j];
      py::object mimic = py::none();
      if (joint.mimic_leader >= 0) {
        mimic = py::cast(Mimic{robot.joints()[joint.mimic_leader].name, joint.mimic_multiplier, joint.mimic_offset});
      }
      joints.push_back({joint.name, model::JointTypeName(joint.type),
                        joint.has_limits ? py::object(py::float_(joint.lower)) : py::none(),
                        joint.has_limits ? py::object(py::float_(joint.upper)) : py::none(), defaults[j], mimic});
    }
    return joints;
  }

  // One pose: `joints` a dict name → value, a sequence of values in joint_names order, or None.
  std::vector<double> Pose(const py::object& joints, bool clamp, Warnings& warnings) const {
    model::NamedValues given;
    if (py::isinstance<py::dict>(joints)) {
      for (const auto& [name, value] : joints.cast<py::dict>()) given.emplace_back(py::str(name), value.cast<double>());
    } else if (!joints.is_none()) {
      given = InJointOrder(joints.cast<std::vector<double>>(), "joints");
    }
    return Resolve(given, clamp, warnings);
  }

  // render_many's poses: an N×J array in joint_names order, or a sequence of Pose's arguments.
  std::vector<std::vector<double>> Poses(const py::object& positions, bool clamp, Warnings& warnings) const {
    std::vector<std::vector<double>> poses;
    if (py::isinstance<py::array>(positions) || (py::isinstance<py::sequence>(positions) && py::len(positions) > 0 &&
                                                 !py::isinstance<py::dict>(positions[py::int_(0)]))) {
      const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(positions);
      const size_t joints = session_->movable_joints().size();
      if (!array || array.ndim() != 2 || array.shape(1) != static_cast<py::ssize_t>(joints)) {
        throw Error("render_many: positions must be an N×" + std::to_string(joints) +
                    " array (one column per Robot.joint_names) or a list of dicts");
      }
      for (py::ssize_t k = 0; k < array.shape(0); ++k) {
        const double* row = array.data(k, 0);
        poses.push_back(Resolve(InJointOrder({row, row + joints}, "positions"), clamp, warnings));
      }
      return poses;
    }
    for (const py::handle pose : positions) poses.push_back(Pose(py::reinterpret_borrow<py::object>(pose), clamp, warnings));
    return poses;
  }

  // Renders `poses` into arrays of shape `batch` + image shape (`batch` empty for one image).
  py::object Render(const std::vector<std::vector<double>>& poses, const RenderCall& call,
                    std::vector<py::ssize_t> batch, py::object out, Warnings& warnings) {
    const render::RenderSettings settings = session_->Settings(call, warnings);
    const std::optional<gl::Backend> backend = BackendKeyword(call.gl_backend);
    const bool depth = call.depth, labels = call.labels, mask = call.extras.mask, keypoints = call.extras.keypoints;
    const py::ssize_t h = settings.size.height, w = settings.size.width;
    const auto shape = [&](std::vector<py::ssize_t> image) {
      image.insert(image.begin(), batch.begin(), batch.end());
      return image;
    };
    const auto checked_out = [&]() {
      auto array = py::array_t<std::uint8_t>::ensure(out);
      if (!array || !array.ptr() || array.ptr() != out.ptr() || !array.writeable() ||
          !(array.flags() & py::array::c_style) || std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()) != shape({h, w, 3})) {
        throw Error("out: expected a writeable C-contiguous uint8 array of shape (N, H, W, 3) for the poses and size given");
      }
      return array;
    };
    const bool single = batch.empty();
    py::array_t<std::uint8_t> color = out.is_none() ? py::array_t<std::uint8_t>(shape({h, w, 3})) : checked_out();
    py::array_t<float> depths(depth ? shape({h, w}) : std::vector<py::ssize_t>{0});
    py::array_t<std::uint16_t> label_image(labels ? shape({h, w}) : std::vector<py::ssize_t>{0});
    py::array_t<std::uint8_t> masks(mask ? shape({h, w}) : std::vector<py::ssize_t>{0});
    std::uint8_t* color_data = color.mutable_data();
    float* depth_data = depths.mutable_data();
    std::uint16_t* label_data = label_image.mutable_data();
    std::uint8_t* mask_data = masks.mutable_data();
    std::vector<std::string> keypoint_files(poses.size());
    image::Frame one;
    {
      py::gil_scoped_release released;
      std::lock_guard lock(session_->mutex());
      session_->Render(settings, backend, poses, {true, depth, labels}, call.extras,
                       [&](size_t k, image::Frame&& frame, dataset::FrameExtras&& extras) {
        keypoint_files[k] = std::move(extras.keypoints);
        if (single) {
          one = std::move(frame);
          if (mask) std::memcpy(mask_data, extras.mask.values.data(), h * w);
          return;
        }
        std::memcpy(color_data + k * h * w * 3, frame.colour.rgb.data(), frame.colour.rgb.size());
        if (depth) std::memcpy(depth_data + k * h * w, frame.depth.metres.data(), h * w * sizeof(float));
        if (labels) std::memcpy(label_data + k * h * w, frame.labels.labels.data(), h * w * sizeof(std::uint16_t));
        if (mask) std::memcpy(mask_data + k * h * w, extras.mask.values.data(), h * w);
      }, warnings);
    }
    if (single) {
      color = ArrayOf(std::move(one.colour.rgb), {h, w, 3});
      if (depth) depths = ArrayOf(std::move(one.depth.metres), {h, w});
      if (labels) label_image = ArrayOf(std::move(one.labels.labels), {h, w});
    }
    if (!depth && !labels && !mask && !keypoints) return color;
    // the keypoints file's contents, as json.load reads `render --keypoints`'s file
    py::object keypoint_dicts = py::none();
    if (keypoints) {
      const py::object loads = py::module_::import("json").attr("loads");
      py::list dicts;
      for (const std::string& text : keypoint_files) dicts.append(loads(text));
      keypoint_dicts = single ? dicts[0] : py::object(dicts);
    }
    RenderResult result{color, depth ? py::object(depths) : py::none(), labels ? py::object(label_image) : py::none(),
                        mask ? py::object(masks) : py::none(), keypoint_dicts, py::list()};
    result.label_names.append("");
    for (const model::Link& link : session_->robot().links()) result.label_names.append(link.name);
    return py::cast(std::move(result));
  }

 private:
  // `values` named by joint_names; throws urdfsnap::Error naming `what` for a wrong count.
  model::NamedValues InJointOrder(const std::vector<double>& values, const char* what) const {
    const std::vector<std::string>& names = session_->movable_joints();
    if (values.size() != names.size()) {
      throw Error(std::string(what) + ": expected " + std::to_string(names.size()) +
                  " values in Robot.joint_names order, got " + std::to_string(values.size()));
    }
    model::NamedValues given;
    for (size_t j = 0; j < names.size(); ++j) given.emplace_back(names[j], values[j]);
    return given;
  }

  // All joint positions for `given`, as `urdfsnap render -j` resolves them.
  std::vector<double> Resolve(const model::NamedValues& given, bool clamp, Warnings& warnings) const {
    for (const auto& [name, value] : given) {
      if (!std::isfinite(value)) throw Error("joint '" + name + "': expected a finite number, got " + FormatNumber(value));
    }
    return session_->Positions(given, clamp, warnings);
  }

  std::unique_ptr<RobotSession> session_;
};

// Numbers as `urdfsnap render` reads them: each the shortest text that reads back as it, joined.
std::string NumbersText(const py::handle& value, const char* separator) {
  std::string text;
  for (const double number : value.cast<std::vector<double>>()) text += (text.empty() ? "" : separator) + FormatNumber(number);
  return text;
}

// Robot.render's and render_many's keyword arguments as `urdfsnap render`'s options: not given,
// RViz's default (as the command line); an unknown keyword is a TypeError, as in Python.
RenderCall CallFrom(const py::kwargs& kwargs, const char* function) {
  RenderCall call;
  request::RenderRequest& r = call.request;
  std::map<std::string, std::string request::RenderRequest::*> numbers{
      {"yaw", &request::RenderRequest::yaw}, {"pitch", &request::RenderRequest::pitch},
      {"distance", &request::RenderRequest::distance}, {"fov", &request::RenderRequest::fov},
      {"alpha", &request::RenderRequest::alpha}, {"tf_scale", &request::RenderRequest::tf_scale},
      {"near", &request::RenderRequest::near}, {"far", &request::RenderRequest::far},
      {"underlay_alpha", &request::RenderRequest::underlay_alpha}};
  std::map<std::string, bool*> flags{{"fit", &r.fit}, {"tf", &r.tf}, {"collision", &r.collision},
                                     {"allow_missing_meshes", &r.allow_missing_meshes},
                                     {"depth", &call.depth}, {"labels", &call.labels}, {"distort", &r.distort},
                                     {"mask", &call.extras.mask}, {"keypoints", &call.extras.keypoints}};
  std::map<std::string, bool*> negated{{"grid", &r.no_grid}, {"visual", &r.no_visual}, {"antialias", &r.no_aa},
                                       {"clamp", &r.no_clamp}};
  for (const auto& [key, item] : kwargs) {
    const std::string name = py::str(key);
    const py::object value = py::reinterpret_borrow<py::object>(item);
    if (numbers.count(name)) r.*numbers[name] = FormatNumber(value.cast<double>());
    else if (flags.count(name)) *flags[name] = value.cast<bool>();
    else if (negated.count(name)) *negated[name] = !value.cast<bool>();
    else if (name == "focal") r.focal = NumbersText(value, ",");
    else if (name == "size") r.size = NumbersText(value, "x");
    // R, G, B from 0 to 255, or a colour as --background takes it ("white", "#RRGGBB")
    else if (name == "background") r.background = py::isinstance<py::str>(value) ? value.cast<std::string>() : NumbersText(value, ",");
    else if (name == "fixed_frame") r.fixed_frame = value.cast<std::string>();
    else if (name == "camera_info") r.camera_info = PathText(value);
    else if (name == "camera_frame") r.camera_frame = value.cast<std::string>();
    else if (name == "camera_pose") r.camera_pose = NumbersText(value, ",");
    // a PNG file's path, or the image itself as an H×W×3 array
    else if (name == "underlay") {
      if (IsPath(value)) r.underlay = PathText(value);
      else call.underlay = ImageFrom(value, "underlay");
    } else if (name == "mask_dilate") {
      call.extras.mask_dilate = value.cast<int>();
      dataset::CheckMaskDilate(call.extras.mask_dilate, "mask_dilate");
    }
    else if (name == "gl_backend") call.gl_backend = value.cast<std::string>();
    else throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name + "'");
  }
  return call;
}

// The value types Robot's properties and render's results hand out.
void BindValueTypes(py::module_& m) {
  py::class_<Mimic>(m, "Mimic", "A mimic joint's rule: value = multiplier * joint's value + offset.")
      .def_readonly("joint", &Mimic::joint)
      .def_readonly("multiplier", &Mimic::multiplier)
      .def_readonly("offset", &Mimic::offset)
      .def("__repr__", [](const Mimic& mi) {
        return "Mimic(joint='" + mi.joint + "', multiplier=" + FormatNumber(mi.multiplier) + ", offset=" + FormatNumber(mi.offset) + ")";
      });

  py::class_<Joint>(m, "Joint", "A joint of the robot, in URDF document order.")
      .def_readonly("name", &Joint::name)
      .def_readonly("type", &Joint::type, "'revolute', 'continuous', 'prismatic', 'fixed', 'floating' or 'planar'")
      .def_readonly("lower", &Joint::lower, "lower limit (rad or m); None for joints without limits")
      .def_readonly("upper", &Joint::upper, "upper limit (rad or m); None for joints without limits")
      .def_readonly("default", &Joint::default_value, "the value a render takes when none is given")
      .def_readonly("mimic", &Joint::mimic, "a Mimic when this joint follows another, else None")
      .def("__repr__", [](const Joint& j) { return "Joint(name='" + j.name + "', type='" + j.type + "')"; });

  py::class_<RenderResult>(m, "RenderResult", "Robot.render's result when depth or labels are asked for.")
      .def_readonly("color", &RenderResult::color, "H×W×3 uint8 RGB (N×H×W×3 from render_many)")
      .def_readonly("depth", &RenderResult::depth,
                    "H×W float32, metres along the viewing axis, NaN off the robot; None unless depth=True")
      .def_readonly("labels", &RenderResult::labels,
                    "H×W uint16, 1 + the index of the link seen (Robot.links order), 0 off the robot; None unless labels=True")
      .def_readonly("mask", &RenderResult::mask,
                    "H×W uint8, 255 on the robot (grown by mask_dilate pixels), 0 elsewhere; None unless mask=True")
      .def_readonly("keypoints", &RenderResult::keypoints,
                    "the keypoints file's contents as a dict (a list of them from render_many); None unless keypoints=True")
      .def_readonly("label_names", &RenderResult::label_names, "label value → link name ('' for 0)")
      .def("_repr_png_", [](const RenderResult& r) -> py::object {
        if (py::array(r.color).ndim() != 3) return py::none();
        return PngBytes(ImageFrom(r.color, "color"));
      });
}

// Module functions that need no robot: xacro, PNG files, the image comparison of urdfsnap.testing.
void BindFunctions(py::module_& m) {
  m.def("xacro", [](const py::object& path, const py::object& args, const py::object& packages, bool xacro_ns) {
    xacro::Options options;
    options.args = XacroArgs(args);
    options.packages = Packages(packages);
    options.xacro_ns = xacro_ns;
    Warnings warnings;
    std::string xml = xacro::ExpandFile(PathText(path), options, warnings).xml;
    Warn(warnings);
    return xml;
  }, "Expands a xacro file to URDF text, as `urdfsnap xacro` prints it.", "path"_a, "args"_a = py::none(),
        "packages"_a = py::none(), "xacro_ns"_a = false);

  m.def("read_png", [](const py::object& path) {
    image::Image image = image::ReadPng(PathText(path));
    return ArrayOf(std::move(image.rgb), {image.height, image.width, 3});
  }, "Reads a PNG file as an H×W×3 uint8 array.", "path"_a);
  m.def("write_png", [](const py::object& array, const py::object& path) {
    image::CheckImageFileName(PathText(path), image::ImageKind::kColour, "write_png");
    image::WritePng(ImageFrom(array, "write_png"), PathText(path));
  }, "Writes an H×W×3 uint8 array as a PNG file, atomically.", "image"_a, "path"_a);
  m.def("encode_png", [](const py::object& array) { return PngBytes(ImageFrom(array, "encode_png")); },
        "The PNG file bytes of an H×W×3 uint8 array.", "image"_a);

  m.def("_compare", [](const py::object& expected, const py::object& actual, int max_delta, double max_fraction,
                       double max_mean) {
    const image::Image e = ImageFrom(expected, "expected"), a = ImageFrom(actual, "actual");
    const image::DiffTolerance tolerance{max_delta, max_fraction, max_mean};
    const image::DiffStats stats = image::CompareImages(e, a, max_delta);
    image::Image picture = image::MakeDiffImage(e, a, max_delta);
    return py::dict("passed"_a = image::WithinTolerance(stats, tolerance), "fraction"_a = stats.fraction_over,
                    "max_delta"_a = stats.max_delta, "mean_delta"_a = stats.mean_delta,
                    "pixels_over"_a = stats.pixels_over, "description"_a = image::DescribeDiff(stats, tolerance),
                    "image"_a = ArrayOf(std::move(picture.rgb), {picture.height, picture.width, 3}));
  }, "expected"_a, "actual"_a, "max_delta"_a, "max_fraction"_a, "max_mean"_a);
  const image::DiffTolerance defaults;
  m.attr("DIFF_MAX_DELTA") = defaults.max_delta;
  m.attr("DIFF_MAX_FRACTION") = defaults.max_fraction;
  m.attr("DIFF_MAX_MEAN") = defaults.max_mean;
}

// urdfsnap.Robot: a loaded robot and its renders.
void BindRobot(py::module_& m) {
  py::class_<Robot> robot(m, "Robot", R"(A robot loaded from a URDF or xacro file, ready to render.)");
  robot.def(py::init<const py::object&, const py::object&, const py::object&, bool>(), "path"_a,
            "args"_a = py::none(), "packages"_a = py::none(), "xacro_ns"_a = false)
      .def_property_readonly("name", [](const Robot& r) { return r.session().robot().name(); })
      .def_property_readonly("path", [](const Robot& r) { return r.session().model().path; })
      .def_property_readonly("links", [](const Robot& r) {
        std::vector<std::string> names;
        for (const model::Link& link : r.session().robot().links()) names.push_back(link.name);
        return names;
      })
      .def_property_readonly("joints", &Robot::Joints)
      .def_property_readonly("joint_names", [](const Robot& r) { return r.session().movable_joints(); })
      .def("default_positions", &Robot::DefaultPositions)
      .def("_repr_png_", [](Robot& r) {
        Warnings ignored;
        const py::array_t<std::uint8_t> color =
            r.Render({r.Pose(py::none(), true, ignored)}, RenderCall{}, {}, py::none(), ignored);
        return PngBytes(ImageFrom(color, "color"));
      });
  robot.def("render", [](Robot& r, const py::object& joints, const py::kwargs& kwargs) {
    const RenderCall call = CallFrom(kwargs, "render");
    Warnings warnings;
    py::object result = r.Render({r.Pose(joints, !call.request.no_clamp, warnings)}, call, {}, py::none(), warnings);
    Warn(warnings);
    return result;
  }, "Renders one pose; see urdfsnap/__init__.pyi.", "joints"_a = py::none());
  robot.def("render_many", [](Robot& r, const py::object& positions, const py::object& out, const py::kwargs& kwargs) {
    const RenderCall call = CallFrom(kwargs, "render_many");
    Warnings warnings;
    const std::vector<std::vector<double>> poses = r.Poses(positions, !call.request.no_clamp, warnings);
    py::object result = r.Render(poses, call, {static_cast<py::ssize_t>(poses.size())}, out, warnings);
    Warn(warnings);
    return result;
  }, "Renders many poses with one GL context; see urdfsnap/__init__.pyi.", "positions"_a, py::kw_only(), "out"_a = py::none());
}

}  // namespace

}  // namespace urdfsnap::python

PYBIND11_MODULE(_urdfsnap, m) {
  using namespace urdfsnap;
  using namespace urdfsnap::python;
  m.doc() = "urdfsnap's typed core from Python: RViz-like images of URDF/xacro robots as numpy arrays";
  // Mesa (OSMesa or libEGL, LLVM behind it: ~0.1 s) loads on a thread from import on, overlapping
  // numpy's import and reading the model, as the commands overlap it (gl::StartLoadingGl). The
  // future waits at exit; _wait_for_gl lets __init__.py wait before a fork (a child forked while
  // dlopen runs would inherit the loader's lock held).
  static std::future<void> gl_loading = gl::StartLoadingGl();
  m.def("_wait_for_gl", [] {
    py::gil_scoped_release released;
    gl_loading.wait();
  });
  m.attr("__version__") = Version();
  py::register_exception<Error>(m, "Error", PyExc_ValueError);
  m.attr("UrdfsnapWarning") =
      py::reinterpret_steal<py::object>(PyErr_NewException("urdfsnap.UrdfsnapWarning", PyExc_UserWarning, nullptr));

  BindValueTypes(m);
  BindFunctions(m);
  BindRobot(m);
}
