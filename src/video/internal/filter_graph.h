// A libavfilter graph between frames urdfsnap pushes and frames it pulls: buffer sources named
// in0, in1, ..., one buffer sink named out, and a filter description between them such as
// "[in0][in1]paletteuse=dither=sierra2_4a[out]".
#pragma once

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavutil/frame.h>
}

#include <string>
#include <vector>

namespace urdfsnap::video {

class FilterGraph {
 public:
  // The frames each source receives.
  struct Source {
    AVPixelFormat format;
    int width, height;
    AVRational time_base;
  };

  // Throws Error naming `output` (the file the frames are for) when the graph cannot be built.
  FilterGraph(const std::vector<Source>& sources, const std::string& description,
              std::string output);
  ~FilterGraph();

  FilterGraph(const FilterGraph&) = delete;
  FilterGraph& operator=(const FilterGraph&) = delete;

  // Gives `frame` to source `index` and runs the filters on it at once (the graph copies what it
  // keeps, so memory does not grow when nothing is pulled); nullptr ends the source's stream.
  void Push(int index, const AVFrame* frame);
  // Takes the next frame out into `frame` (unreferenced first); false when none is ready.
  bool Pull(AVFrame* frame);

 private:
  std::string output_;
  AVFilterGraph* graph_ = nullptr;
  std::vector<AVFilterContext*> sources_;
  AVFilterContext* sink_ = nullptr;
};

}  // namespace urdfsnap::video
