// `urdfsnap docs` against the binary: the page's files, byte-identical reruns, --check passing on a
// fresh page and failing after a joint limit changes, errors that leave nothing half-written, and
// folders it refuses to replace; worker processes (--jobs) making the same page, their errors and
// SIGTERM.
#include <filesystem>
#include <map>
#include <regex>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

// Every file below `folder` by relative path, with its bytes.
std::map<std::string, std::string> Files(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) files[fs::relative(entry.path(), folder).string()] = ReadBytes(entry.path());
  }
  return files;
}

class DocsTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    model_ = Write("mrm.urdf", ReadBytes(kMrm));
  }
  // The names in the folder itself (no temporary folders may be left beside a page).
  std::vector<std::string> Listing() const { return folder_->Listing(); }
  std::string model_;
};

TEST_F(DocsTest, WritesThePageAndTwoRunsAreByteIdentical) {
  URDFSNAP_REQUIRE_GL();
  const Result first = RunUrdfsnap("docs " + model_ + " -o " + Path("page"));
  ASSERT_EQ(first.status, 0) << first.output;
  const Result second = RunUrdfsnap("docs " + model_ + " -o " + Path("again"));
  ASSERT_EQ(second.status, 0) << second.output;
  const auto files = Files(Path("page"));
  EXPECT_EQ(files, Files(Path("again")));
  // pictures and animations as WebP by default
  for (const char* name : {"README.md", "index.html", "images/robot.webp", "images/tf.webp",
                           "images/turntable.webp", "joints/link_01__link_02/lower.webp",
                           "joints/link_01__link_02/default.webp", "joints/link_01__link_02/upper.webp",
                           "joints/link_01__link_02/sweep.webp"}) {
    EXPECT_TRUE(files.count(name)) << name;
  }
  EXPECT_FALSE(files.count("images/collision.webp")) << "mrm has no collision geometry";
  EXPECT_EQ(Listing(), (std::vector<std::string>{"again", "mrm.urdf", "page"}));  // no temporary folders
  // as PNG on request: the views at --size, the joints' pictures three quarters of it
  ASSERT_EQ(RunUrdfsnap("docs " + model_ + " --stills png --animations none -o " + Path("png")).status, 0);
  for (const auto& [name, bytes] : Files(Path("png"))) {
    if (name.ends_with(".png")) {
      EXPECT_GT(image::DecodePng(bytes, name).width, 0) << name;
    }
  }
  EXPECT_EQ(image::ReadPng(Path("png/images/robot.png")).width, 640);
  EXPECT_EQ(image::ReadPng(Path("png/joints/link_01__link_02/upper.png")).width, 480);
  fs::remove_all(Path("png"));
  // missing parent folders are made
  ASSERT_EQ(RunUrdfsnap("docs " + model_ + " -o " + Path("docs/robots/mrm")).status, 0);
  EXPECT_EQ(Files(Path("docs/robots/mrm")), files);
}

TEST_F(DocsTest, CheckPassesOnAFreshPageAndFailsAfterALimitChanges) {
  URDFSNAP_REQUIRE_GL();
  ASSERT_EQ(RunUrdfsnap("docs " + model_ + " --stills png -o " + Path("page")).status, 0);
  const Result fresh = RunUrdfsnap("docs " + model_ + " --stills png --check " + Path("page"));
  EXPECT_EQ(fresh.status, 0) << fresh.output;
  EXPECT_NE(fresh.output.find(Path("page") + ": up to date"), std::string::npos) << fresh.output;

  // the third joint's upper limit from π to 1 rad
  std::string urdf = ReadBytes(model_);
  const size_t joint = urdf.find("name=\"link_02__link_03\"");
  const size_t upper = urdf.find("upper=\"", joint);
  ASSERT_NE(upper, std::string::npos);
  urdf.replace(upper, urdf.find('"', upper + 7) - upper + 1, "upper=\"1\"");
  Write("mrm.urdf", urdf);
  const Result stale = RunUrdfsnap("docs " + model_ + " --stills png --check " + Path("page"));
  EXPECT_EQ(stale.status, 1) << stale.output;
  EXPECT_NE(stale.output.find(Path("page") + ": stale, "), std::string::npos) << stale.output;
  EXPECT_TRUE(std::regex_search(stale.output, std::regex("\n  README.md: line [0-9]+ differs: committed '.*', now "
                                                         "'.*-3.14 to 1 rad \\(-179.9° to 57.3°\\)")))
      << stale.output;
  EXPECT_NE(stale.output.find("  index.html: line "), std::string::npos) << stale.output;
  EXPECT_NE(stale.output.find("  joints/link_02__link_03/upper.png: max delta "), std::string::npos) << stale.output;
  EXPECT_NE(stale.output.find("regenerate it: the same command with -o "), std::string::npos);
  // pictures of the joints it does not change still match
  EXPECT_EQ(stale.output.find("joints/base_link__link_01/"), std::string::npos) << stale.output;
  EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf", "page"}));
}

