// A bag's camera image behind a calibrated camera's robot in every frame of an animation, and so
// in `render --bag`'s still (frame 0 of a one-frame animation): --underlay-topic's image at the
// frame's moment as RViz's Camera display shows it (display::CameraImageDisplay), fed from the bag
// in one pass as frames advance (display::BagDisplayFeed). Memory holds the shown image and a few
// waiting messages, however long the bag.
#pragma once

#include <optional>
#include <string>

#include "common/warnings.h"
#include "display/bag_display_feed.h"
#include "display/camera_image_display.h"
#include "display/display_set.h"
#include "render/camera_settings.h"

namespace urdfsnap::animation {

class FrameUnderlay {
 public:
  // The images on `topic` of the bag at `bag`, whose trajectory time 0 is the stamp
  // `stamp_at_zero` (seconds since 1970).
  FrameUnderlay(std::string bag, std::string topic, double stamp_at_zero);
  FrameUnderlay(const FrameUnderlay&) = delete;
  FrameUnderlay& operator=(const FrameUnderlay&) = delete;

  // Sets `camera`'s underlay to the image shown at trajectory time `t` (which never goes back from
  // one call to the next). Throws urdfsnap::Error naming the bag when it has no such topic, when
  // the topic carries neither image type, and when no image was received at or before the moment;
  // and naming the message for one that cannot be shown (camera/ros_image.h).
  void Attach(double t, render::CameraSettings& camera, Warnings& warnings);

 private:
  std::string bag_, topic_;
  double stamp_at_zero_;
  display::DisplaySet displays_;   // the camera image alone
  display::CameraImageDisplay* image_;
  display::BagDisplayFeed feed_;
};

}  // namespace urdfsnap::animation
