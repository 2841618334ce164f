// Text to typed settings: RViz's defaults, the .rviz file, then the options; one number grammar
// for every option (the joint values' too); errors named by the caller's label (unit).
#include "request/settings_parsing.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "common/error.h"
#include "model/joint_values.h"
#include "request/value_parsing.h"

namespace urdfsnap::request {
namespace {

using ::testing::ElementsAre;

render::RenderSettings Parse(const RenderRequest& request) {
  Warnings warnings;
  return ParseRenderSettings(request, CommandLineLabel, warnings);
}

std::string ErrorOf(const RenderRequest& request, const OptionLabel& label = CommandLineLabel) {
  Warnings warnings;
  try {
    ParseRenderSettings(request, label, warnings);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(SettingsParsing, FitMarginIsAFractionOrPixelsOfTheImage) {
  RenderRequest r;
  r.fit = true;
  r.size = "200x100";
  r.fit_margin = "0.1";
  EXPECT_DOUBLE_EQ(Parse(r).fit_margin.For({200, 100}).x, 0.1);
  r.fit_margin = "10px";
  const scene::FitMargin pixels = Parse(r).fit_margin.For({200, 100});
  EXPECT_DOUBLE_EQ(pixels.x, 0.05);
  EXPECT_DOUBLE_EQ(pixels.y, 0.1);
  for (const char* bad : {"0.5", "-0.1", "50px", "px", "1e999", "10 px"}) {
    r.fit_margin = bad;
    EXPECT_NE(ErrorOf(r).find("--fit-margin '" + std::string(bad) + "': expected a fraction"), std::string::npos) << bad;
  }
}

// Options that would do nothing say so: --fit-margin without --fit, TF options with the TF display off.
TEST(SettingsParsing, OptionsWithoutEffectAreWarnedOf) {
  RenderRequest r;
  r.fit_margin = "0.1";
  r.tf_scale = "2";
  r.no_tf_names = true;
  Warnings warnings;
  ParseRenderSettings(r, CommandLineLabel, warnings);
  ASSERT_EQ(warnings.messages().size(), 3u);
  EXPECT_EQ(warnings.messages()[0], "--tf-scale is ignored: the TF display is off (--tf shows it)");
  EXPECT_EQ(warnings.messages()[1], "--no-tf-names is ignored: the TF display is off (--tf shows it)");
  EXPECT_EQ(warnings.messages()[2], "--fit-margin 0.1 is ignored: it is the border --fit leaves, and --fit is not given");
  r.fit = r.tf = true;
  Warnings none;
  ParseRenderSettings(r, CommandLineLabel, none);
  EXPECT_TRUE(none.messages().empty());
}

// A camera replaces the orbit view: its options say so; --fov still sets a posed camera's field of
// view when there is no --camera-info to give one.
TEST(SettingsParsing, OrbitOptionsBesideACameraAreWarnedOf) {
  RenderRequest r;
  r.camera_pose = "0,0,5,1,0,0,0";
  r.yaw = "1";
  r.focal = "0,0,1";
  r.fov = "30";
  Warnings warnings;
  ParseRenderSettings(r, CommandLineLabel, warnings);
  EXPECT_THAT(warnings.messages(),
              ElementsAre("--yaw is ignored: the camera (--camera-info, --camera-frame, --camera-pose) replaces the "
                          "orbit view",
                          "--focal is ignored: the camera (--camera-info, --camera-frame, --camera-pose) replaces the "
                          "orbit view"));
}

TEST(SettingsParsing, NothingGivenIsRvizsDefaults) {
  RenderRequest request;
  request.model.path = "robots/arm.urdf";
  request.model.packages = {{"arm_description", "robots"}};
  const render::RenderSettings settings = Parse(request);
  EXPECT_EQ(settings.size.width, 640);
  EXPECT_EQ(settings.size.height, 480);
  EXPECT_EQ(settings.samples, 4);
  EXPECT_EQ(settings.fit, render::Fit::kNone);
  EXPECT_DOUBLE_EQ(settings.view.yaw, scene::OrbitView{}.yaw);
  EXPECT_DOUBLE_EQ(settings.view.distance, 10);
  EXPECT_TRUE(settings.scene.show_visual);
  EXPECT_FALSE(settings.scene.show_collision);
  EXPECT_TRUE(settings.scene.grid.enabled);
  EXPECT_FALSE(settings.scene.tf.enabled);
  // meshes are found relative to the model and through its packages
  EXPECT_EQ(settings.scene.model_file, "robots/arm.urdf");
  EXPECT_EQ(settings.scene.packages.at("arm_description"), "robots");
}

TEST(SettingsParsing, EveryOptionReachesItsTypedField) {
  RenderRequest r;
  r.size = "320x200";
  r.yaw = "+0.5";   // a leading '+' is accepted as in joint values
  r.pitch = "-0.25";
  r.distance = "4.5";
  r.focal = "0,0,1.2";
  r.fov = "60";
  r.fixed_frame = "tool";
  r.background = "255,255,255";
  r.alpha = "0.5";
  r.tf_scale = "2";
  r.collision = r.no_visual = r.no_grid = r.tf = r.no_tf_names = r.no_tf_axes = r.no_tf_arrows = true;
  r.no_aa = r.allow_missing_meshes = r.fit = true;
  const render::RenderSettings s = Parse(r);
  EXPECT_EQ(s.size.width, 320);
  EXPECT_EQ(s.size.height, 200);
  EXPECT_DOUBLE_EQ(s.view.yaw, 0.5);
  EXPECT_DOUBLE_EQ(s.view.pitch, -0.25);
  EXPECT_DOUBLE_EQ(s.view.distance, 4.5);
  EXPECT_TRUE(s.view.focal.isApprox(Eigen::Vector3d(0, 0, 1.2)));
  EXPECT_NEAR(s.view.fov_y, std::numbers::pi / 3, 1e-12);
  EXPECT_EQ(s.scene.fixed_frame, "tool");
  EXPECT_TRUE(s.scene.background.isApprox(Eigen::Vector3f(1, 1, 1)));
  EXPECT_DOUBLE_EQ(s.scene.alpha, 0.5);
  EXPECT_DOUBLE_EQ(s.scene.tf.marker_scale, 2);
  EXPECT_TRUE(s.scene.show_collision);
  EXPECT_FALSE(s.scene.show_visual);
  EXPECT_FALSE(s.scene.grid.enabled);
  EXPECT_TRUE(s.scene.tf.enabled);
  EXPECT_FALSE(s.scene.tf.show_names || s.scene.tf.show_axes || s.scene.tf.show_arrows);
  EXPECT_TRUE(s.scene.allow_missing_meshes);
  EXPECT_EQ(s.samples, 0);
  EXPECT_EQ(s.fit, render::Fit::kKeepFocal);   // --fit with --focal keeps the focal point
  r.focal.clear();
  EXPECT_EQ(Parse(r).fit, render::Fit::kFit);
}

TEST(SettingsParsing, OptionsOverrideTheRvizFile) {
  RenderRequest r;
  r.rviz = std::string(URDFSNAP_SOURCE_DIR) + "/tests/data/mrm.rviz";
  const render::RenderSettings from_file = Parse(r);
  EXPECT_NE(from_file.view.distance, 10);   // the file's close view
  r.distance = "7";
  r.no_grid = true;
  const render::RenderSettings overridden = Parse(r);
  EXPECT_DOUBLE_EQ(overridden.view.distance, 7);
  EXPECT_DOUBLE_EQ(overridden.view.yaw, from_file.view.yaw);   // the rest stays the file's
  EXPECT_FALSE(overridden.scene.grid.enabled);
}

TEST(SettingsParsing, BackgroundTakesNumbersHexAndNames) {
  const auto background = [](const char* text) {
    RenderRequest r;
    r.background = text;
    return Parse(r).scene.background;
  };
  EXPECT_EQ(background("255,128,0"), Eigen::Vector3f(1, 128 / 255.f, 0));
  EXPECT_EQ(background("white"), Eigen::Vector3f(1, 1, 1));
  EXPECT_EQ(background("Grey"), Eigen::Vector3f(128 / 255.f, 128 / 255.f, 128 / 255.f));
  EXPECT_EQ(background("#ff8000"), background("255,128,0"));
  EXPECT_EQ(background("#f80"), background("255,136,0"));
  for (const char* bad : {"#ff80", "#gg0000", "whit", "1,2", "-1,0,0"}) {
    EXPECT_NE(ErrorOf([&] { RenderRequest r; r.background = bad; return r; }()).find("or a colour name"),
              std::string::npos) << bad;
  }
}

TEST(SettingsParsing, BadValuesNameTheOptionThroughTheLabel) {
  const auto with = [](std::string RenderRequest::*field, const char* text) {
    RenderRequest r;
    r.*field = text;
    return r;
  };
  EXPECT_EQ(ErrorOf(with(&RenderRequest::yaw, "nan")), "--yaw 'nan': expected a finite number");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::yaw, "inf")), "--yaw 'inf': expected a finite number");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::yaw, " 1")), "--yaw ' 1': expected a finite number");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::distance, "0")), "--distance '0': expected a value from 0.01 to 1e+06");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::fov, "120")), "--fov '120': expected a value from 0.06 to 90");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::alpha, "1.5")), "--alpha '1.5': expected a value from 0 to 1");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::background, "300,0,0")),
            "--background '300,0,0': expected R,G,B from 0 to 255 (e.g. 255,255,255), #RRGGBB or a colour "
            "name (black, white, grey, gray, lightgrey, lightgray, darkgrey, darkgray, red, green, blue, "
            "yellow, cyan, magenta, orange)");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::focal, "1,2")), "--focal '1,2': expected three finite numbers X,Y,Z");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::size, "640x0")), "--size '640x0': each side must be between 1 and 16384 pixels");
  EXPECT_EQ(ErrorOf(with(&RenderRequest::size, "640x48.5")),
            "--size '640x48.5': expected WIDTHxHEIGHT in pixels, e.g. 640x480");
  // a suite names the option by its file and line
  EXPECT_EQ(ErrorOf(with(&RenderRequest::pitch, "x"), [](std::string_view name) { return "suite.yaml:7: " + std::string(name); }),
            "suite.yaml:7: pitch 'x': expected a finite number");
  RenderRequest missing;
  missing.rviz = "/nonexistent/view.rviz";
  EXPECT_NE(ErrorOf(missing).find("/nonexistent/view.rviz"), std::string::npos);
}

TEST(SettingsParsing, OneNumberGrammarForOptionsAndJointValues) {
  for (const char* text : {"0.5", "+0.5", "-0.5", "1e-3", "+1E2", ".5", "5."}) {
    model::NamedValues joints;
    model::ParseJointAssignment(std::string("j=") + text, joints);
    EXPECT_DOUBLE_EQ(ParseFinite(text, "--yaw"), joints[0].second) << text;
  }
  for (const char* text : {"", "+", "1,5", "0x10", "1 ", "nan", "-inf", "++1", "+-1", "1e400"}) {
    model::NamedValues joints;
    EXPECT_THROW(ParseFinite(text, "--yaw"), Error) << text;
    EXPECT_THROW(model::ParseJointAssignment(std::string("j=") + text, joints), Error) << text;
  }
}

}  // namespace
}  // namespace urdfsnap::request
