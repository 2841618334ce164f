// RepeatedScenes: which pictures of a joint section show exactly the scene an earlier one shows,
// so that the page draws each distinct picture once. A joint that moves only links without
// geometry (the PR2's gripper motor screws and slider) shows one scene in every still and sweep
// frame, and a still at the limit the default position sits on repeats the default still: same
// scene, same view, same image.
#pragma once

#include <functional>
#include <map>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace urdfsnap::docs {

// Whether two scenes draw the same: every item, line, label, point and triangle equal, bit for bit.
bool SameScene(const scene::Scene& a, const scene::Scene& b);

class RepeatedScenes {
 public:
  // Poses the scene of every picture k < count (GL-free) and finds the repeats.
  RepeatedScenes(int count, const std::function<scene::Scene(int)>& posed);

  // Picture k: draw() when no earlier picture shows its scene, else that picture's image. An image
  // is kept only until the last picture that repeats it.
  image::Image Picture(int k, const std::function<image::Image()>& draw);

 private:
  std::vector<int> first_;   // per picture: the first picture showing its scene
  std::vector<int> last_;    // per first picture: the last picture that repeats it
  std::map<int, image::Image> kept_;
};

}  // namespace urdfsnap::docs
