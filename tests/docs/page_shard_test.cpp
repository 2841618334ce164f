// Shards of a docs page's pictures and animations (unit, no GL): every file in exactly one shard, in
// page order and contiguous, and the animations spread so that no shard takes far more images than
// its share; the pieces of `docs --jobs`, which keep a joint section whole.
#include "docs/page_shard.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "docs/test_robot.h"
#include "model/robot.h"

namespace urdfsnap::docs {
namespace {

struct PageShardTest : ::testing::Test {
  std::vector<PageImage> Files(const PageOptions& options = {}) {
    const RobotPage page = MakeRobotPage(robot, "grip.urdf", {}, options, warnings);
    return PageImages(page, PageLook{});
  }
  Warnings warnings;
  model::Robot robot = model::LoadRobot(kGripperUrdf, "grip.urdf", warnings);
};

TEST_F(PageShardTest, PageImagesListEveryPictureAndAnimationInTheOrderTheyAreMade) {
  const std::vector<PageImage> files = Files();
  ASSERT_GE(files.size(), 5u);
  EXPECT_EQ(files[0].file, "images/robot.png");
  EXPECT_EQ(files[3].images, PageLook{}.turntable_frames);  // after the collision and TF views
  // 3 views, the turntable, and per joint section (turn, lift, wrist, finger_left) pictures and a sweep
  const auto sweeps = std::count_if(files.begin(), files.end(), [](const PageImage& f) { return f.images == PageOptions{}.sweep_frames; });
  EXPECT_EQ(sweeps, 4);
}

TEST_F(PageShardTest, EveryFileLandsInExactlyOneShardInPageOrder) {
  PageOptions stills_only;
  stills_only.animation_extension = "";
  for (const PageOptions& options : {PageOptions{}, stills_only}) {
    const std::vector<PageImage> all = Files(options);
    for (int count = 1; count <= static_cast<int>(all.size()) + 3; ++count) {
      std::vector<std::string> joined;
      for (int index = 1; index <= count; ++index) {
        for (const PageImage& file : ShardPageImages(all, {index, count})) joined.push_back(file.file);
      }
      std::vector<std::string> expected;
      for (const PageImage& file : all) expected.push_back(file.file);
      EXPECT_EQ(joined, expected) << count << " shards";
    }
  }
}

TEST_F(PageShardTest, PiecesKeepEachJointSectionWholeAndTakeEveryFileOnce) {
  const std::vector<PageImage> all = Files();
  for (int count = 1; count <= static_cast<int>(all.size()) + 3; ++count) {
    std::vector<std::string> joined;
    std::map<int, int> piece_of_group;
    for (int index = 1; index <= count; ++index) {
      for (const PageImage& file : PiecePageImages(all, {index, count})) {
        joined.push_back(file.file);
        EXPECT_EQ(piece_of_group.emplace(file.group, index).first->second, index) << file.file << ", " << count << " pieces";
      }
    }
    std::vector<std::string> expected;
    for (const PageImage& file : all) expected.push_back(file.file);
    EXPECT_EQ(joined, expected) << count << " pieces";
  }
  // the views are groups of their own, each section one group of its pictures and sweep
  EXPECT_EQ(all[0].group, 0);
  EXPECT_NE(all[1].group, all[2].group);
  EXPECT_EQ(all[4].group, all[5].group);
}

TEST_F(PageShardTest, AnAnimationGoesToTheShardHoldingMostOfItsFrames) {
  // three pictures, then a 10-frame animation: frames 3..12 of 14, its middle (frame 8) in shard 2
  const std::vector<PageImage> all = {{"a.png"}, {"b.png"}, {"c.png"}, {"turn.gif", 10}, {"d.png"}};
  const auto names = [&](int index) {
    std::string text;
    for (const PageImage& file : ShardPageImages(all, {index, 2})) text += file.file + " ";
    return text;
  };
  EXPECT_EQ(names(1), "a.png b.png c.png ");
  EXPECT_EQ(names(2), "turn.gif d.png ");
  EXPECT_EQ(ImageCount(all), 14);
}

}  // namespace
}  // namespace urdfsnap::docs
