// Every option of every command and every key of a snapshot suite, each classified here as a
// number, text or a flag; the numeric ones must refuse NaN and infinities with exit status 2 and
// an error naming them (CLI11's range checks let NaN through: `diff --max-fraction nan` once said
// "differ" for two identical images). The table is checked against what the binary itself lists
// (each command's --help, the suite reader's known keys), so a new option fails this test until
// it is classified here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/temp_folder.h"
#include "urdfsnap_process.h"

namespace {

namespace fs = std::filesystem;

enum class Kind { kNumber, kText, kFlag };

const std::string kMrm = std::string(URDFSNAP_SOURCE_DIR) + "/models/mrm_description/urdf/mrm.urdf";
const std::string kPng = std::string(URDFSNAP_SOURCE_DIR) + "/tests/fuzz/png_reader/rgb8.png";

struct CommandOption {
  const char* command;  // as typed after "urdfsnap" ("" for the options before any command)
  const char* option;   // the long name, or the short one when there is no long one
  Kind kind;
  // numbers: the arguments after the command that use the option, {v} standing for the value
  std::string usage = "";
};

// the camera options of render's table (a camera placed by --camera-pose makes the others apply)
void AddCameraOptions(std::vector<CommandOption>& options, const char* command, const std::string& before,
                      bool pose = true) {
  const std::string camera = before + (pose ? " --camera-pose 0,0,5,1,0,0,0 " : " ");
  if (pose) options.push_back({command, "--camera-pose", Kind::kNumber, before + " --camera-pose 0,0,{v},1,0,0,0"});
  options.push_back({command, "--near", Kind::kNumber, camera + "--near {v}"});
  options.push_back({command, "--far", Kind::kNumber, camera + "--far {v}"});
  if (pose) options.push_back({command, "--underlay-alpha", Kind::kNumber, camera + "--underlay-alpha {v}"});
  for (const char* text : {"--camera-info", "--camera-frame", "--underlay"}) {
    if (pose || std::string(text) == "--camera-info") options.push_back({command, text, Kind::kText});
  }
  options.push_back({command, "--distort", Kind::kFlag});
}

// render's view, display and pose options, which serve and docs have too (docs without --distance,
// --fit and the camera's: it refuses them with the reason, outside its --help); `before` is what
// comes before the option on the command line
void AddViewOptions(std::vector<CommandOption>& options, const char* command, const std::string& before,
                    bool fitted_only = false) {
  const auto number = [&](const char* option, const std::string& use) {
    options.push_back({command, option, Kind::kNumber, before + " " + use});
  };
  number("--joint", "-j base_link__link_01={v}");
  number("--size", "--size {v}x480");
  number("--yaw", "--yaw {v}");
  number("--pitch", "--pitch {v}");
  if (!fitted_only) number("--distance", "--distance {v}");
  number("--focal", "--focal 0,{v},0");
  number("--fov", "--fov {v}");
  // docs always fits: there --fit is only warned of, and the margin stands alone
  number("--fit-margin", fitted_only ? "--fit-margin {v}" : "--fit --fit-margin {v}");
  number("--background", "--background {v},0,0");
  number("--alpha", "--alpha {v}");
  number("--tf-scale", "--tf-scale {v}");
  for (const char* text : {"--help", "--package", "--joints", "--rviz", "--fixed-frame", "--follow"}) {
    options.push_back({command, text, std::string(text) == "--help" ? Kind::kFlag : Kind::kText});
  }
  for (const char* flag : {"--xacro-ns", "--no-clamp", "--fit", "--collision", "--no-visual", "--no-grid", "--tf",
                           "--no-tf-names", "--no-tf-axes", "--no-tf-arrows", "--no-aa", "--allow-missing-meshes"}) {
    if (!fitted_only || std::string(flag) != "--fit") options.push_back({command, flag, Kind::kFlag});
  }
  if (!fitted_only) AddCameraOptions(options, command, before);
}

// every option --help lists, per command
const std::vector<CommandOption>& Options() {
  static const std::vector<CommandOption> options = [] {
    std::vector<CommandOption> o = {
        {"", "--help", Kind::kFlag},
        {"", "--version", Kind::kFlag},
        {"", "--verbose", Kind::kFlag},
        {"", "--strict", Kind::kFlag},
        {"render", "--output", Kind::kText},
        {"render", "--depth", Kind::kText},
        {"render", "--labels", Kind::kText},
        {"info", "--help", Kind::kFlag},
        {"info", "--json", Kind::kFlag},
        {"info", "--package", Kind::kText},
        {"info", "--xacro-ns", Kind::kFlag},
        {"xacro", "--help", Kind::kFlag},
        {"xacro", "--output", Kind::kText},
        {"xacro", "--inorder", Kind::kFlag},
        {"xacro", "--xacro-ns", Kind::kFlag},
        {"xacro", "--deps", Kind::kFlag},
        {"xacro", "-q", Kind::kFlag},
        {"xacro", "--package", Kind::kText},
        {"diff", "--help", Kind::kFlag},
        {"diff", "--diff", Kind::kText},
        {"diff", "--depth", Kind::kFlag},
        {"diff", "--labels", Kind::kFlag},
        {"diff", "--max-delta", Kind::kNumber, "PNG PNG --max-delta {v}"},
        {"diff", "--max-fraction", Kind::kNumber, "PNG PNG --max-fraction {v}"},
        {"diff", "--max-mean", Kind::kNumber, "PNG PNG --max-mean {v}"},
        {"snapshot", "--help", Kind::kFlag},
        {"snapshot check", "--help", Kind::kFlag},
        {"snapshot check", "--report", Kind::kText},
        {"snapshot check", "--junit", Kind::kText},
        {"snapshot update", "--help", Kind::kFlag},
        {"snapshot check", "--shard", Kind::kText},
        {"snapshot check", "--no-shard", Kind::kFlag},
        {"snapshot check", "--results", Kind::kText},
        {"snapshot update", "--force", Kind::kFlag},
        {"snapshot update", "--shard", Kind::kText},
        {"snapshot update", "--no-shard", Kind::kFlag},
        {"snapshot merge", "--help", Kind::kFlag},
        {"snapshot merge", "--report", Kind::kText},
        {"snapshot merge", "--junit", Kind::kText},
        {"snapshot merge", "--results", Kind::kText},
        // serve refuses its bad options before it listens (a port of 0 in case it did not)
        {"serve", "--port", Kind::kNumber, "MRM --port {v}"},
        {"serve", "--bind", Kind::kText},
        {"serve", "--max-size", Kind::kNumber, "MRM --port 0 --max-size {v}x480"},
        {"docs", "--output", Kind::kText},
        {"docs", "--check", Kind::kText},
        {"docs", "--animations", Kind::kText},
        {"docs", "--stills", Kind::kText},
        {"docs", "--sections", Kind::kText},
        {"docs", "--quiet", Kind::kFlag},
        {"docs", "--shard", Kind::kText},
        {"docs", "--no-shard", Kind::kFlag},
        {"docs", "--jobs", Kind::kNumber, "MRM -o OUT --jobs {v}"},
        {"animate", "--output", Kind::kText},
        {"animate", "--trajectory", Kind::kText},
        {"animate", "--topic", Kind::kText},
        {"animate", "--fps", Kind::kNumber, "MRM -o OUT.gif --turntable --fps {v}"},
        {"animate", "--jobs", Kind::kNumber, "MRM -o OUT/%03d.png --turntable --jobs {v}"},
        {"animate", "--speed", Kind::kNumber, "MRM -o OUT.gif --turntable --speed {v}"},
        {"animate", "--duration", Kind::kNumber, "MRM -o OUT.gif --turntable --duration {v}"},
        {"animate", "--start", Kind::kNumber, "MRM -o OUT.gif --turntable --start {v}"},
        {"animate", "--end", Kind::kNumber, "MRM -o OUT.gif --turntable --end {v}"},
        {"animate", "--clamp", Kind::kFlag},
        {"animate", "--description-topic", Kind::kText},
        {"animate", "--strict-joints", Kind::kFlag},
        {"animate", "--print-frame", Kind::kNumber, "MRM -o OUT.gif --turntable --print-frame {v}"},
        {"animate", "--turntable", Kind::kFlag},
        {"animate", "--depth", Kind::kText},
        {"animate", "--labels", Kind::kText},
        {"animate", "--quiet", Kind::kFlag},
        {"animate", "--shard", Kind::kText},
        {"animate", "--no-shard", Kind::kFlag},
        {"animate", "--display", Kind::kText},
        {"animate", "--message", Kind::kText},
        {"render", "--mask", Kind::kText},
        {"render", "--display", Kind::kText},
        {"render", "--message", Kind::kText},
        {"render", "--bag", Kind::kText},
        // a number or an absolute stamp, read once the bag is; its NaN and infinities are refused
        // in hostile_input_test, which has the bags
        {"render", "--at", Kind::kText},
        {"render", "--topic", Kind::kText},
        {"render", "--description-topic", Kind::kText},
        {"render", "--underlay-topic", Kind::kText},
        {"render", "--camera-info-topic", Kind::kText},
        {"animate", "--underlay-topic", Kind::kText},
        {"animate", "--camera-info-topic", Kind::kText},
        {"render", "--keypoints", Kind::kText},
        {"render", "--mask-dilate", Kind::kNumber, "MRM -o OUT --mask M.png --mask-dilate {v}"},
        {"animate", "--mask", Kind::kText},
        {"animate", "--keypoints", Kind::kText},
        {"animate", "--mask-dilate", Kind::kNumber, "MRM -o OUT.gif --turntable --mask M/%d.png --mask-dilate {v}"},
        {"dataset", "--camera-poses", Kind::kText},
        {"dataset", "--camera-frame", Kind::kText},
        {"dataset", "--output", Kind::kText},
        {"dataset", "--count", Kind::kNumber, "MRM -o OUT --count {v}"},
        {"dataset", "--jobs", Kind::kNumber, "MRM -o OUT --count 1 --jobs {v}"},
        {"dataset", "--seed", Kind::kNumber, "MRM -o OUT --count 1 --seed {v}"},
        {"dataset", "--distance", Kind::kNumber, "MRM -o OUT --count 1 --distance 1:{v}"},
        {"dataset", "--elevation", Kind::kNumber, "MRM -o OUT --count 1 --elevation 0:{v}"},
        {"dataset", "--quiet", Kind::kFlag},
        {"dataset", "--shard", Kind::kText},
        {"dataset", "--no-shard", Kind::kFlag},
        {"dataset", "--size", Kind::kNumber, "MRM -o OUT --count 1 --size {v}x480"},
        {"dataset", "--fov", Kind::kNumber, "MRM -o OUT --count 1 --fov {v}"},
        {"dataset", "--background", Kind::kNumber, "MRM -o OUT --count 1 --background {v},0,0"},
        {"dataset", "--alpha", Kind::kNumber, "MRM -o OUT --count 1 --alpha {v}"},
        {"dataset", "--tf-scale", Kind::kNumber, "MRM -o OUT --count 1 --tf-scale {v}"},
    };
    AddViewOptions(o, "render", "MRM -o OUT");
    AddViewOptions(o, "serve", "MRM --port 0");
    AddViewOptions(o, "animate", "MRM -o OUT.gif --turntable");
    AddViewOptions(o, "docs", "MRM -o OUT", true);
    // dataset: the display options and the camera's intrinsics; poses and cameras are drawn
    for (const char* text : {"--help", "--package", "--rviz", "--fixed-frame", "--follow"}) {
      o.push_back({"dataset", text, std::string(text) == "--help" ? Kind::kFlag : Kind::kText});
    }
    for (const char* flag : {"--xacro-ns", "--no-clamp", "--collision", "--no-visual", "--no-grid", "--tf",
                             "--no-tf-names", "--no-tf-axes", "--no-tf-arrows", "--no-aa", "--allow-missing-meshes"}) {
      o.push_back({"dataset", flag, Kind::kFlag});
    }
    AddCameraOptions(o, "dataset", "MRM -o OUT --count 1", false);
    // every command that renders: the GL backend (a name) and the line saying which was taken
    for (const char* command : {"render", "serve", "animate", "docs", "dataset", "snapshot check", "snapshot update"}) {
      o.push_back({command, "--gl-backend", Kind::kText});
      o.push_back({command, "--verbose", Kind::kFlag});
    }
    return o;
  }();
  return options;
}

struct SuiteKey {
  const char* key;
  Kind kind;
  const char* value = "";  // numbers: the value that uses the key, {v} standing for the number
};

// every key a case of a suite file may have
const std::vector<SuiteKey>& SuiteKeys() {
  static const std::vector<SuiteKey> keys = {
      {"name", Kind::kText},
      {"golden", Kind::kText},
      {"model", Kind::kText},
      {"args", Kind::kText},
      {"packages", Kind::kText},
      {"xacro-ns", Kind::kFlag},
      {"bag", Kind::kText},
      // a number or a stamp, read once the bag is, as render's --at
      {"at", Kind::kText},
      {"displays", Kind::kText},
      {"joints", Kind::kNumber, "{base_link__link_01: {v}}"},
      {"max-delta", Kind::kNumber, "{v}"},
      {"max-fraction", Kind::kNumber, "{v}"},
      {"max-mean", Kind::kNumber, "{v}"},
      {"depth", Kind::kFlag},
      {"depth-golden", Kind::kText},
      {"depth-max-delta", Kind::kNumber, "{v}"},
      {"depth-max-fraction", Kind::kNumber, "{v}"},
      {"labels", Kind::kFlag},
      {"labels-golden", Kind::kText},
      {"labels-max-fraction", Kind::kNumber, "{v}"},
      {"size", Kind::kNumber, "{v}x480"},
      {"rviz", Kind::kText},
      {"yaw", Kind::kNumber, "{v}"},
      {"pitch", Kind::kNumber, "{v}"},
      {"distance", Kind::kNumber, "{v}"},
      {"focal", Kind::kNumber, "0,{v},0"},
      {"fov", Kind::kNumber, "{v}"},
      {"fit-margin", Kind::kNumber, "{v}"},
      {"fixed-frame", Kind::kText},
      {"follow", Kind::kText},
      {"background", Kind::kNumber, "{v},0,0"},
      {"alpha", Kind::kNumber, "{v}"},
      {"tf-scale", Kind::kNumber, "{v}"},
      {"no-clamp", Kind::kFlag},
      {"fit", Kind::kFlag},
      {"collision", Kind::kFlag},
      {"no-visual", Kind::kFlag},
      {"no-grid", Kind::kFlag},
      {"tf", Kind::kFlag},
      {"no-tf-names", Kind::kFlag},
      {"no-tf-axes", Kind::kFlag},
      {"no-tf-arrows", Kind::kFlag},
      {"no-aa", Kind::kFlag},
      {"allow-missing-meshes", Kind::kFlag},
      {"camera-info", Kind::kText},
      {"camera-frame", Kind::kText},
      {"camera-pose", Kind::kNumber, "0,0,{v},1,0,0,0"},
      {"near", Kind::kNumber, "{v}"},
      {"far", Kind::kNumber, "{v}"},
      {"underlay", Kind::kText},
      {"underlay-alpha", Kind::kNumber, "{v}"},
      {"distort", Kind::kFlag},
  };
  return keys;
}

// NaN and the infinities as a user might write them (YAML's spellings in suites too)
const std::vector<std::string> kNotFinite = {"nan", "NaN", "inf", "-inf", "+Infinity", "1e999"};
const std::vector<std::string> kNotFiniteInYaml = {"nan", ".nan", "inf", "-.inf", "1e999"};

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// the options a command's --help lists (the long name where there is one)
std::set<std::string> HelpOptions(const std::string& command) {
  const auto run = urdfsnap::test::RunUrdfsnap(command + " --help");
  EXPECT_EQ(run.status, 0) << command << ": " << run.err;
  static const std::regex kOptionLine(R"(^  (-[A-Za-z0-9])?,?(--[a-z][a-z0-9-]*)?[ \[])");
  std::set<std::string> names;
  std::istringstream lines(run.out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, kOptionLine)) continue;
    if (m[2].matched) names.insert(m[2]);
    else if (m[1].matched) names.insert(m[1]);
  }
  return names;
}

