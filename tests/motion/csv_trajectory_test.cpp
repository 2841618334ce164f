// CSV trajectories: the layouts people write and export, and one located error for each kind of
// bad table.
#include "motion/csv_trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/error_text.h"

namespace urdfsnap::motion {
namespace {

using ::testing::ElementsAre;

TEST(CsvTrajectoryTest, ReadsTimesAndJointColumns) {
  const Trajectory trajectory = ParseCsvTrajectory(
      "# a planned wave\n"
      "time, shoulder, \"elbow\"\r\n"
      "0.5, 0, 1\r\n"
      "\n"
      "1.0, 0.25, +2\r\n"
      "2.5, -0.5, 3e-1\r\n",
      "wave.csv");
  EXPECT_EQ(trajectory.source, "wave.csv");
  EXPECT_EQ(trajectory.time_base, TimeBase::kSeconds);
  ASSERT_EQ(trajectory.tracks.size(), 2u);
  const JointTrack& shoulder = trajectory.tracks[0];
  EXPECT_EQ(shoulder.joint, "shoulder");
  EXPECT_EQ(shoulder.named_at, "wave.csv:2");
  // times count from the first row
  EXPECT_THAT(shoulder.times, ElementsAre(0.0, 0.5, 2.0));
  EXPECT_THAT(shoulder.positions, ElementsAre(0.0, 0.25, -0.5));
  EXPECT_EQ(trajectory.tracks[1].joint, "elbow");
  EXPECT_THAT(trajectory.tracks[1].positions, ElementsAre(1.0, 2.0, 0.3));
  EXPECT_DOUBLE_EQ(trajectory.EndTime(), 2.0);
}

TEST(CsvTrajectoryTest, TheTimeColumnMayBeAnywhere) {
  const Trajectory trajectory = ParseCsvTrajectory("elbow,time\n1,0\n2,0.1\n", "t.csv");
  ASSERT_EQ(trajectory.tracks.size(), 1u);
  EXPECT_THAT(trajectory.tracks[0].times, ElementsAre(0.0, 0.1));
  EXPECT_THAT(trajectory.tracks[0].positions, ElementsAre(1.0, 2.0));
}

TEST(CsvTrajectoryTest, WithoutATimeColumnEachRowIsAFrame) {
  const Trajectory trajectory =
      ParseCsvTrajectory("shoulder,elbow\n0,0\n0.1,0.2\n0.2,0.4", "f.csv");
  EXPECT_EQ(trajectory.time_base, TimeBase::kRows);
  EXPECT_THAT(trajectory.tracks[1].times, ElementsAre(0.0, 1.0, 2.0));
  EXPECT_THAT(trajectory.tracks[1].positions, ElementsAre(0.0, 0.2, 0.4));
}

struct BadCsv {
  const char* name;
  const char* text;
  const char* error;
};

class BadCsvTest : public ::testing::TestWithParam<BadCsv> {};

TEST_P(BadCsvTest, IsOneLocatedError) {
  EXPECT_EQ(test::ErrorText([] { ParseCsvTrajectory(GetParam().text, "bad.csv"); }),
            GetParam().error);
}

INSTANTIATE_TEST_SUITE_P(
    Tables, BadCsvTest,
    ::testing::Values(
        BadCsv{"empty", "", "bad.csv: no header row (expected time,<joint>,<joint>...)"},
        BadCsv{"header_only", "time,elbow\n",
               "bad.csv: no rows after the header: an empty trajectory"},
        BadCsv{"only_time", "time\n0\n",
               "bad.csv:1: the header names no joint columns (expected time,<joint>,<joint>...)"},
        BadCsv{"unnamed_column", "time,,elbow\n", "bad.csv:1: column 2 of the header has no name"},
        BadCsv{"duplicate_joint", "time,elbow,elbow\n",
               "bad.csv:1: column 'elbow' appears twice in the header"},
        BadCsv{"duplicate_time", "time,elbow,time\n",
               "bad.csv:1: column 'time' appears twice in the header"},
        BadCsv{"short_row", "time,a,b\n0,1,2\n1,2\n",
               "bad.csv:3: 2 fields, but the header has 3 columns"},
        BadCsv{"nan", "time,a\n0,1\n1,nan\n",
               "bad.csv:3: column 'a': expected a finite number, got 'nan'"},
        BadCsv{"inf", "time,a\n0,inf\n",
               "bad.csv:2: column 'a': expected a finite number, got 'inf'"},
        BadCsv{"text_time", "time,a\nsoon,1\n",
               "bad.csv:2: column 'time': expected a finite number, got 'soon'"},
        BadCsv{"repeated_time", "time,a\n0,1\n# same time\n0,2\n",
               "bad.csv:4: time 0 is not after the previous row's 0 (times must increase)"},
        BadCsv{"backwards", "time,a\n1,1\n0.5,2\n",
               "bad.csv:3: time 0.5 is not after the previous row's 1 (times must increase)"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace urdfsnap::motion