TEST_F(DocsTest, CheckFindsMissingExtraAndUndecodableFiles) {
  URDFSNAP_REQUIRE_GL();
  ASSERT_EQ(RunUrdfsnap("docs " + model_ + " --stills png -o " + Path("page")).status, 0);
  fs::remove(Path("page/images/tf.png"));
  Write("page/notes.txt", "mine");
  Write("page/images/robot.png", "not a png");
  const Result r = RunUrdfsnap("docs " + model_ + " --stills png --check " + Path("page"));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("  images/tf.png: missing from the committed page\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  notes.txt: not in a fresh page\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  images/robot.png: " + Path("page/images/robot.png")), std::string::npos) << r.output;

  const Result none = RunUrdfsnap("docs " + model_ + " --check " + Path("nothing"));
  EXPECT_EQ(none.status, 1) << none.output;
  EXPECT_NE(none.output.find("no page here"), std::string::npos) << none.output;

  // a committed page is input: a link out of it is not followed (nor a pipe read)
  fs::remove(Path("page/images/robot.png"));
  fs::create_symlink("/etc/passwd", Path("page/images/robot.png"));
  const Result linked = RunUrdfsnap("docs " + model_ + " --stills png --check " + Path("page"));
  EXPECT_EQ(linked.status, 2) << linked.output;
  EXPECT_NE(linked.output.find("the page's file 'images/robot.png': 'images/robot.png' leads outside"),
            std::string::npos) << linked.output;
}

TEST_F(DocsTest, CheckComparesAnimationsByTheirFrames) {
  for (const std::string format : {"gif", "webp"}) {
    const std::string page = Path("page_" + format), options = " --animations " + format;
    ASSERT_EQ(RunUrdfsnap("docs " + model_ + options + " -o " + page).status, 0);
    const std::string sweep = page + "/joints/link_01__link_02/sweep." + format;
    const std::string turntable = page + "/images/turntable." + format;
    ASSERT_TRUE(fs::exists(sweep) && fs::exists(turntable)) << format;
    // rendered on a CPU without AVX, the GIFs' dithering differs in bytes but not in substance
    const std::string other_cpu = Path("other_cpu_" + format);
    ASSERT_EQ(RunUrdfsnap("docs " + model_ + options + " -o " + other_cpu, "GALLIUM_OVERRIDE_CPU_CAPS=sse2").status, 0);
    if (format == "gif") {
      EXPECT_NE(ReadBytes(other_cpu + "/images/turntable.gif"), ReadBytes(turntable)) << "no difference to tolerate";
    }
    const Result same = RunUrdfsnap("docs " + model_ + options + " --check " + other_cpu);
    EXPECT_EQ(same.status, 0) << same.output;
    // another joint's sweep in its place, and a turntable cut short, are stale
    fs::copy_file(page + "/joints/link_02__link_03/sweep." + format, sweep, fs::copy_options::overwrite_existing);
    const std::string bytes = ReadBytes(turntable);
    Write(turntable.substr(dir_.string().size() + 1), bytes.substr(0, bytes.size() / 2));
    const Result stale = RunUrdfsnap("docs " + model_ + options + " --check " + page);
    EXPECT_EQ(stale.status, 1) << stale.output;
    EXPECT_NE(stale.output.find("  joints/link_01__link_02/sweep." + format + ": frame "), std::string::npos)
        << stale.output;
    EXPECT_NE(stale.output.find("  images/turntable." + format + ": "), std::string::npos) << stale.output;
    // a cut GIF holds its first frames; a cut WebP does not read at all
    const std::string cut = format == "gif" ? " frames, now 36\n" : "not an animated WebP file";
    EXPECT_NE(stale.output.find(cut), std::string::npos) << stale.output;
  }
}

