// GL plumbing by exact pixels (after MuJoCo's render test): cleared background, a lit triangle
// facing the camera, row order of the read-back, and the grid's blended line colour.
#include "gl/scene_renderer.h"

#include <cstdlib>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/error.h"
#include "gl/internal/gpu_mesh.h"
#include "gl/internal/shader_program.h"
#include "texture/glyph_atlas.h"
#include "front_view.h"
#include "scene/grid.h"
#include "scene/primitive_meshes.h"
#include "renderer_fixture.h"

namespace urdfsnap::gl {
namespace {

using namespace urdfsnap::scene;  // the scene vocabulary the renderer draws

using Rgb = std::array<int, 3>;

Rgb Pixel(const image::Image& image, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * image.width + x) * 3;
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

// One triangle in the x = 0 plane, facing +X (the camera), covering the upper part of the view.
std::shared_ptr<const geometry::TriangleMesh> UpperTriangle() {
  geometry::TriangleMesh mesh;
  mesh.positions = {{0, -0.3f, 0.1f}, {0, 0.3f, 0.1f}, {0, 0, 0.6f}};
  mesh.normals.assign(3, Eigen::Vector3f::UnitX());
  mesh.indices = {0, 1, 2};
  return std::make_shared<const geometry::TriangleMesh>(mesh);
}

using RendererTest = RendererFixture;

TEST_F(RendererTest, RunsOnTheBackendAskedForAndSaysWhichGl) {
  const char* asked = std::getenv("URDFSNAP_GL_BACKEND");
  if (asked && *asked && std::string(asked) != "auto") {
    EXPECT_EQ(BackendName(renderer_->backend()), asked);
  }
  const std::string prefix = renderer_->backend() == Backend::kEgl ? "EGL (" : "OSMesa, ";
  EXPECT_EQ(renderer_->description().rfind(prefix, 0), 0u) << renderer_->description();
  EXPECT_NE(renderer_->description().find(", OpenGL "), std::string::npos) << renderer_->description();
}

TEST_F(RendererTest, EmptySceneIsTheBackgroundEverywhere) {
  Scene scene;
  scene.background = {48 / 255.f, 48 / 255.f, 48 / 255.f};
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48).colour;
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) ASSERT_EQ(Pixel(image, x, y), (Rgb{48, 48, 48})) << x << "," << y;
  }
}

// UpperTriangle in orange-red (1, 0.2, 0).
Scene UpperTriangleScene() {
  Scene scene;
  DrawItem item;
  item.mesh = UpperTriangle();
  item.X_FG = Eigen::Affine3d::Identity();
  item.rgba = {1, 0.2f, 0, 1};
  scene.items.push_back(item);
  return scene;
}

TEST_F(RendererTest, TriangleFacingTheLightHasItsFullColourAndTopRowComesFirst) {
  const Scene scene = UpperTriangleScene();
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48).colour;
  // n · l = 1, so the colour is exactly the diffuse colour (0.2 · 255 = 51)
  EXPECT_EQ(Pixel(image, 32, 14), (Rgb{255, 51, 0}));
  // the triangle is above the centre, so the bottom rows are background
  EXPECT_EQ(Pixel(image, 32, 40), (Rgb{48, 48, 48}));
  EXPECT_EQ(Pixel(image, 2, 2), (Rgb{48, 48, 48}));
}

TEST_F(RendererTest, ReleasedContextRendersOnAnotherThread) {
  const Scene scene = UpperTriangleScene();
  const image::Image here = renderer_->Render(scene, FrontView(), 64, 48).colour;
  // without the release, EGL refuses the context on the other thread (EGL_BAD_ACCESS)
  renderer_->ReleaseContext();
  image::Image there;
  std::thread([&] {
    there = renderer_->Render(scene, FrontView(), 64, 48).colour;
    renderer_->ReleaseContext();
  }).join();
  EXPECT_EQ(there.rgb, here.rgb);
  EXPECT_EQ(Pixel(there, 32, 14), (Rgb{255, 51, 0}));
  EXPECT_EQ(renderer_->Render(scene, FrontView(), 64, 48).colour.rgb, here.rgb);
}

