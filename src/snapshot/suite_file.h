// Snapshot suites: a YAML file listing views of robots (cases) and the golden image of each.
//
//   defaults:                      # optional: keys every case starts from
//     model: ../urdf/robot.xacro   # paths are relative to the suite file
//     size: 640x480
//   cases:
//     - name: home                 # [A-Za-z0-9_.-], unique; golden default: home.png
//     - name: reach
//       joints: {shoulder: 0.5, elbow: -1.0}   # or the name of a joint file
//       args: {use_gripper: "true"}            # xacro NAME:=VALUE
//       fit: true
//       golden: goldens/reach.png
//       depth: true                # also goldens/reach.depth.png (16-bit, mm)
//       labels: true               # also goldens/reach.labels.png (16-bit, 1 + link index)
//
// Case keys: name, golden, model, args, packages (PKG: DIR), xacro-ns, joints, every view and
// display option of `urdfsnap render` under its option name without the dashes (yaw, fit,
// background, rviz, tf, no-grid, ...), the tolerance of `urdfsnap diff` (max-delta,
// max-fraction, max-mean), and the depth and label goldens: depth, depth-golden, depth-max-delta,
// depth-max-fraction, labels, labels-golden, labels-max-fraction. A case's keys replace those of
// `defaults`, except that `joints`, `args` and `packages` add to them (a name given in both takes
// the case's value). Golden paths (golden, depth-golden, labels-golden) must stay inside the
// suite's folder, since `snapshot update` writes them; models, joint and .rviz files may be
// anywhere, as on the command line.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "image/gray16_diff.h"
#include "image/image_diff.h"
#include "request/render_request.h"

namespace urdfsnap::snapshot {

// A depth or link-label golden of a case, beside its colour golden.
struct Gray16Golden {
  bool wanted = false;         // `depth: true` / `labels: true` (or a `depth-golden:` path)
  std::string golden;          // its path; default the colour golden's with .depth.png / .labels.png
  image::Gray16Tolerance tolerance;
};

// A moment of a recording a case draws, as `render --bag BAG --at AT --display ...` draws it: the
// robot at the bag's joint states and TF then, with the displays of the case's .rviz file and
// `displays` showing the bag's messages up to it.
struct RecordingMoment {
  std::string bag;                    // a .mcap or .db3 file or rosbag2 folder; "" for none
  std::string at;                     // seconds from the first joint state, or a stamp ("" for 0)
  std::vector<std::string> displays;  // CLASS:TOPIC, as --display takes them
};

struct SnapshotCase {
  std::string name;
  int index = 0;              // position in the suite, 0-based
  int line = 0;               // of the case in the suite file
  request::RenderRequest request;
  RecordingMoment moment;
  std::string golden;         // path of the golden PNG (relative to the working directory)
  image::DiffTolerance tolerance;
  Gray16Golden depth{false, "", image::DefaultTolerance(image::Gray16Kind::kDepth)};
  Gray16Golden labels{false, "", image::DefaultTolerance(image::Gray16Kind::kLabels)};
  std::map<std::string, int> option_lines;  // the line each option was given on
};

struct Suite {
  std::string path;
  std::string digest;  // StableHashText of the file's bytes: which suite (and revision) results are of
  std::vector<SnapshotCase> cases;
};

// Reads the suite at `path`. Throws urdfsnap::Error "PATH:LINE: ..." for bad YAML, unknown or
// repeated keys, values of the wrong kind, a case without a model, bad or repeated case names, a
// golden outside the suite's folder.
Suite ReadSuite(const std::string& path);

// True for a usable case name: letters, digits, '_', '-' and '.', not "." or ".." (it names the
// golden and the report's image files).
bool IsCaseName(std::string_view name);

// The label for option `name` of `c` in error messages: "suite.yaml:12: yaw".
std::string OptionLocation(const Suite& suite, const SnapshotCase& c, std::string_view name);

}  // namespace urdfsnap::snapshot
