// `urdfsnap dataset`: the same bytes for a seed, shards that add up to the whole, COCO annotations
// that agree with the label images, cameras from a poses file, and its errors.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

class DatasetTest : public CliTest {
 protected:
  void Dataset(const std::string& folder, const std::string& options) {
    const Result r = RunUrdfsnap("dataset " + kMrm + " -o " + Path(folder) +
                                 " --count 5 --size 96x72 --no-grid --quiet " + options);
    ASSERT_EQ(r.status, 0) << r.output;
  }
  nlohmann::json Coco(const std::string& file) { return nlohmann::json::parse(ReadBytes(Path(file))); }
};

TEST_F(DatasetTest, SameSeedSameBytesAndShardsAddUp) {
  URDFSNAP_REQUIRE_GL();
  Dataset("a", "--seed 4");
  Dataset("b", "--seed 4");
  Dataset("s", "--seed 4 --shard 1/2");
  Dataset("s", "--seed 4 --shard 2/2");
  Dataset("other", "--seed 5");
  for (const char* sub : {"images", "depth", "labels"}) {
    for (int k = 0; k < 5; ++k) {
      const std::string file = std::string(sub) + "/00000" + std::to_string(k) + ".png";
      const std::string bytes = ReadBytes(Path("a/" + file));
      ASSERT_FALSE(bytes.empty()) << file;
      EXPECT_EQ(ReadBytes(Path("b/" + file)), bytes) << file;
      EXPECT_EQ(ReadBytes(Path("s/" + file)), bytes) << file;
    }
  }
  EXPECT_NE(ReadBytes(Path("other/images/000000.png")), ReadBytes(Path("a/images/000000.png")));
  EXPECT_EQ(ReadBytes(Path("b/annotations.json")), ReadBytes(Path("a/annotations.json")));
  // shard 1/2 holds samples 0-2, shard 2/2 samples 3-4; together the whole file's
  const nlohmann::json whole = Coco("a/annotations.json");
  const nlohmann::json first = Coco("s/annotations.1-of-2.json"), second = Coco("s/annotations.2-of-2.json");
  for (const char* key : {"images", "annotations"}) {
    nlohmann::json joined = first[key];
    joined.insert(joined.end(), second[key].begin(), second[key].end());
    EXPECT_EQ(joined, whole[key]) << key;
  }
  EXPECT_EQ(first["categories"], whole["categories"]);
}

