// CoverageCull without GL: which instances are culled, what is kept of them, and that the
// commands name their instances in order (the pixels themselves: small_triangle_cull_test.cpp).
#include "gl/internal/coverage_cull.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "geometry/triangle_mesh.h"
#include "scene/orbit_view.h"

namespace urdfsnap::gl {
namespace {

// An instance of the unit sphere `diameter` metres across at `where`, seen from RViz's default
// view in a 640x480 image.
MeshInstance Sphere(const Eigen::Vector3d& where, double diameter) {
  const scene::OrbitView view;
  const Eigen::Matrix4d MVP = scene::ProjectionMatrix(view, 640.0 / 480) * scene::ViewMatrix(view) *
                              (Eigen::Translation3d(where) * Eigen::Scaling(diameter)).matrix();
  MeshInstance instance{};
  Eigen::Map<Eigen::Matrix4f>(instance.model_view_projection) = MVP.cast<float>();
  return instance;
}

class CoverageCullTest : public ::testing::Test {
 protected:
  const geometry::TriangleMesh sphere_ = geometry::MakeUnitSphere();
  // llvmpipe's four sample positions
  CoverageCull cull_{640, 480, {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}}};
  std::vector<std::uint32_t> indices_;
  std::vector<InstanceTriangles> commands_;

  bool Cull(const std::vector<MeshInstance>& instances) {
    return cull_.Cull(sphere_, Eigen::Vector3d::Zero(), 0.5, false, instances, indices_, commands_);
  }
};

TEST_F(CoverageCullTest, SmallSphereKeepsFewOfItsTrianglesAllOfThemItsOwn) {
  ASSERT_TRUE(Cull({Sphere({1, 2, 0}, 0.1)}));
  ASSERT_EQ(commands_.size(), 1u);
  EXPECT_EQ(commands_[0].first_index, 0u);
  EXPECT_EQ(commands_[0].instance_count, 1u);
  EXPECT_EQ(commands_[0].base_instance, 0u);
  EXPECT_EQ(commands_[0].count, indices_.size());
  // far fewer than the front faces (half), and some
  EXPECT_GT(indices_.size(), 0u);
  EXPECT_LT(indices_.size(), sphere_.indices.size() / 3);
  // whole triangles of the mesh, in its order
  ASSERT_EQ(indices_.size() % 3, 0u);
  std::size_t t = 0;
  for (std::size_t k = 0; k < indices_.size(); k += 3, t += 3) {
    while (t < sphere_.indices.size() && !std::equal(indices_.begin() + k, indices_.begin() + k + 3,
                                                     sphere_.indices.begin() + t)) {
      t += 3;
    }
    ASSERT_LT(t, sphere_.indices.size());
  }
}

TEST_F(CoverageCullTest, LargeSphereIsDrawnAsItIs) {
  EXPECT_FALSE(Cull({Sphere({0, 0, 0}, 3)}));
  EXPECT_TRUE(indices_.empty());
  EXPECT_TRUE(commands_.empty());
}

TEST_F(CoverageCullTest, InstancesReachingOutOfTheViewAreDrawnWholeAndEachNamesItsInstance) {
  // the second is a small sphere beside the eye, reaching through the near plane
  const scene::OrbitView view;
  const Eigen::Vector3d eye = scene::EyePosition(view);
  ASSERT_TRUE(Cull({Sphere({1, 2, 0}, 0.1), Sphere(eye, 0.1), Sphere({-1, 2, 0}, 0.1)}));
  ASSERT_EQ(commands_.size(), 3u);
  for (std::uint32_t i = 0; i < 3; ++i) EXPECT_EQ(commands_[i].base_instance, i);
  EXPECT_EQ(commands_[1].count, sphere_.indices.size());
  EXPECT_TRUE(std::equal(sphere_.indices.begin(), sphere_.indices.end(), indices_.begin() + commands_[1].first_index));
  EXPECT_LT(commands_[0].count, sphere_.indices.size() / 3);
  EXPECT_LT(commands_[2].count, sphere_.indices.size() / 3);
}

TEST_F(CoverageCullTest, SphereBetweenSamplesKeepsNothing) {
  // a sphere far smaller than the gaps between samples, 3 hundredths of a pixel across, around
  // the focal point, which the view sees at window (320, 240): a pixel corner, 0.395 pixels from
  // the nearest samples
  ASSERT_TRUE(Cull({Sphere({0, 0, 0}, 0.0005)}));
  EXPECT_TRUE(indices_.empty());
  EXPECT_TRUE(commands_.empty());
}

TEST_F(CoverageCullTest, MeshNamingAVertexItLacksIsLeftToGl) {
  geometry::TriangleMesh broken = sphere_;
  broken.indices.back() = static_cast<std::uint32_t>(broken.positions.size());
  EXPECT_FALSE(cull_.Cull(broken, Eigen::Vector3d::Zero(), 0.5, false, {Sphere({1, 2, 0}, 0.1)}, indices_, commands_));
  EXPECT_TRUE(commands_.empty());
}

}  // namespace
}  // namespace urdfsnap::gl