TEST_F(RendererTest, BackFacesAreCulled) {
  Scene scene;
  DrawItem item;
  item.mesh = UpperTriangle();
  item.X_FG = Eigen::AngleAxisd(3.14159265358979, Eigen::Vector3d::UnitZ()) * Eigen::Affine3d::Identity();
  scene.items.push_back(item);
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48).colour;
  EXPECT_EQ(Pixel(image, 32, 14), (Rgb{48, 48, 48}));
}

// A thin triangle in the x = 0 plane facing the camera, from the view's centre to 50 m away along
// `direction` (in the image plane): the sphere around it is centred far outside the view.
std::shared_ptr<const geometry::TriangleMesh> TriangleReachingIn(const Eigen::Vector3f& direction) {
  const Eigen::Vector3f across = Eigen::Vector3f::UnitX().cross(direction);
  geometry::TriangleMesh mesh;
  mesh.positions = {-0.1f * direction - 0.1f * across, -0.1f * direction + 0.1f * across, 50 * direction};
  if ((mesh.positions[1] - mesh.positions[0]).cross(mesh.positions[2] - mesh.positions[0]).x() < 0) {
    std::swap(mesh.positions[0], mesh.positions[1]);   // counter-clockwise seen from the camera
  }
  mesh.normals.assign(3, Eigen::Vector3f::UnitX());
  mesh.indices = {0, 1, 2};
  return std::make_shared<const geometry::TriangleMesh>(mesh);
}

TEST_F(RendererTest, MeshesOutsideTheViewAreLeftOutAndThoseReachingInAreDrawn) {
  const Eigen::Vector3f sides[] = {Eigen::Vector3f::UnitY(), -Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitZ(),
                                   -Eigen::Vector3f::UnitZ()};
  for (const Eigen::Vector3f& side : sides) {
    for (const double mirror : {1.0, -1.0}) {
      SCOPED_TRACE(testing::Message() << "reaching in from " << side.transpose() << ", mirror " << mirror);
      Scene scene;
      DrawItem item;
      item.mesh = TriangleReachingIn(side);
      item.link = 0;
      // mirrored through the image plane's vertical axis, the winding and the side turn round
      item.X_FG = Eigen::Affine3d(Eigen::Scaling(1.0, mirror, 1.0));
      item.rgba = {1, 0.2f, 0, 1};
      scene.items.push_back(item);
      // and a mesh wholly outside, beside it, draws nothing
      DrawItem outside = item;
      outside.X_FG = Eigen::Translation3d(0, 0, 30) * item.X_FG;
      scene.items.push_back(outside);
      const image::Frame frame = renderer_->Render(scene, FrontView(), 64, 48, {true, false, true});
      EXPECT_EQ(Pixel(frame.colour, 32, 24), (Rgb{255, 51, 0}));
      EXPECT_EQ(frame.labels.labels[24 * 64 + 32], 1);   // the label pass draws it too
      EXPECT_EQ(Pixel(frame.colour, 2, 2), (Rgb{48, 48, 48}));
    }
  }
}

TEST_F(RendererTest, ClipVolumeTestLeavesOutOnlyWhatCannotBeSeen) {
  renderer_->Render(Scene{}, FrontView(), 64, 48);   // its context current here
  const GpuMesh mesh(*UpperTriangle());
  const Eigen::Matrix4d PV = ProjectionMatrix(FrontView(), 64.0 / 48) * ViewMatrix(FrontView());
  const auto outside = [&](const Eigen::Affine3d& X) { return mesh.OutsideClipVolume(PV * X.matrix()); };
  EXPECT_FALSE(outside(Eigen::Affine3d::Identity()));
  EXPECT_TRUE(outside(Eigen::Affine3d(Eigen::Translation3d(0, 0, 30))));    // above
  EXPECT_TRUE(outside(Eigen::Affine3d(Eigen::Translation3d(0, -30, 0))));   // to the left
  EXPECT_TRUE(outside(Eigen::Affine3d(Eigen::Translation3d(5, 0, 0))));     // behind the camera
  EXPECT_FALSE(outside(Eigen::Affine3d(Eigen::Translation3d(0, 0, -0.5))));  // partly in view
  EXPECT_FALSE(outside(Eigen::Affine3d(Eigen::Scaling(1.0, 100.0, 1.0) * Eigen::Translation3d(0, 0.05, 0))));
  geometry::TriangleMesh unsure = *UpperTriangle();
  unsure.positions[0].x() = std::nanf("");
  EXPECT_FALSE(GpuMesh(unsure).OutsideClipVolume(PV * Eigen::Affine3d(Eigen::Translation3d(0, 0, 30)).matrix()));
}