TEST_F(DatasetTest, AnnotationsAgreeWithTheLabelImages) {
  URDFSNAP_REQUIRE_GL();
  Dataset("d", "--seed 11 --distance 6:8");
  const nlohmann::json coco = Coco("d/annotations.json");
  ASSERT_EQ(coco["images"].size(), 5u);
  ASSERT_EQ(coco["categories"].size(), 7u);   // six links, then the robot
  EXPECT_EQ(coco["categories"][6]["keypoints"].size(), 5u);
  int robots = 0;
  for (const nlohmann::json& image : coco["images"]) {
    EXPECT_EQ(image["camera"]["K"].size(), 9u);
    EXPECT_EQ(image["joints"].size(), 5u);
    const image::Gray16Image labels = image::ReadGray16Png(Path("d/" + image["labels_file"].get<std::string>()));
    for (const nlohmann::json& a : coco["annotations"]) {
      if (a["image_id"] != image["id"]) continue;
      const int category = a["category_id"];
      int area = 0, x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
      for (int y = 0; y < labels.height; ++y) {
        for (int x = 0; x < labels.width; ++x) {
          const int label = labels.values[static_cast<size_t>(y) * labels.width + x];
          if (category == 7 ? label == 0 : label != category) continue;
          ++area;
          x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
      }
      EXPECT_EQ(a["area"], area);
      EXPECT_EQ(a["bbox"], nlohmann::json({x0, y0, x1 - x0 + 1, y1 - y0 + 1}));
      EXPECT_EQ(a["segmentation"]["size"], nlohmann::json({72, 96}));
      if (category == 7) {
        ++robots;
        ASSERT_EQ(a["keypoints"].size(), 15u);
        for (size_t i = 2; i < 15; i += 3) EXPECT_TRUE(a["keypoints"][i] == 0 || a["keypoints"][i] == 1 || a["keypoints"][i] == 2);
      }
    }
  }
  EXPECT_EQ(robots, 5);   // from 6 to 8 m the robot is in every image
}

TEST_F(DatasetTest, APosesFileGivesEachSampleItsCameraInTurn) {
  URDFSNAP_REQUIRE_GL();
  // a small calibration (off-centre, non-square pixels) and two cameras looking back at the arm
  const std::string info = Write("cam.yaml", "width: 96\nheight: 72\nk: [80, 0, 45.5, 0, 84, 40.25, 0, 0, 1]\n"
                                             "d: []\ndistortion_model: plumb_bob\n");
  const std::string poses = Write("poses.txt", "# x y z qx qy qz qw\n5 0 1 -0.5 -0.5 0.5 0.5\n\n"
                                              "0,5,1.2,0,-0.7071067811865476,0.7071067811865476,0\n");
  Dataset("p", "--seed 3 --camera-info " + info + " --camera-poses " + poses);
  const nlohmann::json coco = Coco("p/annotations.json");
  ASSERT_EQ(coco["images"].size(), 5u);
  const std::vector<std::string> pose_options = {"5,0,1,-0.5,-0.5,0.5,0.5",
                                                 "0,5,1.2,0,-0.7071067811865476,0.7071067811865476,0"};
  for (int k : {0, 1, 2}) {
    const nlohmann::json& image = coco["images"][k];
    EXPECT_EQ(image["width"], 96);
    const double x = image["camera"]["pose"][0], y = image["camera"]["pose"][1];
    EXPECT_NEAR(x, k % 2 ? 0 : 5, 1e-12) << k;
    EXPECT_NEAR(y, k % 2 ? 5 : 0, 1e-12) << k;
    // the sample is `render` of its joints through that camera
    std::string joints;
    for (const auto& [name, value] : image["joints"].items()) joints += " -j " + name + "=" + value.dump();
    const Result r = RunUrdfsnap("render " + kMrm + " --no-grid --camera-info " + info + " --camera-pose " +
                                 pose_options[k % 2] + joints + " -o " + Path("r.png"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(ReadBytes(Path("r.png")), ReadBytes(Path("p/images/00000" + std::to_string(k) + ".png"))) << k;
  }
  // a camera on a link: every sample from the link's frame, moved by the poses
  Dataset("f", "--seed 3 --camera-frame link_02 --camera-poses " + Write("back.txt", "0 0 -3 0 0 0 1\n"));
  EXPECT_NE(ReadBytes(Path("f/images/000000.png")), ReadBytes(Path("f/images/000001.png")));
}

TEST_F(DatasetTest, ErrorsAreOneLine) {
  const auto error = [&](const std::string& options) {
    const Result r = RunUrdfsnap("dataset " + kMrm + " -o " + Path("e") + " " + options);
    EXPECT_EQ(r.status, 2) << r.output;
    return r.output;
  };
  EXPECT_EQ(error(""), "urdfsnap: error: dataset: give the number of samples with --count N\n");
  EXPECT_EQ(error("--count 2.5"), "urdfsnap: error: --count '2.5': expected a whole number\n");
  EXPECT_EQ(error("--count 3 --distance 4:2"),
            "urdfsnap: error: --distance '4:2': expected MIN:MAX, MIN not above MAX, both from 0.001 to 1e+06\n");
  EXPECT_EQ(error("--count 3 --elevation 0:95"),
            "urdfsnap: error: --elevation '0:95': expected MIN:MAX, MIN not above MAX, both from -90 to 90\n");
  const std::string poses = Write("poses.txt", "1 2 3 0 0 0 1\n1 2 3\n");
  EXPECT_EQ(error("--count 3 --camera-poses " + poses),
            "urdfsnap: error: " + poses + ":2: expected a camera pose: seven numbers X Y Z QX QY QZ QW\n");
  EXPECT_EQ(error("--count 3 --camera-poses " + Write("one.txt", "1 2 3 0 0 0 1\n") + " --distance 2:3"),
            "urdfsnap: error: --distance places random cameras around the robot; the cameras are given by "
            "--camera-poses\n");
  EXPECT_EQ(error("--count 3 --camera-frame nowhere"),
            "urdfsnap: error: camera frame 'nowhere' is not a link of robot 'mrm'\n");
  EXPECT_FALSE(std::filesystem::exists(Path("e")));
}

// --jobs: samples written by worker processes, 12 pieces of 5 samples (most empty), are the one
// process's files byte for byte, with one annotations.json merged from the workers' entries.
TEST_F(DatasetTest, WorkersWriteTheSameFilesAsOneProcess) {
  URDFSNAP_REQUIRE_GL();
  Dataset("one", "--seed 3 --jobs 1");
  Dataset("three", "--seed 3 --jobs 3");
  const auto files = FilesBelow(Path("one"));
  EXPECT_EQ(files.size(), 3u * 5u + 1u);
  EXPECT_EQ(FilesBelow(Path("three")), files);
}

// By default a light robot (mrm: 812 triangles) is drawn in this process alone, which --verbose
// says; --jobs N starts N worker processes whatever the robot.
TEST_F(DatasetTest, ALightRobotIsOneProcessUnlessJobsAreGiven) {
  URDFSNAP_REQUIRE_GL();
  const std::string dataset = "dataset " + kMrm + " --count 2 --size 96x72 --quiet --verbose -o ";
  const Result light = RunUrdfsnap(dataset + Path("light"));
  ASSERT_EQ(light.status, 0) << light.output;
  EXPECT_NE(light.output.find("urdfsnap: 812 triangles: one process (--jobs N for worker processes)\n"),
            std::string::npos)
      << light.output;
  const Result given = RunUrdfsnap(dataset + Path("given") + " --jobs 2");
  ASSERT_EQ(given.status, 0) << given.output;
  EXPECT_EQ(given.output.find("triangles:"), std::string::npos) << given.output;
  EXPECT_EQ(FilesBelow(Path("given")), FilesBelow(Path("light")));
}

// A worker that fails (here: every file past 4 KB refused, as on a full disk) is the command's one
// error line, status 2, with no annotations.json and none of the workers' entry files.
TEST_F(DatasetTest, AFailingWorkerIsTheCommandsOneError) {
  URDFSNAP_REQUIRE_GL();
  ExpectTheOneFullDiskError("dataset " + kMrm + " -o " + Path("d") + " --count 6 --size 640x480 --jobs 2");
  for (const auto& entry : std::filesystem::directory_iterator(Path("d"))) {
    EXPECT_TRUE(entry.is_directory()) << entry.path();   // images/, depth/, labels/ only
  }
}

// SIGTERM to samples being written by this process and its one worker (--jobs 2 starts exactly
// one) stops the worker, removes the pieces' COCO entry files and ends the command by that signal,
// with no annotations.json.
TEST_F(DatasetTest, SigtermStopsTheOneWorkerAndLeavesNoAnnotations) {
  URDFSNAP_REQUIRE_GL();
  ExpectSigtermStopsTheOneWorker("dataset " + kMrm + " -o " + Path("d") + " --count 5000 --size 640x480 --jobs 2",
                                 Path("d"));
  for (const auto& entry : std::filesystem::directory_iterator(Path("d"))) {
    EXPECT_TRUE(entry.is_directory()) << entry.path();   // images/, depth/, labels/ only
  }
}

}  // namespace
}  // namespace urdfsnap::cli_test
