// SceneRenderer::CullSmallTriangles: many small lit shapes (RViz's sphere, cylinder, cone and cube,
// as markers are) drawn with and without dropping the triangles that cover no sample give the same
// bytes, in the colour, depth and label images, with 4x multisampling and without.
#include <cstring>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "gl/scene_renderer.h"
#include "scene/primitive_meshes.h"
#include "support/gl_required.h"

namespace urdfsnap::gl {
namespace {

// `count` shapes 2 cm to 30 cm across, turned every way, some mirrored, on a 6 m square around
// the origin (RViz's default view sees it from 10 m, so most are a few pixels wide and some reach
// out of the image); translucent ones unless `opaque`, each a link of its own when `links`.
scene::Scene SmallShapes(int count, bool opaque, bool links) {
  const std::shared_ptr<const geometry::TriangleMesh> meshes[] = {scene::UnitSphereMesh(), scene::UnitCylinderMesh(),
                                                                   scene::UnitConeMesh(), scene::UnitBoxMesh()};
  std::mt19937 random(23);
  std::uniform_real_distribution<double> place(-3, 3), size(0.02, 0.3), unit(0, 1);
  scene::Scene scene;
  for (int i = 0; i < count; ++i) {
    scene::DrawItem item;
    item.mesh = meshes[i % 4];
    const Eigen::Quaterniond turn = Eigen::Quaterniond::UnitRandom();
    const Eigen::Vector3d scale(size(random), size(random) * (i % 7 == 0 ? -1 : 1), size(random));
    item.X_FG = Eigen::Translation3d(place(random), place(random), place(random) / 3) * turn * Eigen::Scaling(scale);
    item.rgba = {static_cast<float>(unit(random)), static_cast<float>(unit(random)), static_cast<float>(unit(random)),
                 opaque || i % 3 ? 1.f : 0.5f};
    item.link = links ? i : -1;
    scene.items.push_back(item);
  }
  return scene;
}

// Renders `scene` at 320x240 with each output, culling small triangles and not, and expects the
// same bytes.
void ExpectSameWithAndWithoutCulling(SceneRenderer& renderer, const scene::Scene& scene) {
  const image::FrameOutputs all{true, true, true};
  renderer.CullSmallTriangles(false);
  const image::Frame plain = renderer.Render(scene, scene::OrbitView{}, 320, 240, all);
  renderer.CullSmallTriangles(true);
  const image::Frame culled = renderer.Render(scene, scene::OrbitView{}, 320, 240, all);
  ASSERT_EQ(plain.colour.rgb.size(), 320u * 240 * 3);
  ASSERT_EQ(plain.depth.metres.size(), culled.depth.metres.size());
  EXPECT_TRUE(plain.colour.rgb == culled.colour.rgb);
  EXPECT_TRUE(plain.labels.labels == culled.labels.labels);
  EXPECT_EQ(0, std::memcmp(plain.depth.metres.data(), culled.depth.metres.data(),
                           plain.depth.metres.size() * sizeof(float)));
  // not a blank frame: the shapes are drawn
  std::size_t shape_pixels = 0;
  for (const std::uint16_t label : plain.labels.labels) shape_pixels += label != 0;
  EXPECT_GT(shape_pixels, 1000u);
}

TEST(SmallTriangleCullTest, SameBytesWithFourSamples) {
  URDFSNAP_REQUIRE_GL();
  SceneRenderer renderer(4);
  ExpectSameWithAndWithoutCulling(renderer, SmallShapes(600, false, true));   // blended: labels in their own pass
  ExpectSameWithAndWithoutCulling(renderer, SmallShapes(600, true, true));    // opaque: labels in the colour pass
}

TEST(SmallTriangleCullTest, SameBytesWithOneSample) {
  URDFSNAP_REQUIRE_GL();
  SceneRenderer renderer(1);
  ExpectSameWithAndWithoutCulling(renderer, SmallShapes(600, false, true));
  ExpectSameWithAndWithoutCulling(renderer, SmallShapes(600, true, true));
}

}  // namespace
}  // namespace urdfsnap::gl