TEST_F(RendererTest, GridLinesBlendAtHalfAlphaAsRvizMeasured) {
  SceneRenderer no_aa(0);
  Scene scene;
  scene.lines.push_back(MakeGrid({}));
  OrbitView top;
  top.pitch = 1.5;
  top.distance = 12;
  const image::Image image = no_aa.Render(scene, top, 320, 240).colour;
  // without multisampling a line pixel has full coverage: 0.5·(160,160,164) + 0.5·48, and where
  // two lines cross the second blends over the first
  const Rgb line{104, 104, 106}, crossing{132, 132, 135}, background{48, 48, 48};
  int line_pixels = 0, crossings = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Rgb p = Pixel(image, x, y);
      line_pixels += p == line;
      crossings += p == crossing;
      ASSERT_TRUE(p == line || p == crossing || p == background) << x << "," << y;
    }
  }
  EXPECT_GT(line_pixels, 1000);
  EXPECT_GT(crossings, 0);
}

// Line sets are drawn together (one draw for neighbours in the blending order) but stay apart: a
// set's odd last point is dropped, as a draw of its own drops it, not joined to the next set's first.
TEST_F(RendererTest, LineSetsDrawnTogetherStayApart) {
  SceneRenderer no_aa(0);
  Scene scene;
  LineSet odd;   // farther, so drawn first: a red line across the top and a lone point below its end
  odd.points = {{-0.5f, -0.4f, 0.3f}, {-0.5f, 0.4f, 0.3f}, {-0.5f, 0.4f, -0.3f}};
  odd.rgba = {1, 0, 0, 1};
  LineSet next;   // a green line up from the bottom left
  next.points = {{0, -0.4f, -0.3f}, {0, -0.4f, 0}};
  next.rgba = {0, 1, 0, 1};
  scene.lines = {odd, next};
  scene.background = {48 / 255.f, 48 / 255.f, 48 / 255.f};
  const image::Image image = no_aa.Render(scene, FrontView(), 64, 48).colour;
  int widest_top = 0, widest_bottom = 0;   // most line pixels in a row of either half
  for (int y = 0; y < image.height; ++y) {
    int drawn = 0;
    for (int x = 0; x < image.width; ++x) drawn += Pixel(image, x, y) != Rgb{48, 48, 48};
    int& widest = y < image.height / 2 ? widest_top : widest_bottom;
    widest = std::max(widest, drawn);
  }
  EXPECT_GT(widest_top, 10);     // the red line
  EXPECT_LE(widest_bottom, 2);   // the green line only: nothing from the lone point across to it
}

// Pixel (x, y) is `expected` within 12 per channel.
void ExpectNear(const image::Image& image, const Rgb& expected, int x, int y) {
  const Rgb p = Pixel(image, x, y);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], expected[c], 12) << x << "," << y << " channel " << c;
}

// A 2x2 RGBA texture: red, green on top; blue, white below.
std::shared_ptr<const texture::TextureImage> FourColours() {
  auto texture = std::make_shared<texture::TextureImage>();
  texture->width = texture->height = 2;
  texture->texels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  return texture;
}

TEST_F(RendererTest, TextureModulatesTheLitColourWithVZeroAtTheImageTop) {
  // RViz's box faces each show the whole image; the +X face looks at the camera here
  Scene scene;
  DrawItem box;
  box.mesh = UnitBoxMesh();
  box.X_FG = Eigen::Translation3d(-0.5, 0, 0) * Eigen::Scaling(1.0, 1.0, 1.0);
  box.rgba = {1, 1, 0.5f, 1};
  box.texture = FourColours();
  scene.items.push_back(box);
  SceneRenderer no_aa(0);
  const image::Image image = no_aa.Render(scene, FrontView(), 128, 128).colour;
  // the face spans 77 px around the centre; the texel centres (u, v = 0.25, 0.75) lie 19 px from
  // it, where bilinear filtering gives nearly the texels' own colours (within half a pixel). Seen from +X, +Y (u) runs to the
  // right and v = 0 is the top: red top left, green top right, blue bottom left (times the
  // diffuse's half blue), white bottom right (yellowish)
  ExpectNear(image, {255, 0, 0}, 45, 45);
  ExpectNear(image, {0, 255, 0}, 83, 45);
  ExpectNear(image, {0, 0, 128}, 45, 83);
  ExpectNear(image, {255, 255, 128}, 83, 83);
}

