// `urdfsnap diff EXPECTED ACTUAL`: compares two PNG images with the snapshot tolerance, prints the
// figures it decided on and exits 0 (match), 1 (differ) or 2 (bad input).
#include <cstdio>
#include <memory>

#include "cli/command.h"
#include "common/error.h"
#include "image/image_diff.h"
#include "image/png_reader.h"
#include "image/png_writer.h"

namespace urdfsnap::cli {

namespace {

struct DiffOptions {
  std::string expected, actual, diff_output;
  image::DiffTolerance tolerance;
};

void Run(const DiffOptions& o) {
  const image::Image expected = image::ReadPng(o.expected);
  const image::Image actual = image::ReadPng(o.actual);
  if (expected.width != actual.width || expected.height != actual.height) {
    throw Error("image sizes differ: " + o.expected + " is " + image::SizeText(expected) + ", " +
                o.actual + " is " + image::SizeText(actual));
  }
  const image::DiffStats stats = image::CompareImages(expected, actual, o.tolerance.max_delta);
  if (!o.diff_output.empty()) {
    image::WritePng(image::MakeDiffImage(expected, actual, o.tolerance.max_delta), o.diff_output);
  }
  const bool match = image::WithinTolerance(stats, o.tolerance);
  std::printf("%s: %s\n", match ? "match" : "differ", image::DescribeDiff(stats, o.tolerance).c_str());
  std::fflush(stdout);
  if (!match) throw CommandExit{1};
}

}  // namespace

void AddDiffCommand(CLI::App& app) {
  auto o = std::make_shared<DiffOptions>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two PNG images with a tolerance: exit 0 if they match, 1 if they differ, 2 on bad input");
  cmd->add_option("EXPECTED", o->expected, "the reference image (PNG)")->required();
  cmd->add_option("ACTUAL", o->actual, "the image to check (PNG), of the same size")->required();
  cmd->add_option("--diff", o->diff_output,
                  "write a picture of the difference: pixels over the delta magenta, smaller changes yellow, "
                  "over a dimmed EXPECTED");
  cmd->add_option("--max-delta", o->tolerance.max_delta,
                  "a pixel counts as changed when a channel differs by more than N (0-255)")
      ->capture_default_str()->check(FiniteNumber())->check(CLI::Range(0, 255));
  cmd->add_option("--max-fraction", o->tolerance.max_fraction,
                  "the images differ when more than this fraction of the pixels changed")
      ->capture_default_str()->check(FiniteNumber())->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--max-mean", o->tolerance.max_mean,
                  "the images differ when the mean pixel delta (0-255) is above this")
      ->capture_default_str()->check(FiniteNumber())->check(CLI::Range(0.0, 255.0));
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
