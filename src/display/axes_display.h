// RViz's Axes display (axes_display.cpp): axes at a reference frame, followed through TF.
#pragma once

#include "display/display.h"
#include "display/display_settings.h"

namespace urdfsnap::display {

class AxesDisplay : public Display {
 public:
  // `fixed_frame`: the frame a settings' empty Reference Frame stands for.
  AxesDisplay(AxesSettings settings, std::string fixed_frame);

  const std::string& topic() const override { return no_topic_; }
  bool Reads(const std::string&) const override { return false; }
  void Receive(const bag::MessageValue&, std::int64_t, const std::string&, Warnings&) override {}
  void Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
            Warnings& warnings) const override;

 private:
  AxesSettings settings_;
  std::string frame_;
  std::string no_topic_;
};

}  // namespace urdfsnap::display