TEST_F(RendererTest, EachTextureUnitModulatesByTheTextureAgain) {
  // one texel, so filtering plays no part: the lit white times (128, 192, 255)/255 per unit
  auto texel = std::make_shared<texture::TextureImage>();
  texel->width = texel->height = 1;
  texel->texels = {128, 192, 255, 255};
  Scene scene;
  DrawItem item;
  item.mesh = UpperTriangle();
  item.X_FG = Eigen::Affine3d::Identity();
  item.rgba = {1, 1, 1, 1};
  item.texture = texel;
  scene.items.push_back(item);
  const Rgb expected[] = {{255, 255, 255}, {128, 192, 255}, {64, 145, 255}, {32, 109, 255}};
  for (int units = 0; units < 4; ++units) {
    scene.items[0].texture_units = units;
    const Rgb p = Pixel(renderer_->Render(scene, FrontView(), 64, 48).colour, 32, 14);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], expected[units][c], 1) << units << " units, channel " << c;
  }
}

TEST_F(RendererTest, EmissionAddsToTheLitColourAndClampsAtOne) {
  Scene scene;
  DrawItem item;
  item.mesh = UpperTriangle();
  item.X_FG = Eigen::AngleAxisd(0.9, Eigen::Vector3d::UnitZ()) * Eigen::Affine3d::Identity();
  item.rgba = {0.5f, 0.5f, 0, 1};
  item.emissive = {0.8f, 0, 0.25f};
  scene.items.push_back(item);
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48).colour;
  // n · l = cos 0.9 = 0.6216: red 0.8 + 0.311 clamps to 255, green 0.311·255, blue 0.25·255
  EXPECT_EQ(Pixel(image, 32, 14), (Rgb{255, 79, 64}));
}

// A label "H" 0.4 m high at the origin, seen from the front.
TextLabel LetterH() {
  const auto atlas = texture::BuildGlyphAtlas(texture::FindLiberationSans(), {U'A', U'H'});
  return {atlas->texture, LayOutText(*atlas, "H", 0.4f), Eigen::Vector3d::Zero(), {1, 1, 1, 1}};
}

// The bounding box of the pixels that differ from the background: {x0, y0, x1, y1}, or all -1.
std::array<int, 4> InkBox(const image::Image& image) {
  std::array<int, 4> box{-1, -1, -1, -1};
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (Pixel(image, x, y) == Rgb{48, 48, 48}) continue;
      if (box[0] < 0) box = {x, y, x, y};
      box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
    }
  }
  return box;
}

// Neighbouring labels cut from one glyph texture are one draw, each still at its own anchor and in
// its own colour: a red H left of the centre and a green one right of it.
TEST_F(RendererTest, LabelsOfOneTextureDrawnTogetherKeepTheirAnchorsAndColours) {
  Scene scene;
  TextLabel left = LetterH(), right = left;
  left.anchor = {0, -0.5, 0}, left.rgba = {1, 0, 0, 1};
  right.anchor = {0, 0.5, 0}, right.rgba = {0, 1, 0, 1};
  scene.labels = {left, right};
  const image::Image image = renderer_->Render(scene, FrontView(), 128, 96).colour;
  int red[2] = {0, 0}, green[2] = {0, 0};   // pixels of each colour in the left and right halves
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      red[x >= 64] += Pixel(image, x, y) == Rgb{255, 0, 0};
      green[x >= 64] += Pixel(image, x, y) == Rgb{0, 255, 0};
    }
  }
  EXPECT_GT(red[0], 10);
  EXPECT_EQ(red[1], 0);
  EXPECT_EQ(green[0], 0);
  EXPECT_GT(green[1], 10);
}

