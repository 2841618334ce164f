// The point-cloud drawing benchmark (issue 23's budget: mrm plus a 100k-point PointCloud2 at
// 640x480 on 2 cores, Points <= 8 ms per frame, Flat Squares <= 25 ms): mrm at its zero pose in
// RViz's default view with a cloud of N points (a lidar-like ring of walls and floor around the
// robot, coloured by height), drawn in each style with 4x multisampling and read back; the median
// per-frame time of the draw alone and of the robot without points, through the typed core.
// usage: urdfsnap_points_bench [POINTS [FRAMES [SAMPLES [STYLE [PNG]]]]]   (defaults 100000, 30, 4
// and every style; STYLE as the table names it, "Points" or "Flat Squares", to profile one; PNG
// a file for STYLE's frame, to compare two builds' pictures with `urdfsnap diff`)
// Timings only: no test asserts on them.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "../pipeline/frame_loop.h"
#include "../pipeline/timing.h"
#include "image/png_writer.h"
#include "scene/scene.h"

namespace {

using namespace urdfsnap;
using Style = scene::PointSet::Style;

// `count` points on a cylinder wall of radius 3 m (0..2 m high) and a floor disc, seeded.
scene::PointSet Cloud(std::size_t count, Style style) {
  scene::PointSet points;
  points.style = style;
  points.size = style == Style::kPoints ? Eigen::Vector3f::Constant(3) : Eigen::Vector3f::Constant(0.01f);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  points.positions.reserve(count);
  points.colours.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const float angle = 6.2831853f * unit(random);
    const bool wall = i % 2 == 0;
    const float radius = wall ? 3.f : 3.f * std::sqrt(unit(random));
    const float z = wall ? 2.f * unit(random) : 0.f;
    points.positions.emplace_back(radius * std::cos(angle), radius * std::sin(angle), z);
    points.colours.emplace_back(z / 2.f, 1.f - z / 2.f, 0.5f, 1.f);
  }
  return points;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 100000;
  const int frames = argc > 2 ? std::atoi(argv[2]) : 30;
  const std::string model = std::string(URDFSNAP_SOURCE_DIR) + "/models/mrm_description/urdf/mrm.urdf";
  const scene::Scene posed = bench::ZeroPoseScene(model);
  gl::SceneRenderer renderer(argc > 3 ? std::atoi(argv[3]) : 4);
  // wall time (median) and the CPU time of all threads (mean), per frame in ms: on a shared
  // machine the wall time grows with the load, the CPU time much less
  const auto time = [&](const scene::Scene& scene) {
    renderer.Render(scene, scene::OrbitView{}, 640, 480);   // warm-up: shaders, framebuffer
    const double cpu_before = bench::CpuSeconds();
    const double wall = bench::MedianTime(frames, [&] { renderer.Render(scene, scene::OrbitView{}, 640, 480); });
    return std::pair{1000 * wall, 1000 * (bench::CpuSeconds() - cpu_before) / frames};
  };
  std::printf("mrm at 640x480, 4x MSAA, %s; median of %d frames, draw + read back\n",
              renderer.description().c_str(), frames);
  std::printf("| scene | wall ms per frame | CPU ms per frame |\n|---|---|---|\n");
  const auto [wall, cpu] = time(posed);
  std::printf("| mrm alone | %.2f | %.2f |\n", wall, cpu);
  const std::pair<Style, const char*> styles[] = {{Style::kPoints, "Points (3 px)"},
                                                  {Style::kFlatSquares, "Flat Squares (0.01 m)"},
                                                  {Style::kSquares, "Squares (0.01 m)"},
                                                  {Style::kSpheres, "Spheres (0.01 m)"},
                                                  {Style::kBoxes, "Boxes (0.01 m)"}};
  const std::string only = argc > 4 ? argv[4] : "";
  for (const auto& [style, name] : styles) {
    if (!only.empty() && std::string(name).rfind(only + " (", 0) != 0) continue;
    scene::Scene scene = posed;
    scene.points.push_back(Cloud(count, style));
    const auto [style_wall, style_cpu] = time(scene);
    std::printf("| mrm + %zu points, %s | %.2f | %.2f |\n", count, name, style_wall, style_cpu);
    if (argc > 5) image::WritePng(renderer.Render(scene, scene::OrbitView{}, 640, 480).colour, argv[5]);
  }
  return 0;
}
