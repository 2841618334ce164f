// RepeatedScenes: a picture whose scene equals an earlier one's is not drawn again, and gets that
// picture's image; scenes that differ anywhere are drawn.
#include "docs/repeated_scenes.h"

#include <gtest/gtest.h>

namespace urdfsnap::docs {
namespace {

scene::Scene Box(double x) {
  scene::Scene scene;
  scene::DrawItem item;
  item.X_FG = Eigen::Translation3d(x, 0, 0);
  item.link = 1;
  scene.items.push_back(item);
  scene::LineSet line;
  line.points = {Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitX()};
  scene.lines.push_back(line);
  return scene;
}

image::Image Filled(int value) {
  image::Image image;
  image.width = image.height = 1;
  image.rgb = {static_cast<std::uint8_t>(value), 0, 0};
  return image;
}

TEST(RepeatedScenesTest, SameSceneComparesEveryPlacement) {
  EXPECT_TRUE(SameScene(Box(0.5), Box(0.5)));
  EXPECT_FALSE(SameScene(Box(0.5), Box(0.5000001)));
  scene::Scene moved_line = Box(0.5);
  moved_line.lines[0].points[1].y() = 1e-6f;
  EXPECT_FALSE(SameScene(Box(0.5), moved_line));
  scene::Scene more = Box(0.5);
  more.items.push_back(more.items[0]);
  EXPECT_FALSE(SameScene(Box(0.5), more));
}

TEST(RepeatedScenesTest, EachDistinctSceneIsDrawnOnce) {
  const std::vector<double> places = {0, 1, 0, 0, 2, 1};
  RepeatedScenes repeated(static_cast<int>(places.size()), [&](int k) { return Box(places[k]); });
  std::vector<int> drawn;
  for (int k = 0; k < static_cast<int>(places.size()); ++k) {
    const image::Image image = repeated.Picture(k, [&] {
      drawn.push_back(k);
      return Filled(10 * k);
    });
    const int first = k == 2 || k == 3 ? 0 : k == 5 ? 1 : k;
    EXPECT_EQ(image.rgb[0], 10 * first) << "picture " << k;
  }
  EXPECT_EQ(drawn, (std::vector<int>{0, 1, 4}));
}

TEST(RepeatedScenesTest, ARepeatOfAPictureNotDrawnHereIsDrawn) {
  RepeatedScenes repeated(3, [](int) { return Box(0); });
  int draws = 0;
  const auto draw = [&] { return Filled(++draws); };
  // a piece of the page that wants pictures 1 and 2 only: picture 1 is drawn, picture 2 repeats it
  EXPECT_EQ(repeated.Picture(1, draw).rgb[0], 1);
  EXPECT_EQ(repeated.Picture(2, draw).rgb[0], 1);
  EXPECT_EQ(draws, 1);
}

}  // namespace
}  // namespace urdfsnap::docs