// Items of one mesh are one instanced draw (gl/internal/mesh_batches.h), each instance with its own
// pose, colour and winding; translucent ones still blend farthest first whatever the scene's order.
TEST_F(RendererTest, ItemsOfOneMeshEachHaveTheirPoseColourAndWindingAndBlendFarthestFirst) {
  Scene scene;
  const auto mesh = UpperTriangle();   // one mesh: one batch per kind
  const auto add = [&](const Eigen::Affine3d& X_FG, const Eigen::Vector4f& rgba) {
    DrawItem item;
    item.mesh = mesh;
    item.X_FG = X_FG;
    item.rgba = rgba;
    scene.items.push_back(item);
  };
  const Eigen::Translation3d below(0, 0, -0.7);
  add(Eigen::Affine3d(below), {0, 0, 1, 1});                                                 // blue
  add(below * Eigen::Scaling(1.0, -1.0, 1.0) * Eigen::Translation3d(0, 0.7, 0), {1, 1, 0, 1});   // mirrored, left: yellow
  add(Eigen::Affine3d::Identity(), {0, 1, 0, 0.5f});                                         // near: green
  add(Eigen::Affine3d(Eigen::Translation3d(-0.5, 0, 0)), {1, 0, 0, 0.5f});                   // far: red
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48).colour;
  EXPECT_EQ(Pixel(image, 32, 36), (Rgb{0, 0, 255}));
  EXPECT_EQ(Pixel(image, 12, 36), (Rgb{255, 255, 0}));
  // red over the background, then green over that
  const Rgb blended = Pixel(image, 32, 14);
  EXPECT_NEAR(blended[0], 76, 1);
  EXPECT_NEAR(blended[1], 140, 1);
  EXPECT_NEAR(blended[2], 12, 1);
}

// Triangle lists (TRIANGLE_LIST markers) are unlit and seen from both sides, in their corners'
// colours, the translucent ones blended over what is drawn.
TEST_F(RendererTest, TriangleListsAreUnlitTwoSidedAndBlendBelowAlphaOne) {
  Scene scene;
  const auto add = [&](float z, bool facing, const Eigen::Vector4f& rgba) {
    FlatTriangles triangles;
    triangles.positions = {{0, -0.3f, z}, {0, 0.3f, z}, {0, 0, z + 0.3f}};
    if (!facing) std::swap(triangles.positions[0], triangles.positions[1]);   // its back to the camera
    triangles.colours.assign(3, rgba);
    scene.triangles.push_back(triangles);
  };
  add(0.2f, true, {1, 0, 0, 1});
  add(-0.5f, false, {0, 1, 0, 1});
  add(-0.5f, true, {0, 0, 1, 0.5f});   // over the green one
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48).colour;
  EXPECT_EQ(Pixel(image, 32, 14), (Rgb{255, 0, 0}));
  EXPECT_EQ(Pixel(image, 32, 33), (Rgb{0, 127, 128}));   // half blue over green
}

TEST_F(RendererTest, LabelIsWhiteUnlitTextHangingBelowItsAnchor) {
  Scene scene;
  scene.labels.push_back(LetterH());
  const image::Image image = renderer_->Render(scene, FrontView(), 128, 96).colour;
  const std::array<int, 4> box = InkBox(image);
  ASSERT_GE(box[0], 0) << "nothing drawn";
  // the anchor projects to the image centre (64, 48): the letter is centred under it
  EXPECT_NEAR((box[0] + box[2]) / 2.0, 64, 1.5);
  EXPECT_GT(box[1], 48);
  // fully covered stem pixels are white: unlit, not shaded by the head-light
  int white = 0;
  for (int y = box[1]; y <= box[3]; ++y) {
    for (int x = box[0]; x <= box[2]; ++x) white += Pixel(image, x, y) == Rgb{255, 255, 255};
  }
  EXPECT_GT(white, 10);
  // seen from the side the label still faces the camera and keeps its width
  OrbitView side = FrontView();
  side.yaw = 1.2;
  const std::array<int, 4> turned = InkBox(renderer_->Render(scene, side, 128, 96).colour);
  EXPECT_NEAR(turned[2] - turned[0], box[2] - box[0], 1);
}

