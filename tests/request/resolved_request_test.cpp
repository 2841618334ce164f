// A request resolved into types: the joint file then -j (-j wins), --fit as a Fit, the command
// line's option label, and files read once so that later requests over them read none (unit).
#include "request/resolved_request.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/temp_folder.h"

namespace urdfsnap::request {
namespace {

TEST(ResolvedRequest, TheJointFileComesFirstAndDashJWins) {
  RenderRequest r;
  r.joints = {{"elbow", 0.5}, {"wrist", 1}};
  const model::NamedValues given = GivenJoints({{"elbow", 0.1}, {"shoulder", 0.2}}, r);
  const model::NamedValues expected = {{"elbow", 0.1}, {"shoulder", 0.2}, {"elbow", 0.5}, {"wrist", 1}};
  EXPECT_EQ(given, expected);  // a later entry wins when the values are resolved
}

TEST(ResolvedRequest, FitKeepsTheFocalPointOnlyWhenOneIsGiven) {
  RenderRequest r;
  EXPECT_EQ(FitOf(r), render::Fit::kNone);
  r.focal = "0,0,1";
  EXPECT_EQ(FitOf(r), render::Fit::kNone);
  r.fit = true;
  EXPECT_EQ(FitOf(r), render::Fit::kKeepFocal);
  r.focal.clear();
  EXPECT_EQ(FitOf(r), render::Fit::kFit);
}

TEST(ResolvedRequest, CommandLineLabelIsTheOptionWithDashes) {
  EXPECT_EQ(CommandLineLabel("yaw"), "--yaw");
  EXPECT_EQ(CommandLineLabel("tf-scale"), "--tf-scale");
}

TEST(ResolvedRequest, FilesAreReadOnceAndRequestsOverThemReadNone) {
  const test::TempFolder folder("resolved_request");
  RenderRequest base;
  base.model.path = "arm.urdf";
  base.rviz = folder.Write("view.rviz",
                           "Visualization Manager:\n  Global Options:\n    Background Color: 10; 20; 30\n"
                           "    Fixed Frame: base_link\n  Displays:\n    - Class: rviz/Grid\n      Enabled: true\n");
  base.joint_file = folder.Write("joints.yaml", "elbow: 0.25\n");
  base.joints = {{"wrist", 1}};
  Warnings warnings;
  const RequestFiles files = ReadRequestFiles(base, warnings);
  std::filesystem::remove(base.rviz);
  std::filesystem::remove(base.joint_file);

  RenderRequest query = base;  // a live view's query over the same files
  query.yaw = "1.5";
  query.fit = true;
  const ResolvedRequest resolved = ResolveRequest(query, files, CommandLineLabel);
  EXPECT_EQ(resolved.model.path, "arm.urdf");
  EXPECT_EQ(resolved.settings.scene.fixed_frame, "base_link");
  EXPECT_FLOAT_EQ(resolved.settings.scene.background.x(), 10 / 255.0f);
  EXPECT_DOUBLE_EQ(resolved.settings.view.yaw, 1.5);
  EXPECT_EQ(resolved.settings.fit, render::Fit::kFit);
  const model::NamedValues joints = {{"elbow", 0.25}, {"wrist", 1}};
  EXPECT_EQ(resolved.joints, joints);
  EXPECT_TRUE(resolved.clamp);
  EXPECT_FALSE(resolved.fixed_frame_given);
}

TEST(ResolvedRequest, TheCameraInfoFileIsReadWithTheOtherFilesNotPerRequest) {
  const test::TempFolder folder("resolved_request_camera");
  RenderRequest base;
  base.model.path = "arm.urdf";
  base.camera_info = folder.Write("info.yaml", "width: 64\nheight: 48\nk: [50, 0, 32, 0, 50, 24, 0, 0, 1]\n");
  Warnings warnings;
  const RequestFiles files = ReadRequestFiles(base, warnings);
  ASSERT_TRUE(files.camera.info.has_value());
  std::filesystem::remove(base.camera_info);

  RenderRequest query = base;
  query.near = "0.5";
  const ResolvedRequest resolved = ResolveRequest(query, files, CommandLineLabel);
  ASSERT_TRUE(resolved.settings.camera.has_value());
  EXPECT_EQ(resolved.settings.size.width, 64);
  EXPECT_EQ(resolved.settings.size.height, 48);
}

}  // namespace
}  // namespace urdfsnap::request
