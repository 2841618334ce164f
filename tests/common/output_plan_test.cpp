// The output plan: outputs that are one file (by name, through a link, by inode, a sequence's
// names, inside a replaced folder) are refused before anything is written; the folders made and
// the temporary files are gone after a plan that did not commit, and an existing file keeps its
// bytes; a committed plan moves every file into place (unit).
#include "common/output_plan.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "common/error.h"
#include "support/temp_folder.h"

namespace urdfsnap {
namespace {

namespace fs = std::filesystem;

class OutputPlanTest : public testing::Test {
 protected:
  std::string Path(const std::string& name) const { return folder_.Path(name); }
  // The message Prepare throws for `plan`, or "" when it accepts the plan.
  static std::string Refusal(OutputPlan& plan) {
    try {
      plan.Prepare();
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  test::TempFolder folder_{"output_plan_test"};
};

TEST_F(OutputPlanTest, TwoOutputsThatAreOneFileAreRefused) {
  const std::string model = folder_.Write("robot.urdf", "<robot/>");
  fs::create_symlink(model, Path("link.png"));
  fs::create_hard_link(model, Path("hard.png"));
  folder_.Write("seg.png", "old");
  struct Case {
    std::vector<std::pair<std::string, std::string>> files;  // name, role
    std::string message;  // the start of the refusal
  } cases[] = {
      {{{"out.png", "-o"}, {"out.png", "--depth"}}, "--depth '" + Path("out.png") + "': the same file as -o"},
      {{{"out.png", "-o"}, {"sub/../out.png", "--depth"}}, "--depth '" + Path("sub/../out.png") + "': the same file as -o"},
      {{{"robot.urdf", "-o"}}, "-o '" + model + "': the same file as the model"},
      {{{"link.png", "-o"}}, "-o '" + Path("link.png") + "': the same file as the model"},
      {{{"hard.png", "-o"}}, "-o '" + Path("hard.png") + "': the same file as the model"},
  };
  for (const Case& c : cases) {
    OutputPlan plan;
    plan.AddInput(model, "the model");
    for (const auto& [name, role] : c.files) plan.AddFile(Path(name), role);
    EXPECT_EQ(Refusal(plan).rfind(c.message, 0), 0u) << Refusal(plan);
  }
  OutputPlan fine;
  fine.AddInput(model, "the model");
  fine.AddFile(Path("out.png"), "-o");
  fine.AddFile(Path("out.depth.png"), "--depth");
  EXPECT_EQ(Refusal(fine), "");
}

TEST_F(OutputPlanTest, SequencesAreComparedByEveryNameTheyCanTake) {
  // (prefix, suffix) of each sequence, or a file; whether they can meet
  EXPECT_TRUE(NumberedNamesMeet("f/", ".png", "f/", ".png", true));
  EXPECT_TRUE(NumberedNamesMeet("f/", ".png", "f/1", ".png", true));       // f/%d.png and f/1%d.png: f/10.png
  EXPECT_TRUE(NumberedNamesMeet("f/", ".png", "f/00042.png", "", false));  // a file among the frames
  EXPECT_TRUE(NumberedNamesMeet("f/x", "_1.png", "f/x1_", ".png", true));  // f/x1_1.png both ways
  EXPECT_FALSE(NumberedNamesMeet("f/depth_", ".png", "f/label_", ".png", true));
  EXPECT_FALSE(NumberedNamesMeet("f/", ".png", "f/", ".npy", true));
  EXPECT_FALSE(NumberedNamesMeet("f/", ".png", "f/labels.json", "", false));
  EXPECT_FALSE(NumberedNamesMeet("f/", ".png", "f/x.png", "", false));

  OutputPlan plan;
  plan.AddSequence("frames/%05d.png", Path("frames/"), ".png", "-o");
  plan.AddFile(Path("frames/00007.png"), "--depth");
  EXPECT_EQ(Refusal(plan), "-o 'frames/%05d.png': may name the same file as --depth '" + Path("frames/00007.png") + "'");
  EXPECT_FALSE(fs::exists(Path("frames")));
}

TEST_F(OutputPlanTest, AReplacedFolderHoldsNoInputOrOutput) {
  const std::string model = folder_.Write("page/robot.urdf", "<robot/>");
  OutputPlan plan;
  plan.AddInput(model, "the model");
  plan.AddFolder(Path("page"), "-o");
  EXPECT_EQ(Refusal(plan), "-o '" + Path("page") + "': holds the model '" + model + "'");
  OutputPlan same;
  same.AddInput(model, "the model");
  same.AddFolder(model, "-o");
  EXPECT_EQ(Refusal(same).rfind("-o '" + model + "': the same file as the model", 0), 0u);
}

TEST_F(OutputPlanTest, PlacesThatCannotHoldTheOutputAreRefused) {
  folder_.Write("afile", "x");
  fs::create_directories(Path("adir"));
  OutputPlan under_file;
  under_file.AddFile(Path("afile/depth.png"), "--depth");
  EXPECT_EQ(Refusal(under_file), Path("afile/depth.png") + ": cannot write: Not a directory");
  OutputPlan on_folder;
  on_folder.AddFile(Path("adir"), "the link names of --labels");
  EXPECT_EQ(Refusal(on_folder), Path("adir") + ": cannot write: Is a directory");
  OutputPlan folder_on_file;
  folder_on_file.AddFolder(Path("afile"), "-o");
  EXPECT_EQ(Refusal(folder_on_file), "-o '" + Path("afile") + "': exists and is not a folder");
  OutputPlan missing_folder;
  missing_folder.AddFile(Path("no/such/out.png"), "-o", false);
  EXPECT_EQ(Refusal(missing_folder), Path("no/such/out.png") + ": cannot write: No such file or directory");
  EXPECT_FALSE(fs::exists(Path("no")));
}

TEST_F(OutputPlanTest, AllOrNothing) {
  folder_.Write("old.png", "old bytes");
  {
    // written, then abandoned (an error later in the run): nothing new stays, the old file is kept
    OutputPlan plan;
    plan.AddFile(Path("old.png"), "-o");
    plan.AddFile(Path("new/deeper/depth.png"), "--depth");
    plan.Prepare();
    EXPECT_TRUE(fs::is_directory(Path("new/deeper")));
    plan.Write(Path("old.png"), std::string_view("new bytes"));
    plan.Write(Path("new/deeper/depth.png"), std::string_view("depth"));
    EXPECT_EQ(folder_.Read("old.png"), "old bytes");
  }
  EXPECT_EQ(folder_.Listing(), std::vector<std::string>{"old.png"});
  EXPECT_EQ(folder_.Read("old.png"), "old bytes");
  OutputPlan plan;
  plan.AddFile(Path("old.png"), "-o");
  plan.AddFile(Path("new/depth.png"), "--depth");
  plan.Prepare();
  plan.Write(Path("old.png"), std::string_view("new bytes"));
  AtomicFile& depth = plan.Open(Path("new/depth.png"));
  depth.Write("de");
  depth.Write("pth");
  plan.Commit();
  EXPECT_EQ(folder_.Read("old.png"), "new bytes");
  EXPECT_EQ(folder_.Read("new/depth.png"), "depth");
  EXPECT_EQ(folder_.Listing(), (std::vector<std::string>{"new", "old.png"}));
}

}  // namespace
}  // namespace urdfsnap