TEST_F(RendererTest, LabelIsHiddenBehindOpaqueGeometryButWinsAgainstASurfaceThroughIt) {
  Scene scene;
  scene.labels.push_back(LetterH());
  // an opaque box between the camera and the label hides it
  DrawItem box;
  box.mesh = UnitBoxMesh();
  box.X_FG = Eigen::Translation3d(0.5, 0, -0.2) * Eigen::Scaling(0.1, 1.0, 0.8);
  box.rgba = {0, 0, 1, 1};
  scene.items.push_back(box);
  const image::Image hidden = renderer_->Render(scene, FrontView(), 128, 96).colour;
  for (int y = 0; y < hidden.height; ++y) {
    for (int x = 0; x < hidden.width; ++x) ASSERT_NE(Pixel(hidden, x, y), (Rgb{255, 255, 255}));
  }
  // a face 20 µm in front of the text does not hide it: RViz's depth bias pulls the text forward by
  // one step of the 24-bit depth buffer, about 24 µm at 2 m with the 0.01 m near plane (without
  // the bias this face hides the text)
  scene.items[0].X_FG = Eigen::Translation3d(-0.05 + 2e-5, 0, -0.2) * Eigen::Scaling(0.1, 1.0, 0.8);
  const image::Image coplanar = renderer_->Render(scene, FrontView(), 128, 96).colour;
  int white = 0;
  for (int y = 0; y < coplanar.height; ++y) {
    for (int x = 0; x < coplanar.width; ++x) white += Pixel(coplanar, x, y) == Rgb{255, 255, 255};
  }
  EXPECT_GT(white, 10);
}

TEST_F(RendererTest, MultisamplesLieWhereTheyLieInRvizsWindow) {
  // llvmpipe's four samples sit at (0.375, 0.125), (0.875, 0.375), (0.125, 0.625) and
  // (0.625, 0.875) of a pixel in the buffer's row order. In a window (RViz's) the first row is
  // the top one, so the upper left eighth of pixel (32, 24) holds one sample and the lower left
  // eighth none; in a bottom-up framebuffer object it would be the other way round.
  const int one_sample = 48 + (255 - 48) / 4;
  Scene upper;
  upper.items.push_back(ImageRectangle(32, 32.5, 24, 24.25));
  EXPECT_NEAR(Pixel(renderer_->Render(upper, FrontView(), 64, 48).colour, 32, 24)[0], one_sample, 1);
  Scene lower;
  lower.items.push_back(ImageRectangle(32, 32.5, 24.75, 25));
  EXPECT_EQ(Pixel(renderer_->Render(lower, FrontView(), 64, 48).colour, 32, 24), (Rgb{48, 48, 48}));
  // and the image is upright: the sample in the lower right eighth is pixel (32, 24)'s
  Scene lower_right;
  lower_right.items.push_back(ImageRectangle(32.5, 33, 24.75, 25));
  EXPECT_NEAR(Pixel(renderer_->Render(lower_right, FrontView(), 64, 48).colour, 32, 24)[0], one_sample, 1);
}

TEST_F(RendererTest, MisspeltShaderUniformIsAnError) {
  renderer_->Render(Scene{}, FrontView(), 8, 8);   // makes the renderer's context current
  const ShaderProgram line("line.vert", "line.frag");
  line.Use();
  line.Set("model_view_projection", Eigen::Matrix4f::Identity().eval());
  try {
    line.Set("model_view_projektion", Eigen::Matrix4f::Identity().eval());
    FAIL() << "no error for a misspelt uniform";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "shader program line.vert + line.frag has no active uniform 'model_view_projektion'");
  }
}

// The define switches the sources' #ifdef variants: only the textured surface program samples an
// image, so only it has the uniforms for one.
TEST_F(RendererTest, DefineSelectsTheShaderVariant) {
  renderer_->Render(Scene{}, FrontView(), 8, 8);   // makes the renderer's context current
  const ShaderProgram textured("lit.vert", "lit.frag", "TEXTURED");
  textured.Use();
  textured.Set("texture_units", 1);
  textured.Set("image", 0);
  const ShaderProgram plain("lit.vert", "lit.frag");
  plain.Use();
  try {
    plain.Set("image", 0);
    FAIL() << "the untextured program samples an image";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "shader program lit.vert + lit.frag has no active uniform 'image'");
  }
}

}  // namespace
}  // namespace urdfsnap::gl
