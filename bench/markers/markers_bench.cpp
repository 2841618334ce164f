// The marker benchmark (issue 23's budget: a MarkerArray of 1,000 mixed markers <= 10 ms per frame
// with mrm at 640x480 on 2 cores): mrm at its zero pose in RViz's default view and N markers of
// every type but MESH_RESOURCE in turn (arrows, cubes, spheres, cylinders, line strips and lists,
// cube and sphere lists, points, text, triangle lists; lists of 10 points) on a grid around the
// robot, kept by a MarkerDisplay; per frame the markers are turned into scene items (as every
// animation frame does) and drawn with 4x multisampling and read back. Median wall time of the
// whole frame and of the scene building alone, and the CPU time of all threads.
// usage: urdfsnap_markers_bench [MARKERS [FRAMES [SAMPLES [TYPE [PNG]]]]]   (defaults 1000, 30, 4
// and every type; TYPE a visualization_msgs/Marker type number, e.g. 2 for SPHERE, to time or
// profile that type alone, -1 every type; PNG: where to write the frame's image, to compare the
// pixels of two builds with `urdfsnap diff`)
// Timings only: no test asserts on them.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../pipeline/frame_loop.h"
#include "../pipeline/timing.h"
#include "common/warnings.h"
#include "display/marker_display.h"
#include "image/png_writer.h"
#include "scene/scene.h"

namespace {

using namespace urdfsnap;
using display::Marker;

constexpr int kTypes[] = {Marker::kArrow,     Marker::kCube,     Marker::kSphere,     Marker::kCylinder,
                          Marker::kLineStrip, Marker::kLineList, Marker::kCubeList,   Marker::kSphereList,
                          Marker::kPoints,    Marker::kTextViewFacing, Marker::kTriangleList};

// Marker i: of `type`, or when that is negative each type in turn, on a 0.25 m grid around the robot, 0.1 m in size.
Marker MixedMarker(int i, int type) {
  Marker m;
  m.header.frame_id = "base_link";
  m.ns = "bench";
  m.id = i;
  m.type = type >= 0 ? type : kTypes[i % std::size(kTypes)];
  m.pose.position = {-4 + 0.25 * (i % 32), -4 + 0.25 * (i / 32 % 32), 0.1 * (i / 1024)};
  m.scale = {0.1, 0.1, 0.1};
  m.colour = {0.2f + 0.6f * (i % 3) / 2, 0.5f, 1.f - 0.6f * (i % 5) / 4, 1};
  m.text = "m" + std::to_string(i);
  const int points = m.type == Marker::kTriangleList ? 9 : 10;
  if (m.type >= Marker::kLineStrip && m.type != Marker::kTextViewFacing) {
    for (int k = 0; k < points; ++k) m.points.emplace_back(0.02f * k, 0.015f * (k % 3), 0.01f * (k % 2));
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int frames = argc > 2 ? std::atoi(argv[2]) : 30;
  const int type = argc > 4 ? std::atoi(argv[4]) : -1;
  const std::string model = std::string(URDFSNAP_SOURCE_DIR) + "/models/mrm_description/urdf/mrm.urdf";
  Warnings warnings;
  const scene::Scene posed = bench::ZeroPoseScene(model);
  display::MarkerDisplay markers("/markers", {true, {}}, {});
  for (int i = 0; i < count; ++i) markers.Apply(MixedMarker(i, type), 0, "bench", warnings);
  const display::FrameLookup base = [](const std::string&, std::int64_t) {
    return std::optional<Eigen::Isometry3d>(Eigen::Isometry3d::Identity());
  };
  const auto frame_scene = [&] {
    scene::Scene scene = posed;
    markers.Draw(0, base, scene, warnings);
    return scene;
  };
  gl::SceneRenderer renderer(argc > 3 ? std::atoi(argv[3]) : 4);
  renderer.Render(frame_scene(), scene::OrbitView{}, 640, 480);   // warm-up: shaders, glyphs, framebuffer
  const double build = bench::MedianTime(frames, [&] { frame_scene(); });
  const double cpu_before = bench::CpuSeconds();
  const double whole = bench::MedianTime(frames, [&] { renderer.Render(frame_scene(), scene::OrbitView{}, 640, 480); });
  const double cpu = (bench::CpuSeconds() - cpu_before) / frames;
  const double robot_only = bench::MedianTime(frames, [&] { renderer.Render(posed, scene::OrbitView{}, 640, 480); });
  std::printf("mrm at 640x480, 4x MSAA, %s; median of %d frames\n", renderer.description().c_str(), frames);
  std::printf("| frame | wall ms per frame | CPU ms per frame |\n|---|---|---|\n");
  std::printf("| mrm alone, draw + read back | %.2f | |\n", 1000 * robot_only);
  const std::string what = type >= 0 ? "markers of type " + std::to_string(type) : "mixed markers";
  std::printf("| %d %s to scene items | %.2f | |\n", count, what.c_str(), 1000 * build);
  std::printf("| mrm + %d %s, scene + draw + read back | %.2f | %.2f |\n", count, what.c_str(), 1000 * whole,
              1000 * cpu);
  if (argc > 5) image::WritePng(renderer.Render(frame_scene(), scene::OrbitView{}, 640, 480).colour, argv[5]);
  if (!warnings.empty()) std::fprintf(stderr, "%s\n", warnings.messages().front().c_str());
  return 0;
}