// the commands --help lists under "Subcommands:", with their own, as "snapshot check"
std::set<std::string> HelpCommands(const std::string& command = "") {
  const auto run = urdfsnap::test::RunUrdfsnap(command + " --help");
  std::set<std::string> commands;
  std::istringstream lines(run.out);
  bool listing = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("Subcommands:", 0) == 0) {
      listing = true;
    } else if (listing && line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ') {
      const std::string name = (command.empty() ? "" : command + " ") + line.substr(2, line.find(' ', 2) - 2);
      commands.insert(name);
      for (const std::string& sub : HelpCommands(name)) commands.insert(sub);
    } else if (listing && !line.empty() && line[0] != ' ') {
      listing = false;
    }
  }
  return commands;
}

TEST(NumericOptions, EveryOptionOfEveryCommandIsClassified) {
  std::map<std::string, std::set<std::string>> table;
  for (const CommandOption& o : Options()) table[o.command].insert(o.option);
  std::set<std::string> commands = {""};
  for (const std::string& command : HelpCommands()) commands.insert(command);
  std::set<std::string> tabled;
  for (const auto& [command, options] : table) tabled.insert(command);
  EXPECT_EQ(commands, tabled) << "urdfsnap has other commands than this test's table: add the new ones";
  for (const std::string& command : commands) {
    EXPECT_EQ(HelpOptions(command), table[command])
        << "'urdfsnap " << command << " --help' lists other options than this test's table: classify the new "
        << "ones (a number must refuse NaN and infinities)";
  }
}

