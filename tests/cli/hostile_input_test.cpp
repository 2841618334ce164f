// Broken and hostile input against the urdfsnap binary, one case per row: malformed URDF, xacro
// bombs, bad joint values and options, garbage meshes and files that never end, unwritable outputs,
// outputs that are one file with another output or an input, paths that lead out of their folder.
// Every case must end with exit status 2 and one "urdfsnap: error: " line naming the culprit
// (warnings that led up to it may come first), before a deadline (a hang detector, not a speed
// test) and within 1.5 GB (2 GB of address space where that can be capped), leaving the existing
// output file byte-identical and no new file.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "common/version.h"
#include "support/gl_required.h"
#include "support/temp_folder.h"
#include "urdfsnap_process.h"

namespace {

namespace fs = std::filesystem;

struct HostileCase {
  std::string name;
  // files written into the case's folder first: name and bytes
  std::vector<std::pair<std::string, std::string>> files;
  // the command line after "urdfsnap"; {dir} is the case's folder, {out} its output file, {clip}
  // an existing animation (clip.mp4) and {bags} the test bags' folder
  std::string arguments;
  // text the error message must contain (the culprit: a file:line, name, value or option)
  std::string culprit;
  // whether the command gets as far as rendering (so needs a GL context) before it fails
  bool renders = false;
};

// Two links joined by `joint`, which starts on line 4.
std::string TwoLinks(const std::string& joint) {
  return "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n" + joint + "\n</robot>\n";
}

// A link whose visual geometry is `shape`, on line 3.
std::string OneShape(const std::string& shape) {
  return "<robot name=\"r\">\n<link name=\"a\">\n<visual><geometry>" + shape +
         "</geometry></visual>\n</link>\n</robot>\n";
}

std::string Xacro(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n" +
         body + "\n</robot>\n";
}

// A macro calling the previous one ten times, twelve levels deep: 10^12 links if nothing stops it.
std::string ExponentialXacro() {
  std::string body = "<xacro:macro name=\"m0\"><link name=\"l\"/></xacro:macro>\n";
  for (int level = 1; level <= 12; ++level) {
    body += "<xacro:macro name=\"m" + std::to_string(level) + "\">";
    for (int call = 0; call < 10; ++call) body += "<xacro:m" + std::to_string(level - 1) + "/>";
    body += "</xacro:macro>\n";
  }
  return Xacro(body + "<xacro:m12/>");
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// Properties each the previous one twice, thirty deep: a 2 GiB string if nothing stops it.
// `twice` says how a property doubles `{p}`, the previous one ("${{p}}${{p}}", "${{p} + {p}}").
std::string DoublingXacro(const std::string& twice) {
  std::string body = "<xacro:property name=\"p0\" value=\"ab\"/>\n";
  for (int level = 1; level <= 30; ++level) {
    // (appended piece by piece: gcc 12 warns about "literal" + std::string temporaries here)
    body += "<xacro:property name=\"p";
    body += std::to_string(level);
    body += "\" value=\"";
    body += Replace(twice, "{p}", std::string("p").append(std::to_string(level - 1)));
    body += "\"/>\n";
  }
  return Xacro(body + "<link name=\"${p30}\"/>");
}

// YAML anchors ten deep, each aliasing the previous one ten times: 10^10 items unless aliases are
// shared, as PyYAML shares them.
std::string AliasBombYaml() {
  std::string yaml = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level < 10; ++level) {
    yaml += "a";
    yaml += std::to_string(level);
    yaml += ": &a";
    yaml += std::to_string(level);
    yaml += " [";
    for (int k = 0; k < 10; ++k) {
      yaml += k ? ", *a" : "*a";
      yaml += std::to_string(level - 1);
    }
    yaml += "]\n";
  }
  return yaml;
}

// XML entities nested ten deep, each ten times the one before ("billion laughs").
std::string EntityBomb(bool xacro_namespace) {
  std::string doc = "<?xml version=\"1.0\"?>\n<!DOCTYPE robot [\n<!ENTITY e0 \"lol\">\n";
  for (int level = 1; level <= 10; ++level) {
    doc += "<!ENTITY e" + std::to_string(level) + " \"";
    for (int i = 0; i < 10; ++i) doc += "&e" + std::to_string(level - 1) + ";";
    doc += "\">\n";
  }
  return doc + "]>\n<robot name=\"&e10;\"" +
         (xacro_namespace ? " xmlns:xacro=\"http://www.ros.org/wiki/xacro\"" : "") +
         "><link name=\"a\"/></robot>\n";
}

std::string Nested(const std::string& tag, int depth) {
  std::string doc = "<robot name=\"r\"><link name=\"a\"/>";
  for (int i = 0; i < depth; ++i) doc += "<" + tag + ">";
  for (int i = 0; i < depth; ++i) doc += "</" + tag + ">";
  return doc + "</robot>\n";
}

std::string Bytes(int count, unsigned seed) {
  std::string bytes;
  for (int i = 0; i < count; ++i) {
    seed = seed * 1103515245 + 12345;
    bytes += static_cast<char>(seed >> 16);
  }
  return bytes;
}

// A binary STL whose header claims four billion triangles and holds one.
std::string LyingStl() {
  std::string stl(80, ' ');
  stl += std::string("\xff\xff\xff\xff", 4);
  return stl + std::string(50, '\0');
}

// A small valid PNG from the fuzz seeds (3x2 RGB), to be broken.
std::string SeedPng() {
  std::ifstream in(std::string(URDFSNAP_SOURCE_DIR) + "/tests/fuzz/png_reader/rgb8.png", std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The seed PNG with the IHDR width and height replaced (big-endian at bytes 16 and 20).
std::string PngClaiming(std::uint32_t width, std::uint32_t height) {
  std::string png = SeedPng();
  for (int i = 0; i < 4; ++i) {
    png[16 + i] = static_cast<char>(width >> (24 - 8 * i));
    png[20 + i] = static_cast<char>(height >> (24 - 8 * i));
  }
  return png;
}

const std::string kMesh = "<mesh filename=\"mesh.stl\"/>";
const std::string kModel = "{dir}/robot.urdf";
const std::string kRender = "render " + kModel + " -o {out} ";
const std::string kAnimate = "animate " + kModel + " -o {clip} ";
const std::string kGoodRobot = TwoLinks(
    "<joint name=\"elbow\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
    "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>");

// A results file of an empty one-shard run whose report_dir is `report_dir` (JSON text).
std::string Results(const std::string& report_dir) {
  return "{\"format\":\"urdfsnap-snapshot-results\",\"format_version\":1,\"urdfsnap_version\":\"" +
         std::string(urdfsnap::Version()) + "\",\"suite\":{\"path\":\"s.yaml\",\"digest\":\"d\",\"cases\":0},"
         "\"shard\":{\"index\":1,\"count\":1,\"source\":\"\"},\"report_dir\":" + report_dir + ",\"cases\":[]}";
}

std::vector<HostileCase> Cases() {
  const auto robot = [](const std::string& urdf) {
    return std::vector<std::pair<std::string, std::string>>{{"robot.urdf", urdf}};
  };
  const auto xacro = [](const std::string& text) {
    return std::vector<std::pair<std::string, std::string>>{{"robot.xacro", text}};
  };
  const std::string render_xacro = "render {dir}/robot.xacro -o {out}";
  // the good robot and a trajectory file
  const auto plan = [](const std::string& name, const std::string& text) {
    return std::vector<std::pair<std::string, std::string>>{{"robot.urdf", kGoodRobot}, {name, text}};
  };
  const auto mesh = [&](const std::string& bytes) {
    return std::vector<std::pair<std::string, std::string>>{{"robot.urdf", OneShape(kMesh)},
                                                            {"mesh.stl", bytes}};
  };
  return {
      // malformed URDF
      {"unclosed_element", robot("<robot name=\"r\">\n<link name=\"a\">\n</robot>\n"), kRender,
       "robot.urdf:2: malformed XML"},
      {"empty_file", robot(""), kRender, "robot.urdf"},
      {"binary_garbage", robot(Bytes(3000, 7)), kRender, "robot.urdf"},
      {"not_a_robot", robot("<model/>\n"), kRender, "found <model>"},
      {"duplicate_link", robot("<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"a\"/>\n</robot>"),
       kRender, "robot.urdf:3: link 'a' is defined twice"},
      {"duplicate_joint",
       robot(TwoLinks("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
                      "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>")),
       kRender, "robot.urdf:5: joint 'j' is defined twice"},
      {"missing_child_link",
       robot(TwoLinks("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"ghost\"/></joint>")),
       kRender, "robot.urdf:4: joint 'j' names child link 'ghost'"},
      {"loop",
       robot("<robot name=\"r\">\n<link name=\"root\"/><link name=\"a\"/><link name=\"b\"/>\n"
             "<joint name=\"j1\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
             "<joint name=\"j2\" type=\"fixed\"><parent link=\"b\"/><child link=\"a\"/></joint>\n</robot>"),
       kRender, "robot.urdf:3: joint 'j1' closes a loop"},
      {"two_roots", robot("<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n</robot>"), kRender,
       "robot.urdf:3: robot 'r' has several root links"},
      {"unknown_joint_type",
       robot(TwoLinks("<joint name=\"j\" type=\"hinge\"><parent link=\"a\"/><child link=\"b\"/></joint>")),
       kRender, "robot.urdf:4: joint 'j' has unknown type 'hinge'"},
      {"revolute_without_limit",
       robot(TwoLinks("<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/></joint>")),
       kRender, "robot.urdf:4: joint 'j' is revolute but has no <limit>"},
      {"nan_origin",
       robot(TwoLinks("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/>"
                      "<origin xyz=\"0 nan 0\"/></joint>")),
       kRender, "robot.urdf:4: joint 'j': <origin xyz=\"0 nan 0\">"},
      {"infinite_limit",
       robot(TwoLinks("<joint name=\"j\" type=\"prismatic\"><parent link=\"a\"/><child link=\"b\"/>"
                      "<limit lower=\"0\" upper=\"inf\" effort=\"1\" velocity=\"1\"/></joint>")),
       kRender, "robot.urdf:4: joint 'j': <limit upper=\"inf\">"},
      {"garbage_number",
       robot(TwoLinks("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/>"
                      "<origin rpy=\"0 1.0.0 0\"/></joint>")),
       kRender, "<origin rpy=\"0 1.0.0 0\">"},
      {"zero_axis",
       robot(TwoLinks("<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>"
                      "<axis xyz=\"0 0 0\"/></joint>")),
       kRender, "robot.urdf:4: joint 'j' has a zero axis"},
      {"zero_box", robot(OneShape("<box size=\"1 0 1\"/>")), kRender,
       "robot.urdf:3: link 'a': <box size=\"1 0 1\">"},
      {"negative_sphere", robot(OneShape("<sphere radius=\"-1\"/>")), kRender,
       "robot.urdf:3: link 'a': <sphere radius=\"-1\">"},
      {"zero_cylinder", robot(OneShape("<cylinder radius=\"0\" length=\"1\"/>")), kRender,
       "<cylinder radius=\"0\">"},
      {"zero_mesh_scale", robot(OneShape("<mesh filename=\"m.stl\" scale=\"1 0 1\"/>")), kRender,
       "<mesh scale=\"1 0 1\">"},
      {"entity_bomb_urdf", robot(EntityBomb(false)), kRender, "robot.urdf:2: <!DOCTYPE>"},
      {"deep_nesting", robot(Nested("link", 100000)), kRender, "robot.urdf"},
      {"missing_model", {}, kRender, "robot.urdf: cannot read the model file"},
      {"model_is_a_folder", {}, "render {dir} -o {out}", "a folder without metadata.yaml, .mcap or .db3 files: not a ROS 2 bag"},
      {"endless_model", {}, "render /dev/zero -o {out}", "/dev/zero: cannot read the model file"},
      // xacro
      {"exponential_macros", xacro(ExponentialXacro()), render_xacro,
       "robot.xacro:5: expanded document exceeds the size limit"},
      {"exponential_macros_xacro_command", xacro(ExponentialXacro()),
       "xacro {dir}/robot.xacro -o {out}", "expanded document exceeds the size limit"},
      {"entity_bomb_xacro", xacro(EntityBomb(true)), render_xacro,
       "robot.xacro:15: XML parsing error: limit on input amplification factor"},
      {"infinite_recursion", xacro(Xacro("<xacro:macro name=\"m\"><xacro:m/></xacro:macro><xacro:m/>")),
       render_xacro, "macro"},
      {"self_include", xacro(Xacro("<xacro:include filename=\"robot.xacro\"/>")), render_xacro,
       "include depth exceeds the limit"},
      {"endless_include", xacro(Xacro("<xacro:include filename=\"/dev/zero\"/>")), render_xacro,
       "/dev/zero"},
      {"missing_include", xacro(Xacro("<xacro:include filename=\"nope.xacro\"/>")), render_xacro,
       "/nope.xacro [Errno 2] No such file or directory"},
      {"huge_string", xacro(Xacro("<link name=\"${'a' * 10**10}\"/>")), render_xacro,
       "robot.xacro:3"},
      // each stops where its string would pass 16 MiB (line 34 uses p30, which needs p24)
      {"string_doubling", xacro(DoublingXacro("${{p}}${{p}}")), render_xacro,
       "robot.xacro:34: substituted text too large: 33554432 bytes (the limit is 16777216)"},
      {"string_doubling_xacro_command", xacro(DoublingXacro("${{p}}${{p}}")), "xacro {dir}/robot.xacro -o {out}",
       "substituted text too large"},
      {"string_doubling_concatenation", xacro(DoublingXacro("${{p} + {p}}")), render_xacro,
       "robot.xacro:34: concatenated string too large"},
      {"string_doubling_format", xacro(DoublingXacro("${'%s%s' % ({p}, {p})}")), render_xacro,
       "robot.xacro:34: formatted string too large"},
      {"string_doubling_join", xacro(DoublingXacro("${''.join([{p}, {p}])}")), render_xacro,
       "robot.xacro:34: joined string too large"},
      {"yaml_alias_bomb",
       {{"robot.xacro", Xacro("<xacro:property name=\"d\" value=\"${xacro.load_yaml('bomb.yaml')}\"/>\n"
                              "<link name=\"${len([x for b in d.a9 for c in b for e in c for f in e for g in f "
                              "for h in g for i in h for x in i])}\"/>")},
        {"bomb.yaml", AliasBombYaml()}},
       render_xacro, "robot.xacro:4: comprehension result too large"},
      {"string_copies_in_a_loop",
       xacro(Xacro("<xacro:property name=\"p\" value=\"${'a' * 16000000}\"/>\n"
                   "<link name=\"${len([p.upper() for i in python.range(1000)])}\"/>")),
       render_xacro, "robot.xacro:4: expressions build more than 268435456 bytes of text in all"},
      {"undefined_property", xacro(Xacro("<link name=\"${nothing}\"/>")), render_xacro,
       "name 'nothing' is not defined"},
      {"bad_expression", xacro(Xacro("<link name=\"${1 +}\"/>")), render_xacro, "robot.xacro:3"},
      {"expanded_urdf_error", xacro(Xacro("<link name=\"a\"/>\n<link name=\"a\"/>")), render_xacro,
       "robot.xacro (expanded)"},
      // joint values and options
      {"unknown_joint", robot(kGoodRobot), kRender + "-j wrist=1", "'wrist'"},
      {"joint_value_not_a_number", robot(kGoodRobot), kRender + "-j elbow=abc", "'elbow=abc'"},
      {"joint_value_nan", robot(kGoodRobot), kRender + "-j elbow=nan", "'elbow=nan'"},
      {"joint_without_value", robot(kGoodRobot), kRender + "-j elbow", "'elbow'"},
      {"joint_file_bad_yaml",
       {{"robot.urdf", kGoodRobot}, {"pose.yaml", "elbow: 0.5\nwrist: [1, 2\n"}},
       kRender + "--joints {dir}/pose.yaml", "pose.yaml:3"},
      {"joint_file_string_value",
       {{"robot.urdf", kGoodRobot}, {"pose.json", "{\n\"elbow\": \"bent\"\n}"}},
       kRender + "--joints {dir}/pose.json", "pose.json:2: joint 'elbow'"},
      {"joint_file_endless", robot(kGoodRobot), kRender + "--joints /dev/zero",
       "/dev/zero: cannot read the joint file"},
      {"size_zero", robot(kGoodRobot), kRender + "--size 0x10", "--size '0x10'"},
      {"size_over_limit", robot(kGoodRobot), kRender + "--size 16385x16384", "--size '16385x16384'"},
      {"size_overflow", robot(kGoodRobot), kRender + "--size 99999999999999999999x1", "--size"},
      {"size_fraction", robot(kGoodRobot), kRender + "--size 1.5x2", "--size '1.5x2'"},
      {"yaw_infinite", robot(kGoodRobot), kRender + "--yaw inf", "--yaw 'inf'"},
      {"distance_negative", robot(kGoodRobot), kRender + "--distance -1",
       "--distance '-1': expected a value from 0.01 to 1e+06"},
      {"alpha_above_one", robot(kGoodRobot), kRender + "--alpha 2", "--alpha '2'"},
      {"background_out_of_range", robot(kGoodRobot), kRender + "--background 300,0,0",
       "--background '300,0,0'"},
      {"focal_two_numbers", robot(kGoodRobot), kRender + "--focal 1,2", "--focal '1,2'"},
      {"unknown_fixed_frame", robot(kGoodRobot), kRender + "--fixed-frame world", "'world'"},
      {"unknown_option", robot(kGoodRobot), kRender + "--bogus", "--bogus"},
      {"rviz_bad_yaml", {{"robot.urdf", kGoodRobot}, {"view.rviz", "Visualization Manager:\n  [\n"}},
       kRender + "--rviz {dir}/view.rviz", "view.rviz:"},
      {"rviz_endless", robot(kGoodRobot), kRender + "--rviz /dev/zero",
       "/dev/zero: cannot read the .rviz file"},
      {"strict_turns_a_warning_into_an_error", robot(kGoodRobot), kRender + "-j elbow=5 --strict",
       "'elbow'"},
      // meshes
      {"garbage_mesh", mesh(Bytes(5000, 3)), kRender, "robot.urdf:2: link 'a': mesh 'mesh.stl'"},
      {"empty_mesh", mesh(""), kRender, "mesh 'mesh.stl'"},
      {"lying_stl", mesh(LyingStl()), kRender, "mesh 'mesh.stl'"},
      {"missing_mesh", robot(OneShape(kMesh)), kRender, "mesh 'mesh.stl' not found"},
      {"endless_mesh", robot(OneShape("<mesh filename=\"/dev/zero\"/>")), kRender,
       "mesh '/dev/zero': /dev/zero is not a regular file"},
      {"mesh_in_unknown_package", robot(OneShape("<mesh filename=\"package://nowhere/m.stl\"/>")),
       kRender, "package 'nowhere' not found"},
      {"mesh_over_http", robot(OneShape("<mesh filename=\"http://example.com/m.stl\"/>")), kRender,
       "unsupported URI scheme 'http://'"},
      {"garbage_collada", {{"robot.urdf", OneShape("<mesh filename=\"mesh.dae\"/>")},
                           {"mesh.dae", "<?xml version=\"1.0\"?><COLLADA><library_geometries>"}},
       kRender, "mesh 'mesh.dae'"},
      // PNGs read by diff
      {"png_huge_header", {{"a.png", PngClaiming(100000, 100000)}, {"b.png", SeedPng()}},
       "diff {dir}/a.png {dir}/b.png --diff {out}", "a.png: PNG is 100000x100000 pixels"},
      {"png_lying_header", {{"a.png", SeedPng()}, {"b.png", PngClaiming(16384, 16384)}},
       "diff {dir}/a.png {dir}/b.png --diff {out}",
       "b.png: PNG claims 16384x16384 pixels but holds"},
      {"png_truncated", {{"a.png", SeedPng().substr(0, 50)}, {"b.png", SeedPng()}},
       "diff {dir}/a.png {dir}/b.png --diff {out}", "a.png: PNG chunk at byte 33 claims"},
      {"png_garbage", {{"a.png", Bytes(4000, 11)}, {"b.png", SeedPng()}},
       "diff {dir}/a.png {dir}/b.png --diff {out}", "a.png: not a PNG file"},
      {"png_endless", {{"b.png", SeedPng()}}, "diff /dev/zero {dir}/b.png --diff {out}",
       "/dev/zero: cannot read: larger than the limit of 512 MiB"},
      {"png_fuzz_regression",
       {{"a.png", SeedPng()}},
       "diff {dir}/a.png " + std::string(URDFSNAP_SOURCE_DIR) +
           "/tests/fuzz/png_reader/regression-no-failure-reason.png --diff {out}",
       "regression-no-failure-reason.png: cannot decode PNG: corrupt image data"},
      // snapshot suites and results files
      {"suite_endless", {}, "snapshot check /dev/zero --junit {out}",
       "/dev/zero: cannot read the suite file: larger than the limit of 64 MiB"},
      {"shard_huge", {{"suite.yaml", "cases:\n  - {name: a, model: m.urdf}\n"}},
       "snapshot check {dir}/suite.yaml --shard 1/99999999999999999999 --junit {out}",
       "--shard '1/99999999999999999999': expected K/N"},
      {"results_endless", {}, "snapshot merge /dev/zero --junit {out}",
       "/dev/zero: cannot read the results file: larger than the limit of 64 MiB"},
      {"results_folder", {}, "snapshot merge {dir} --junit {out}", "cannot read the results file: Is a directory"},
      {"results_deep_array", {{"r.json", std::string(1000000, '[') + std::string(1000000, ']')}},
       "snapshot merge {dir}/r.json --junit {out}", "r.json: not a urdfsnap results file"},
      {"results_deep_field",
       {{"r.json", "{\"format\":\"urdfsnap-snapshot-results\",\"format_version\":1,\"urdfsnap_version\":"
                   "\"0\",\"suite\":" + std::string(500000, '[') + std::string(500000, ']') + "}"}},
       "snapshot merge {dir}/r.json --junit {out}", "r.json: suite: expected an object, got a list"},
      {"results_truncated", {{"r.json", "{\"format\": \"urdfsnap-snapshot-res"}},
       "snapshot merge {dir}/r.json --junit {out}", "r.json:1: bad JSON"},
      {"results_number_overflow",
       {{"r.json", "{\"format\":\"urdfsnap-snapshot-results\",\"format_version\":1e999}"}},
       "snapshot merge {dir}/r.json --junit {out}", "r.json: bad JSON"},
      // outputs that cannot be written
      {"output_folder_missing", robot(kGoodRobot), "render " + kModel + " -o {dir}/no/such/out.png",
       "no/such/out.png: cannot write", true},
      {"output_under_a_file", robot(kGoodRobot), "render " + kModel + " -o {dir}/robot.urdf/out.png",
       "robot.urdf/out.png: cannot write: Not a directory", true},
      {"output_is_a_folder", robot(kGoodRobot), "render " + kModel + " -o {dir}", "cannot write", true},
      {"stdout_full", xacro(Xacro("<link name=\"a\"/>")), "xacro {dir}/robot.xacro > /dev/full",
       "cannot write to standard output"},
      {"info_stdout_full", robot(kGoodRobot), "info " + kModel + " > /dev/full",
       "cannot write to standard output"},
      // outputs that are one file with another output or an input, refused before anything is drawn
      {"depth_is_the_output", robot(kGoodRobot), kRender + "--depth {out}", "--depth '{out}': the same file as -o"},
      {"labels_are_the_output", robot(kGoodRobot), kRender + "--labels {out}", "--labels '{out}': the same file as -o"},
      {"label_names_are_the_output", robot(kGoodRobot), "render " + kModel + " -o {dir}/seg.json --labels {dir}/seg.png",
       "the link names of --labels '{dir}/seg.json': the same file as -o"},
      {"depth_and_labels_one_file", robot(kGoodRobot), kRender + "--depth {dir}/both.png --labels {dir}/both.png",
       "--labels '{dir}/both.png': the same file as --depth"},
      {"output_is_the_model", robot(kGoodRobot), "render " + kModel + " -o " + kModel,
       "-o '{dir}/robot.urdf': the same file as the model"},
      {"output_is_the_model_by_another_name", robot(kGoodRobot), "render " + kModel + " -o {dir}/./x/../robot.urdf",
       "the same file as the model"},
      {"depth_folder_missing", robot(kGoodRobot), kRender + "--depth {dir}/no/such/d.png",
       "no/such/d.png: cannot write: No such file or directory"},
      {"depth_under_a_file", robot(kGoodRobot), kRender + "--depth {dir}/robot.urdf/d.npy",
       "robot.urdf/d.npy: cannot write: Not a directory"},
      {"anim_depth_is_the_output", robot(kGoodRobot),
       "animate " + kModel + " --turntable -o {dir}/f/%05d.png --depth {dir}/f/%05d.png",
       "-o '{dir}/f/%05d.png': may name the same files as --depth"},
      {"anim_labels_among_the_frames", robot(kGoodRobot),
       "animate " + kModel + " --turntable -o {dir}/f/%d.png --labels {dir}/f/1%d.png", "may name the same files as"},
      {"anim_video_is_the_trajectory", robot(kGoodRobot), "animate " + kModel + " --trajectory {clip} -o {clip}",
       "-o '{clip}': the same file as --trajectory"},
      {"docs_check_a_file", robot(kGoodRobot), "docs " + kModel + " --check {out}",
       "--check '{out}': exists and is not a folder"},
      {"docs_page_holds_the_model", robot(kGoodRobot), "docs " + kModel + " -o {dir}", "-o '{dir}': holds the model"},
      {"docs_page_is_the_model", robot(kGoodRobot), "docs " + kModel + " -o " + kModel,
       "-o '{dir}/robot.urdf': the same file as the model"},
      {"suite_junit_is_the_suite", {{"suite.yaml", "cases:\n  - {name: a, model: m.urdf}\n"}},
       "snapshot check {dir}/suite.yaml --junit {dir}/suite.yaml", "--junit '{dir}/suite.yaml': the same file as the suite"},
      {"suite_results_are_the_junit", {{"suite.yaml", "cases:\n  - {name: a, model: m.urdf}\n"}},
       "snapshot check {dir}/suite.yaml --junit {out} --results {out}", "--results '{out}': the same file as --junit"},
      {"suite_report_over_a_golden", {{"suite.yaml", "cases:\n  - {name: a, model: m.urdf, golden: a.diff.png}\n"}},
       "snapshot check {dir}/suite.yaml --report {dir}", "the same file as"},
      {"suite_report_outside_the_results_folder", {{"suite.yaml", "cases:\n  - {name: a, model: m.urdf}\n"}},
       "snapshot check {dir}/suite.yaml --report {dir}/report --results {dir}/sub/r.json",
       "--report '{dir}/report': must be inside the folder of --results"},
      {"suite_golden_outside_its_folder", {{"suite.yaml", "cases:\n  - {name: a, model: m.urdf, golden: ../../../../etc/a.png}\n"}},
       "snapshot update {dir}/suite.yaml", "suite.yaml:2: 'golden': '../../../../etc/a.png' leads outside the suite's folder"},
      {"suite_two_cases_one_golden",
       {{"suite.yaml", "cases:\n  - {name: a, model: m.urdf, golden: g.png}\n  - {name: b, model: m.urdf, golden: g.png}\n"}},
       "snapshot update {dir}/suite.yaml", "the golden of case 'b' '{dir}/g.png': the same file as the golden of case 'a'"},
      {"results_report_dir_outside", {{"r.json", Results("\"../../../../../../etc\"")}},
       "snapshot merge {dir}/r.json --report {dir}/merged", "r.json: report_dir: '../../../../../../etc' leads outside"},
      {"results_report_dir_absolute", {{"r.json", Results("\"/etc\"")}},
       "snapshot merge {dir}/r.json --report {dir}/merged", "r.json: report_dir: '/etc' leads outside"},
      {"merge_junit_is_a_results_file", {{"r.json", Results("null")}}, "snapshot merge {dir}/r.json --junit {dir}/r.json",
       "--junit '{dir}/r.json': the same file as the results file"},
      {"xacro_output_under_a_file", xacro(Xacro("<link name=\"a\"/>")),
       "xacro {dir}/robot.xacro -o {dir}/robot.xacro/out.urdf", "cannot write: Not a directory"},
      // animate: trajectories ({bags}: the test bags of the MCAP project's writer), options, outputs
      {"anim_times_not_increasing", plan("plan.csv", "time,elbow\n0,0\n1,0.5\n1,0.2\n"),
       kAnimate + "--trajectory {dir}/plan.csv", "plan.csv:4"},
      {"anim_unknown_joint", plan("plan.csv", "time,elbw\n0,0\n1,1\n"), kAnimate + "--trajectory {dir}/plan.csv",
       "plan.csv:1: robot 'r' has no joint 'elbw'"},  // none of its joints: as --strict-joints
      {"anim_nan_position", plan("plan.csv", "time,elbow\n0,0\n1,nan\n"), kAnimate + "--trajectory {dir}/plan.csv",
       "plan.csv:3"},
      {"anim_infinite_time", plan("plan.csv", "time,elbow\n0,0\ninf,1\n"), kAnimate + "--trajectory {dir}/plan.csv",
       "plan.csv:3"},
      {"anim_empty_table", plan("plan.csv", "time,elbow\n"), kAnimate + "--trajectory {dir}/plan.csv", "plan.csv"},
      {"anim_empty_yaml", plan("plan.yaml", ""), kAnimate + "--trajectory {dir}/plan.yaml", "plan.yaml"},
      {"anim_garbage_trajectory", plan("plan.yaml", Bytes(3000, 5)), kAnimate + "--trajectory {dir}/plan.yaml",
       "plan.yaml"},
      {"anim_trajectory_time_goes_back",
       plan("plan.yaml", "joint_names: [elbow]\npoints:\n- {positions: [0], time_from_start: 1}\n"
                         "- {positions: [1], time_from_start: 0.5}\n"),
       kAnimate + "--trajectory {dir}/plan.yaml", "plan.yaml:4"},
      {"anim_joint_states_nan",
       plan("states.yaml", "header: {stamp: {sec: 1, nanosec: 0}}\nname: [elbow]\nposition: [0]\n---\n"
                           "header: {stamp: {sec: 2, nanosec: 0}}\nname: [elbow]\nposition: [.nan]\n"),
       kAnimate + "--trajectory {dir}/states.yaml", "states.yaml:"},
      {"anim_trajectory_missing", robot(kGoodRobot), kAnimate + "--trajectory {dir}/nothing.csv", "nothing.csv"},
      {"anim_trajectory_endless", robot(kGoodRobot), kAnimate + "--trajectory /dev/zero", "/dev/zero"},
      {"anim_bag_without_the_topic", robot(kGoodRobot), kAnimate + "--trajectory {bags}/no_joint_states.mcap",
       "no_joint_states.mcap"},
      {"anim_bag_other_topic", robot(kGoodRobot), kAnimate + "--trajectory {bags}/joint_states_zstd.mcap --topic /arm",
       "'/arm'"},
      {"anim_bag_wrong_type", robot(kGoodRobot), kAnimate + "--trajectory {bags}/wrong_type.mcap", "wrong_type.mcap"},
      {"anim_bag_no_messages", robot(kGoodRobot), kAnimate + "--trajectory {bags}/no_messages.mcap", "no_messages.mcap"},
      {"anim_bag_nan_position", robot(kGoodRobot), kAnimate + "--trajectory {bags}/nan_position.mcap",
       "nan_position.mcap: message 8"},
      {"anim_bag_time_goes_back", robot(kGoodRobot), kAnimate + "--trajectory {bags}/time_goes_back.mcap",
       "time_goes_back.mcap: message 6"},
      {"anim_bag_length_mismatch", robot(kGoodRobot), kAnimate + "--trajectory {bags}/length_mismatch.mcap",
       "length_mismatch.mcap: message 4"},
      {"anim_bag_garbage_message", robot(kGoodRobot), kAnimate + "--trajectory {bags}/garbage_message.mcap",
       "garbage_message.mcap"},
      {"anim_db3_not_sqlite", robot(kGoodRobot), kAnimate + "--trajectory {bags}/bad_not_sqlite.db3",
       "bad_not_sqlite.db3: not a rosbag2 SQLite file"},
      {"anim_db3_lies_about_tables", robot(kGoodRobot), kAnimate + "--trajectory {bags}/bad_text_data.db3",
       "bad_text_data.db3: not a rosbag2 SQLite file: row 4"},
      {"anim_db3_without_messages_table", robot(kGoodRobot),
       kAnimate + "--trajectory {bags}/bad_no_messages_table.db3", "no such table: messages"},
      {"anim_bag_joints_not_in_robot", robot(kGoodRobot),
       kAnimate + "--trajectory {bags}/joint_states_lz4.mcap --strict-joints", "no joint 'shoulder'"},
      {"anim_bag_corrupt_truncated_half", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_truncated_half.mcap",
       "corrupt_truncated_half.mcap"},
      {"anim_bag_corrupt_truncated_header", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_truncated_header.mcap",
       "corrupt_truncated_header.mcap"},
      {"anim_bag_corrupt_cut_without_end", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_cut_without_end.mcap",
       "corrupt_cut_without_end.mcap"},
      {"anim_bag_corrupt_zstd_data", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_zstd_data.mcap",
       "corrupt_zstd_data.mcap"},
      {"anim_bag_corrupt_lz4_data", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_lz4_data.mcap",
       "corrupt_lz4_data.mcap"},
      {"anim_bag_corrupt_crc", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_crc.mcap",
       "corrupt_crc.mcap"},
      {"anim_bag_corrupt_huge_chunk", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_huge_chunk.mcap",
       "corrupt_huge_chunk.mcap"},
      {"anim_bag_corrupt_huge_record", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_huge_record.mcap",
       "corrupt_huge_record.mcap"},
      {"anim_bag_corrupt_unknown_compression", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_unknown_compression.mcap",
       "corrupt_unknown_compression.mcap"},
      {"anim_bag_corrupt_no_header", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_no_header.mcap",
       "corrupt_no_header.mcap"},
      {"anim_bag_corrupt_not_mcap", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_not_mcap.mcap",
       "corrupt_not_mcap.mcap"},
      {"anim_bag_corrupt_empty", robot(kGoodRobot), kAnimate + "--trajectory {bags}/corrupt_empty.mcap",
       "corrupt_empty.mcap"},
      // hostile TF and descriptions in a rover's recording, drawn as a bag alone (its TF read for
      // the fixed frame odom or the TF display)
      {"bag_tf_nan", {}, "animate {bags}/rover_tf_nan.mcap --fixed-frame odom -o {clip}",
       "rover_tf_nan.mcap: message 4 on '/tf' (log time 1700000000.300000000 s): transform 'odom' -> 'base_link': a NaN"},
      {"bag_tf_loop", {}, "render --bag {bags}/rover_tf_loop.mcap --tf -o {out}",
       "rover_tf_loop.mcap: message 4 on '/tf' (log time 1700000000.300000000 s): transform 'base_link' -> 'odom': a loop"},
      {"bag_tf_two_parents", {}, "render {bags}/rover_tf_two_parents.mcap --at 0.5 --fixed-frame odom -o {out}",
       "frame 'base_link' already has the parent 'odom'"},
      {"bag_tf_backwards", {}, "animate {bags}/rover_tf_backwards.mcap --tf -o {clip}", "stamps go backwards"},
      {"bag_description_junk", {}, "render --bag {bags}/description_junk.mcap -o {out}",
       "description_junk.mcap: '/robot_description':1: malformed XML"},
      {"bag_description_claims_100_mb", {}, "render --bag {bags}/rover_description_huge.mcap -o {out}",
       "rover_description_huge.mcap: message 1 on '/robot_description' (log time 1700000000.000000000 s): not a "
       "std_msgs/msg/String in CDR: a string at byte 8 runs past the message's end"},
      {"bag_db3_not_sqlite", robot(kGoodRobot), "render " + kModel + " --bag {bags}/bad_not_sqlite.db3 -o {out}",
       "bad_not_sqlite.db3: not a rosbag2 SQLite file"},
      {"bag_db3_lies_about_tables", robot(kGoodRobot), "render " + kModel + " --bag {bags}/bad_text_data.db3 -o {out}",
       "bad_text_data.db3: not a rosbag2 SQLite file: row 4"},
      {"bag_at_outside", {}, "render --bag {bags}/rover_loop.mcap --at 1e300 -o {out}", "--at 1e+300"},
      {"bag_at_nan", {}, "render --bag {bags}/rover_loop.mcap --at nan -o {out}", "--at"},
      {"bag_follow_unknown", {}, "render --bag {bags}/rover_loop.mcap --follow nowhere -o {out}", "--follow 'nowhere'"},
      {"bags_without_stem", {}, "animate {bags}/rover_loop.mcap {bags}/rover_tf_nan.mcap -o {clip}", "put {stem}"},
      {"anim_nothing_moves", robot(kGoodRobot), kAnimate, "nothing moves"},
      {"anim_speed_without_trajectory", robot(kGoodRobot), kAnimate + "--turntable --speed 2", "--speed"},
      {"anim_unknown_output", robot(kGoodRobot), "animate " + kModel + " --turntable -o {dir}/clip.avi", "clip.avi"},
      {"anim_png_without_number", robot(kGoodRobot), "animate " + kModel + " --turntable -o {dir}/clip.png",
       "clip.png"},
      {"anim_output_unwritable", robot(kGoodRobot), "animate " + kModel + " --turntable -o /proc/clip.mp4",
       "/proc/clip.mp4"},
      {"anim_output_under_a_file", robot(kGoodRobot), "animate " + kModel + " --turntable -o {dir}/robot.urdf/c.mp4",
       "robot.urdf"},
      {"anim_frames_under_a_file", robot(kGoodRobot),
       "animate " + kModel + " --turntable -o {dir}/robot.urdf/%05d.png", "robot.urdf"},
      {"anim_odd_size_mp4", robot(kGoodRobot), kAnimate + "--turntable --size 321x240", "321x240"},
      {"anim_depth_without_number", robot(kGoodRobot), kAnimate + "--turntable --depth {dir}/d.png", "--depth"},
      {"anim_depth_jpeg", robot(kGoodRobot), kAnimate + "--turntable --depth {dir}/d/%d.jpg", "--depth"},
      {"anim_labels_npy", robot(kGoodRobot), kAnimate + "--turntable --labels {dir}/l/%d.npy", "--labels"},
      {"anim_strict_clamp", plan("plan.csv", "time,elbow\n0,0\n1,5\n"),
       kAnimate + "--trajectory {dir}/plan.csv --strict", "joint 'elbow'"},
      {"anim_print_frame_negative", robot(kGoodRobot), "animate " + kModel + " --turntable --print-frame -1",
       "--print-frame"},
      {"anim_too_many_frames", robot(kGoodRobot), kAnimate + "--turntable --fps 1000 --duration 1e5", "frames"},
      {"anim_fps_0", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --fps 0", "frame rate"},
      {"anim_fps_minus_1", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --fps -1", "frame rate"},
      {"anim_fps_nan", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --fps nan", "--fps"},
      {"anim_fps_inf", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --fps inf", "--fps"},
      {"anim_fps_abc", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --fps abc", "--fps"},
      {"anim_fps_1e9", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --fps 1e9", "frame rate"},
      {"anim_speed_0", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--trajectory {dir}/plan.csv --speed 0", "speed"},
      {"anim_speed_minus_2", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--trajectory {dir}/plan.csv --speed -2", "speed"},
      {"anim_speed_nan", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--trajectory {dir}/plan.csv --speed nan", "--speed"},
      {"anim_speed_inf", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--trajectory {dir}/plan.csv --speed inf", "--speed"},
      {"anim_duration_0", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --duration 0", "duration"},
      {"anim_duration_minus_1", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --duration -1", "duration"},
      {"anim_duration_nan", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --duration nan", "--duration"},
      {"anim_duration_inf", plan("plan.csv", "time,elbow\n0,0\n1,1\n"), kAnimate + "--turntable --duration inf", "--duration"},
  };
}

// gtest prints a failing case's parameter: its name is enough
void PrintTo(const HostileCase& c, std::ostream* os) { *os << c.name; }

class HostileInputTest : public ::testing::TestWithParam<HostileCase> {};


std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::set<std::string> Listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) names.insert(entry.path().string());
  return names;
}

// The number of "urdfsnap: error: " lines in `err`; fails the test for a line that is neither
// that, a warning, nor an indented continuation (xacro's include and macro chain).
int ErrorLines(const std::string& err) {
  int errors = 0;
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("urdfsnap: error: ", 0) == 0) {
      ++errors;
    } else if (line.rfind("urdfsnap: warning: ", 0) != 0 && line.rfind("  ", 0) != 0) {
      ADD_FAILURE() << "unexpected line on stderr: " << line;
    }
  }
  return errors;
}

TEST_P(HostileInputTest, EndsWithOneLocatedErrorAndLeavesTheOutputAlone) {
  const HostileCase& c = GetParam();
  if (c.renders) URDFSNAP_REQUIRE_GL();
  const urdfsnap::test::TempFolder folder("hostile_" + c.name);
  const fs::path& dir = folder.path();
  for (const auto& [name, bytes] : c.files) std::ofstream(dir / name, std::ios::binary) << bytes;
  const fs::path out = dir / "out.png", clip = dir / "clip.mp4";
  const std::string precious = "an image the user cares about";
  std::ofstream(out, std::ios::binary) << precious;
  std::ofstream(clip, std::ios::binary) << precious;
  const std::set<std::string> before = Listing(dir);

  const bool asan = urdfsnap::test::BuiltWithAddressSanitizer();
  const std::string arguments =
      Replace(Replace(Replace(Replace(c.arguments, "{out}", out.string()), "{clip}", clip.string()), "{dir}",
                      dir.string()),
              "{bags}", std::string(URDFSNAP_BINARY_DIR) + "/test-bags");
  const auto run = urdfsnap::test::RunUrdfsnap(arguments, 60, asan ? 0 : 2048);

  EXPECT_FALSE(run.timed_out) << "still running after 60 s: urdfsnap " << arguments;
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_EQ(ErrorLines(run.err), 1) << run.err;
  const std::string culprit =
      Replace(Replace(Replace(c.culprit, "{out}", out.string()), "{clip}", clip.string()), "{dir}", dir.string());
  EXPECT_NE(run.err.find(culprit), std::string::npos) << "expected '" << culprit << "' in:\n" << run.err;
  EXPECT_EQ(run.out, "");
  if (!asan) {
    EXPECT_LT(run.peak_rss_kb, 1536 * 1024) << "peak memory";
  }
  EXPECT_EQ(ReadAll(out), precious);
  EXPECT_EQ(ReadAll(clip), precious);
  EXPECT_EQ(Listing(dir), before) << "a file appeared or disappeared";
}

// The string bombs stop in bounded memory, as the element-count bomb does: under 512 MB where the
// doubling bomb took more than 6 GB and a minute before strings were checked before being built.
TEST(HostileXacroStrings, StopInBoundedMemory) {
  if (urdfsnap::test::BuiltWithAddressSanitizer()) GTEST_SKIP() << "AddressSanitizer's own memory";
  for (const HostileCase& c : Cases()) {
    if (c.name.rfind("string_", 0) != 0) continue;
    const fs::path dir = fs::temp_directory_path() / ("urdfsnap_hostile_memory_" + c.name);
    fs::create_directories(dir);
    for (const auto& [name, bytes] : c.files) std::ofstream(dir / name, std::ios::binary) << bytes;
    const auto run = urdfsnap::test::RunUrdfsnap(
        Replace(Replace(c.arguments, "{out}", (dir / "out").string()), "{dir}", dir.string()), 60, 2048);
    EXPECT_EQ(run.status, 2) << c.name << ": " << run.err;
    EXPECT_LT(run.peak_rss_kb, 512 * 1024) << c.name << ": peak memory";
    fs::remove_all(dir);
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, HostileInputTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<HostileCase>& info) {
                           return info.param.name;
                         });

}  // namespace
