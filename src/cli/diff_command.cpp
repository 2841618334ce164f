// `urdfsnap diff EXPECTED ACTUAL`: compares two PNG images with the snapshot tolerance, prints the
// figures it decided on and exits 0 (match), 1 (differ) or 2 (bad input). With --depth or
// --labels it compares two 16-bit images (`render --depth/--labels`, suites' depth and label
// goldens) as suites do: millimetres with their own tolerance, or link labels.
#include <cstdio>
#include <memory>
#include <optional>

#include "cli/command.h"
#include "common/error.h"
#include "common/number_text.h"
#include "common/output_plan.h"
#include "image/gray16_diff.h"
#include "image/image_diff.h"
#include "image/image_file_names.h"
#include "image/png_reader.h"
#include "image/png_writer.h"

namespace urdfsnap::cli {

namespace {

struct DiffOptions {
  std::string expected, actual, diff_output;
  bool depth = false, labels = false;
  std::optional<int> max_delta;  // the default depends on the kind of image
  std::optional<double> max_fraction, max_mean;
};

bool Report(bool match, const std::string& figures) {
  std::printf("%s: %s\n", match ? "match" : "differ", figures.c_str());
  std::fflush(stdout);
  return match;
}

bool RunColour(const DiffOptions& o) {
  image::DiffTolerance tolerance;
  if (o.max_delta) {
    if (*o.max_delta > 255) throw Error("--max-delta " + std::to_string(*o.max_delta) + ": expected 0 to 255");
    tolerance.max_delta = *o.max_delta;
  }
  tolerance.max_fraction = o.max_fraction.value_or(tolerance.max_fraction);
  tolerance.max_mean = o.max_mean.value_or(tolerance.max_mean);
  const image::Image expected = image::ReadPng(o.expected);
  const image::Image actual = image::ReadPng(o.actual);
  if (expected.width != actual.width || expected.height != actual.height) {
    throw Error("image sizes differ: " + o.expected + " is " + image::SizeText(expected) + ", " +
                o.actual + " is " + image::SizeText(actual));
  }
  const image::DiffStats stats = image::CompareImages(expected, actual, tolerance.max_delta);
  if (!o.diff_output.empty()) {
    image::WritePng(image::MakeDiffImage(expected, actual, tolerance.max_delta), o.diff_output);
  }
  return Report(image::WithinTolerance(stats, tolerance), image::DescribeDiff(stats, tolerance));
}

bool RunGray16(const DiffOptions& o) {
  const image::Gray16Kind kind = o.depth ? image::Gray16Kind::kDepth : image::Gray16Kind::kLabels;
  if (o.max_mean) throw Error("--max-mean is for colour images, not with --depth or --labels");
  if (o.labels && o.max_delta && *o.max_delta != 0) throw Error("--max-delta: labels are compared exactly");
  image::Gray16Tolerance tolerance = image::DefaultTolerance(kind);
  tolerance.max_delta = o.max_delta.value_or(tolerance.max_delta);
  tolerance.max_fraction = o.max_fraction.value_or(tolerance.max_fraction);
  const image::Gray16Image expected = image::ReadGray16Png(o.expected);
  const image::Gray16Image actual = image::ReadGray16Png(o.actual);
  if (expected.width != actual.width || expected.height != actual.height) {
    throw Error("image sizes differ: " + o.expected + " is " + image::SizeText(expected.width, expected.height) +
                ", " + o.actual + " is " + image::SizeText(actual.width, actual.height));
  }
  const image::Gray16DiffStats stats = image::CompareGray16(expected, actual, kind, tolerance.max_delta);
  if (!o.diff_output.empty()) {
    int near = 0, far = 0;
    image::Gray16ValueRange(expected, actual, near, far);
    const image::Image picture = o.depth ? image::DepthPicture(expected, near, far) : image::LabelPicture(expected);
    image::WritePng(image::MakeGray16DiffImage(expected, actual, tolerance.max_delta, picture), o.diff_output);
  }
  return Report(image::WithinTolerance(stats, tolerance), image::DescribeGray16Diff(stats, tolerance, kind));
}

void Run(const DiffOptions& o) {
  if (!o.diff_output.empty()) {  // the diff image may not overwrite an image it compares
    image::CheckImageFileName(o.diff_output, image::ImageKind::kColour, "--diff");
    OutputPlan outputs;
    outputs.AddInput(o.expected, "EXPECTED");
    outputs.AddInput(o.actual, "ACTUAL");
    outputs.AddFile(o.diff_output, "--diff", false);
    outputs.Prepare();
  }
  const bool match = o.depth || o.labels ? RunGray16(o) : RunColour(o);
  if (!match) throw CommandExit{1};
}

}  // namespace

void AddDiffCommand(CLI::App& app) {
  auto o = std::make_shared<DiffOptions>();
  const image::Gray16Tolerance depth = image::DefaultTolerance(image::Gray16Kind::kDepth);
  const image::Gray16Tolerance labels = image::DefaultTolerance(image::Gray16Kind::kLabels);
  const image::DiffTolerance colour;
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two PNG images with a tolerance: exit 0 if they match, 1 if they differ, 2 on bad input");
  cmd->add_option("EXPECTED", o->expected, "the reference image (PNG)")->required();
  cmd->add_option("ACTUAL", o->actual, "the image to check (PNG), of the same size")->required();
  cmd->add_option("--diff", o->diff_output,
                  "write a picture of the difference: pixels over the delta magenta, smaller changes yellow, "
                  "over a dimmed EXPECTED (--depth/--labels: robot in one image only cyan)");
  CLI::Option* depth_flag = cmd->add_flag(
      "--depth", o->depth, "compare 16-bit depth images (millimetres, 0 = no robot; render --depth FILE.png)");
  cmd->add_flag("--labels", o->labels, "compare 16-bit link-label images (render --labels)")->excludes(depth_flag);
  cmd->add_option("--max-delta", o->max_delta,
                  "a pixel counts as changed when a channel differs by more than N (0-255, default " +
                      std::to_string(colour.max_delta) + "); --depth: millimetres (default " +
                      std::to_string(depth.max_delta) + ")")
      ->check(FiniteNumber())->check(CLI::Range(0, 65535));
  cmd->add_option("--max-fraction", o->max_fraction,
                  "the images differ when more than this fraction of the pixels changed (default " +
                      FormatNumber(colour.max_fraction) + "; --depth " + FormatNumber(depth.max_fraction) +
                      ", --labels " + FormatNumber(labels.max_fraction) + ")")
      ->check(FiniteNumber())->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--max-mean", o->max_mean,
                  "the images differ when the mean pixel delta (0-255) is above this (default " +
                      FormatNumber(colour.max_mean) + ")")
      ->check(FiniteNumber())->check(CLI::Range(0.0, 255.0));
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