TEST(NumericOptions, EveryKeyOfASuiteIsClassified) {
  const urdfsnap::test::TempFolder folder("numeric_options");
  const fs::path suite = folder.path() / "suite.yaml";
  std::ofstream(suite) << "cases:\n  - name: a\n    no-such-key: 1\n";
  const auto run = urdfsnap::test::RunUrdfsnap("snapshot check " + suite.string());
  const size_t known = run.err.find("(known: ");
  ASSERT_NE(known, std::string::npos) << run.err;
  std::set<std::string> listed;
  std::istringstream words(run.err.substr(known + 8, run.err.find(')', known) - known - 8));
  for (std::string word; std::getline(words, word, ',');) listed.insert(word.substr(word.find_first_not_of(' ')));
  std::set<std::string> table;
  for (const SuiteKey& k : SuiteKeys()) table.insert(k.key);
  EXPECT_EQ(listed, table) << "the suite reader knows other keys than this test's table: classify the new ones";
}

TEST(NumericOptions, RefuseNanAndInfinitiesNamingTheOption) {
  const urdfsnap::test::TempFolder folder("numeric_options");
  const std::string out = (folder.path() / "out.png").string();
  for (const CommandOption& o : Options()) {
    if (o.kind != Kind::kNumber) continue;
    for (const std::string& value : kNotFinite) {
      std::string arguments = Replace(Replace(Replace(o.usage, "{v}", value), "MRM", kMrm), "OUT", out);
      arguments = std::string(o.command) + " " + Replace(arguments, "PNG", kPng);
      const auto run = urdfsnap::test::RunUrdfsnap(arguments, 30);  // a server that started ends there
      EXPECT_EQ(run.status, 2) << "urdfsnap " << arguments << "\n" << run.out << run.err;
      EXPECT_EQ(run.err.rfind("urdfsnap: error: ", 0), 0u) << arguments << "\n" << run.err;
      EXPECT_NE(run.err.find(o.option), std::string::npos) << "the error does not name " << o.option << ":\n" << run.err;
      EXPECT_NE(run.err.find(value), std::string::npos) << "the error does not quote '" << value << "':\n" << run.err;
      EXPECT_FALSE(fs::exists(out)) << arguments;
      EXPECT_FALSE(fs::exists(out + ".gif")) << arguments;  // animate's
    }
  }
}

TEST(NumericOptions, SuiteKeysRefuseNanAndInfinitiesNamingTheKeyAndLine) {
  const urdfsnap::test::TempFolder folder("numeric_options");
  const fs::path suite = folder.path() / "suite.yaml";
  for (const SuiteKey& k : SuiteKeys()) {
    if (k.kind != Kind::kNumber) continue;
    for (const std::string& value : kNotFiniteInYaml) {
      std::ofstream(suite) << "cases:\n  - name: a\n    model: " << kMrm << "\n    " << k.key << ": "
                           << Replace(k.value, "{v}", value) << "\n";
      const auto run = urdfsnap::test::RunUrdfsnap("snapshot update " + suite.string());
      const std::string output = run.out + run.err;
      EXPECT_EQ(run.status, 2) << k.key << ": " << value << "\n" << output;
      EXPECT_NE(output.find("suite.yaml:4"), std::string::npos) << output;
      EXPECT_NE(output.find(k.key), std::string::npos) << "the error does not name '" << k.key << "':\n" << output;
      EXPECT_FALSE(fs::exists(folder.path() / "a.png")) << k.key << ": " << value;
    }
  }
}

}  // namespace
