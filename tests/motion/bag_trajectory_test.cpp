// Trajectories from the test bags (the MCAP project's writer): times from header stamps or, when
// unstamped, log times; two publishers on one topic; errors naming the message and its log time.
#include "motion/bag_trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "motion/trajectory_file.h"
#include "support/error_text.h"
#include "test_bags.h"

namespace urdfsnap::motion {
namespace {

using test::TestBag;
using ::testing::HasSubstr;

TEST(BagTrajectoryTest, ReadsTheJointsOfEveryMessage) {
  Warnings warnings;
  const Trajectory trajectory = ReadTrajectory(TestBag("joint_states_zstd.mcap"), {}, warnings);
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(trajectory.tracks.size(), 3u);
  const JointTrack& elbow = trajectory.tracks[1];
  EXPECT_EQ(elbow.joint, "elbow");
  ASSERT_EQ(elbow.times.size(), 200u);
  for (int i = 0; i < 200; ++i) {
    EXPECT_NEAR(elbow.times[i], 0.01 * i, 1e-9);
    EXPECT_DOUBLE_EQ(elbow.positions[i], test::BagElbow(i));
  }
  EXPECT_NEAR(trajectory.EndTime(), 1.99, 1e-9);
  EXPECT_THAT(elbow.named_at, HasSubstr("joint_states_zstd.mcap: message 1 on '/joint_states'"));
  // time 0 is the first message's stamp, for --start and --end given as stamps
  ASSERT_TRUE(trajectory.stamp_at_zero.has_value());
  EXPECT_DOUBLE_EQ(*trajectory.stamp_at_zero, test::kBagStartNanoseconds * 1e-9);
}

TEST(BagTrajectoryTest, UnstampedMessagesAreTimedByLogTimeWithAWarning) {
  Warnings warnings;
  const Trajectory trajectory =
      ReadBagTrajectory(TestBag("zero_stamps.mcap"), "/joint_states", warnings);
  ASSERT_EQ(warnings.messages().size(), 1u);
  EXPECT_THAT(warnings.messages()[0],
              HasSubstr("is zero; the messages are timed by their log times"));
  EXPECT_NEAR(trajectory.EndTime(), 0.19, 1e-9);
}

TEST(BagTrajectoryTest, TwoPublishersMakeTracksWithTheirOwnTimes) {
  Warnings warnings;
  const Trajectory trajectory =
      ReadBagTrajectory(TestBag("two_publishers.mcap"), "/joint_states", warnings);
  ASSERT_EQ(trajectory.tracks.size(), 4u);
  EXPECT_EQ(trajectory.tracks[3].joint, "finger");
  EXPECT_EQ(trajectory.tracks[3].times.size(), 50u);
  EXPECT_EQ(trajectory.tracks[0].times.size(), 100u);
}

TEST(BagTrajectoryTest, AFolderIsReadAsASplitBag) {
  Warnings warnings;
  const Trajectory trajectory = ReadTrajectory(TestBag("split_bag"), {}, warnings);
  EXPECT_EQ(trajectory.tracks[0].times.size(), 55u);
}

struct BadBag {
  const char* file;
  const char* error;
};

class BadBagContentTest : public ::testing::TestWithParam<BadBag> {};

TEST_P(BadBagContentTest, NamesTheMessageAndItsLogTime) {
  Warnings warnings;
  EXPECT_THAT(test::ErrorText([&] { ReadTrajectory(TestBag(GetParam().file), {}, warnings); }),
              HasSubstr(GetParam().error));
}

INSTANTIATE_TEST_SUITE_P(
    Content, BadBagContentTest,
    ::testing::Values(
        BadBag{"nan_position.mcap",
               "nan_position.mcap: message 8 on '/joint_states' (log time 1700000000.071000000 s): "
               "joint 'elbow' has position nan; positions must be finite numbers"},
        BadBag{
            "time_goes_back.mcap",
            "message 6 on '/joint_states' (log time 1700000000.051000000 s): joint 'shoulder' at "
            "0.02 s is not after its previous sample at 0.04 s"},
        BadBag{"length_mismatch.mcap",
               "message 4 on '/joint_states' (log time 1700000000.031000000 s): 3 names but 2 "
               "positions"},
        BadBag{"corrupt_zstd_data.mcap", "corrupt MCAP"},
        BadBag{"no_joint_states.mcap", "no topic '/joint_states' in the bag"}),
    [](const auto& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(TrajectoryFileTest, DetectsTheFormatByExtensionThenContent) {
  EXPECT_EQ(DetectTrajectoryFormat("a.CSV", "anything"), TrajectoryFormat::kCsv);
  EXPECT_EQ(DetectTrajectoryFormat("a.yml", ""), TrajectoryFormat::kRosMessages);
  EXPECT_EQ(DetectTrajectoryFormat("a.json", ""), TrajectoryFormat::kRosMessages);
  EXPECT_EQ(DetectTrajectoryFormat("a.mcap", ""), TrajectoryFormat::kBag);
  EXPECT_EQ(DetectTrajectoryFormat("a.db3", ""), TrajectoryFormat::kBag);
  EXPECT_EQ(DetectTrajectoryFormat("recording", std::string("SQLite format 3\0", 16)),
            TrajectoryFormat::kBag);
  EXPECT_EQ(DetectTrajectoryFormat("recording", std::string("\x89MCAP0\r\n", 8)),
            TrajectoryFormat::kBag);
  EXPECT_EQ(DetectTrajectoryFormat("plan.txt", "time,a,b\n0,1,2\n"), TrajectoryFormat::kCsv);
  EXPECT_EQ(DetectTrajectoryFormat("plan.txt", "joint_names: [a, b]\n"),
            TrajectoryFormat::kRosMessages);
  EXPECT_EQ(DetectTrajectoryFormat("-", "{\"joint_names\": [\"a\", \"b\"]}"),
            TrajectoryFormat::kRosMessages);
}

TEST(TrajectoryFileTest, AMissingFileIsAnErrorNamingIt) {
  Warnings warnings;
  EXPECT_EQ(test::ErrorText([&] { ReadTrajectory("/nonexistent/plan.csv", {}, warnings); }),
            "/nonexistent/plan.csv: cannot read the trajectory: No such file or directory");
}

}  // namespace
}  // namespace urdfsnap::motion