TEST_F(DocsTest, ReplacesAnOlderPageAsAWhole) {
  URDFSNAP_REQUIRE_GL();
  ASSERT_EQ(RunUrdfsnap("docs " + model_ + " -o " + Path("page")).status, 0);
  Write("page/joints/gone.png", "left over from an older robot");
  const Result r = RunUrdfsnap("docs " + model_ + " -o " + Path("page") + " --sections 'link_01*'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(Path("page/joints/gone.png")));
  EXPECT_FALSE(fs::exists(Path("page/joints/base_link__link_01")));
  EXPECT_TRUE(fs::exists(Path("page/joints/link_01__link_02/upper.webp")));
  EXPECT_NE(ReadBytes(Path("page/README.md")).find("4 movable joints are left out of this page (--sections)."),
            std::string::npos);
  EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf", "page"}));
}

TEST_F(DocsTest, ErrorsAreOneLineWithStatus2AndWriteNothing) {
  struct Case {
    std::string arguments, message;
  };
  Write("broken.urdf", "<robot name=\"b\"><link name=\"a\"/><joint name=\"j\" type=\"hinge\"/></robot>");
  fs::create_directory(Path("mine"));
  Write("mine/thesis.tex", "precious");
  const std::vector<Case> cases = {
      {Path("broken.urdf") + " -o " + Path("page"), "broken.urdf:1: joint 'j'"},
      {model_ + " -o " + Path("page") + " --sections 'elbow*'", "--sections 'elbow*' matches none of the movable joints"},
      // --joints was the section filter: now the page's pose, as in render
      {model_ + " -o " + Path("page") + " --joints 'link_01*'",
       "--joints 'link_01*': no such joint file (--joints is the page's pose as in render, a YAML/JSON joint "
       "file; to give sections only to some joints use --sections 'link_01*')"},
      {model_ + " -o " + Path("page") + " -j nothing=1", "nothing"},
      // view options that cannot work on a page of fitted pictures say why
      {model_ + " -o " + Path("page") + " --distance 3", "docs: --distance does not apply: each picture of the page "
       "is fitted to what it shows (choose the direction with --yaw and --pitch, the point looked at with --focal)"},
      {model_ + " -o " + Path("page") + " --camera-info cam.yaml", "docs: --camera-info does not apply"},
      {model_ + " -o " + Path("page") + " --yaw sideways", "--yaw"},
      {model_, "give -o DIR to write a page, or --check DIR"},
      {model_ + " -o " + Path("page") + " --check " + Path("page"), "give -o DIR to write a page, or --check DIR"},
      {model_ + " -o " + Path("mine"), "mine: is a folder with other files than a page of urdfsnap docs"},
      {model_ + " -o " + Path("mrm.urdf"), "-o '" + model_ + "': the same file as the model"},
      {model_ + " -o " + Path(""), "holds the model '" + model_ + "'"},
      {model_ + " --check " + model_, "--check '" + model_ + "': exists and is not a folder"},
      {model_ + " -o " + Path("mrm.urdf/page"), "page: cannot write: Not a directory"},
  };
  for (const Case& c : cases) {
    const Result r = RunUrdfsnap("docs " + c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("urdfsnap: error: ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.arguments << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  EXPECT_EQ(Listing(), (std::vector<std::string>{"broken.urdf", "mine", "mrm.urdf"}));
  EXPECT_EQ(ReadBytes(Path("mine/thesis.tex")), "precious");
}

TEST_F(DocsTest, TheJointOptionsPoseThePage) {
  URDFSNAP_REQUIRE_GL();
  const std::string common = " --stills png --animations none --sections link_02__link_03";
  ASSERT_EQ(RunUrdfsnap("docs " + model_ + common + " -o " + Path("zero")).status, 0);
  const Result posed = RunUrdfsnap("docs " + model_ + common + " -j link_01__link_02=0.8 -o " + Path("posed"));
  ASSERT_EQ(posed.status, 0) << posed.output;
  Write("pose.yaml", "link_01__link_02: 0.8\n");
  const Result filed = RunUrdfsnap("docs " + model_ + common + " --joints " + Path("pose.yaml") + " -o " + Path("filed"));
  ASSERT_EQ(filed.status, 0) << filed.output;
  // the robot, and the other joint's section, at the pose; the same from a joint file
  const std::string section = "joints/link_02__link_03/default.png";
  for (const std::string& file : {std::string("images/robot.png"), section}) {
    EXPECT_NE(ReadBytes(Path("posed/" + file)), ReadBytes(Path("zero/" + file))) << file;
    EXPECT_EQ(ReadBytes(Path("posed/" + file)), ReadBytes(Path("filed/" + file))) << file;
  }
  EXPECT_NE(ReadBytes(Path("posed/README.md")).find("at the page's pose (given with -j or --joints"), std::string::npos);
  EXPECT_NE(ReadBytes(Path("zero/README.md")).find("its default (joint_state_publisher's)"), std::string::npos);
  // docs always fits: --fit changes nothing and says so
  const Result fit = RunUrdfsnap("docs " + model_ + common + " --fit -o " + Path("fit"));
  ASSERT_EQ(fit.status, 0) << fit.output;
  EXPECT_NE(fit.output.find("warning: --fit is ignored: docs always fits each picture"), std::string::npos) << fit.output;
  EXPECT_EQ(ReadBytes(Path("fit/images/robot.png")), ReadBytes(Path("zero/images/robot.png")));
}

// --jobs: the page made by worker processes is the page one process makes, byte for byte; a
// model on standard input is made in one process (a worker could not read it again).
TEST_F(DocsTest, WorkerProcessesMakeTheSamePageAsOneProcess) {
  URDFSNAP_REQUIRE_GL();
  // two joint sections' pictures, no animations: enough pieces for three workers
  const auto docs = [&](const std::string& model, const std::string& options) {
    return RunUrdfsnap("docs " + model + " --sections 'link_0[12]*' --animations none " + options);
  };
  ASSERT_EQ(docs(model_, "--jobs 1 -o " + Path("one")).status, 0);
  const Result three = docs(model_, "--jobs 3 -o " + Path("three"));
  ASSERT_EQ(three.status, 0) << three.output;
  EXPECT_EQ(std::count(three.output.begin(), three.output.end(), '\n'), 1) << three.output;  // the summary
  const auto files = Files(Path("one"));
  EXPECT_EQ(Files(Path("three")), files);
  EXPECT_EQ(docs(model_, "--jobs 2 --check " + Path("one")).status, 0);
  const Result piped = docs("/dev/stdin", "--jobs 2 -o " + Path("piped") + " < " + model_);
  ASSERT_EQ(piped.status, 0) << piped.output;
  EXPECT_EQ(Files(Path("piped")).size(), files.size());
  EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf", "one", "piped", "three"}));  // no temporary folders
}

// A worker that fails (here: every file past 4 KB refused, as on a full disk) is the command's one
// error line, status 2, and nothing of the page is left.
TEST_F(DocsTest, AFailingWorkerIsTheCommandsOneError) {
  URDFSNAP_REQUIRE_GL();
  for (const char* jobs : {"1", "2"}) {
    ExpectTheOneFullDiskError("docs " + model_ + " --jobs " + jobs + " -o " + Path("page"));
    EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf"}));
  }
}

// SIGTERM to a page being made by workers stops them, removes the page's folder and ends the
// command by that signal.
TEST_F(DocsTest, SigtermStopsTheWorkersAndLeavesNothing) {
  URDFSNAP_REQUIRE_GL();
  // started in the background; killed once its first picture is in the temporary folder
  const std::string script =
      "sh -c '\"$0\" \"$@\" & pid=$!; "
      "while [ ! -e " + Path("page") + ".tmp-*/images/robot.webp ] && kill -0 $pid 2>/dev/null; do sleep 0.02; done; "
      "kill -TERM $pid; wait $pid; echo status $?; "
      "sleep 0.2; pgrep -f -- \"--worker-[f]older " + Path("page") + "\" || echo no workers' " + std::string(URDFSNAP_BINARY);
  const Result r = RunProgram(script, "docs " + model_ + " --size 1280x960 --jobs 2 -o " + Path("page"));
  EXPECT_NE(r.output.find("status 143"), std::string::npos) << r.output;   // 128 + SIGTERM
  EXPECT_NE(r.output.find("no workers"), std::string::npos) << r.output;
  EXPECT_EQ(Listing(), (std::vector<std::string>{"mrm.urdf"}));
}

}  // namespace
}  // namespace urdfsnap::cli_test
