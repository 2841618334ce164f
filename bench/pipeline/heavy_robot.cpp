// Writes the heavy benchmark robot: four links, each a binary STL torus of a quarter of the
// triangles, on revolute joints about x.
#include "heavy_robot.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

namespace urdfsnap::bench {

namespace {

constexpr int kLinks = 4;

struct Point {
  float x, y, z;
};

Point TorusPoint(double u, double v, double major, double minor) {
  const double r = major + minor * std::cos(v);
  return {static_cast<float>(r * std::cos(u)), static_cast<float>(r * std::sin(u)),
          static_cast<float>(minor * std::sin(v))};
}

void WriteTorusStl(const std::filesystem::path& path, int triangles) {
  const int around = static_cast<int>(std::sqrt(triangles / 2.0 * 2.5));
  const int tube = std::max(3, triangles / 2 / around);
  std::vector<Point> facets;  // 3 vertices per triangle
  auto at = [&](int i, int j) {
    return TorusPoint(2 * std::numbers::pi * i / around, 2 * std::numbers::pi * j / tube, 0.3,
                      0.1);
  };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < tube; ++j) {
      const Point a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      facets.insert(facets.end(), {a, b, c, a, c, d});
    }
  }
  std::ofstream out(path, std::ios::binary);
  const char header[80] = "urdfsnap benchmark torus";
  out.write(header, sizeof header);
  const std::uint32_t count = static_cast<std::uint32_t>(facets.size() / 3);
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  const float zero_normal[3] = {0, 0, 0};  // STL readers recompute it, as assimp does
  const std::uint16_t attributes = 0;
  for (std::size_t f = 0; f < facets.size(); f += 3) {
    out.write(reinterpret_cast<const char*>(zero_normal), sizeof zero_normal);
    out.write(reinterpret_cast<const char*>(&facets[f]), 3 * sizeof(Point));
    out.write(reinterpret_cast<const char*>(&attributes), sizeof attributes);
  }
}

}  // namespace

std::string WriteHeavyRobot(const std::string& dir, int triangles) {
  const std::filesystem::path root = std::filesystem::absolute(dir);
  std::filesystem::create_directories(root / "meshes");
  std::ostringstream urdf;
  urdf << "<?xml version=\"1.0\"?>\n<robot name=\"heavy\">\n";
  for (int i = 0; i < kLinks; ++i) {
    const auto mesh = root / "meshes" / ("link" + std::to_string(i) + ".stl");
    WriteTorusStl(mesh, triangles / kLinks);
    urdf << "  <link name=\"link" << i << "\"><visual><geometry><mesh filename=\"file://"
         << mesh.string() << "\"/></geometry></visual></link>\n";
    if (i > 0) {
      urdf << "  <joint name=\"joint" << i << "\" type=\"revolute\"><parent link=\"link" << i - 1
           << "\"/><child link=\"link" << i << "\"/><origin xyz=\"0 0 0.5\"/><axis xyz=\"1 0 0\"/>"
           << "<limit lower=\"-3.1\" upper=\"3.1\" effort=\"1\" velocity=\"1\"/></joint>\n";
    }
  }
  urdf << "</robot>\n";
  const auto path = root / "heavy.urdf";
  std::ofstream(path) << urdf.str();
  return path.string();
}

}  // namespace urdfsnap::bench
