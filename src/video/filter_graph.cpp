// FilterGraph: buffer/buffersink filters made by hand, the rest parsed from the description with
// avfilter_graph_parse_ptr (FFmpeg's filtering example's way of joining them).
#include "video/internal/filter_graph.h"

extern "C" {
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/pixdesc.h>
}

#include "common/error.h"
#include "video/internal/ffmpeg_output.h"

namespace urdfsnap::video {

FilterGraph::FilterGraph(const std::vector<Source>& sources, const std::string& description,
                         std::string output)
    : output_(std::move(output)), graph_(avfilter_graph_alloc()) {
  TakeOverFfmpegLog();
  if (!graph_) throw std::bad_alloc();
  graph_->nb_threads = 1;            // the encoders' threads and the renderer have the cores
  AVFilterInOut* outputs = nullptr;  // the sources' open pads, as the description sees them
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const Source& source = sources[i];
    const std::string name = "in" + std::to_string(i);
    const std::string arguments = "video_size=" + std::to_string(source.width) + "x" +
                                  std::to_string(source.height) +
                                  ":pix_fmt=" + av_get_pix_fmt_name(source.format) +
                                  ":time_base=" + std::to_string(source.time_base.num) + "/" +
                                  std::to_string(source.time_base.den) + ":pixel_aspect=1/1";
    AVFilterContext* context = nullptr;
    CheckAv(avfilter_graph_create_filter(&context, avfilter_get_by_name("buffer"), name.c_str(),
                                         arguments.c_str(), nullptr, graph_),
            output_, "cannot make a frame source");
    sources_.push_back(context);
    AVFilterInOut* pad = avfilter_inout_alloc();
    pad->name = av_strdup(name.c_str());
    pad->filter_ctx = context;
    pad->pad_idx = 0;
    pad->next = outputs;
    outputs = pad;
  }
  CheckAv(avfilter_graph_create_filter(&sink_, avfilter_get_by_name("buffersink"), "out", nullptr,
                                       nullptr, graph_),
          output_, "cannot make a frame sink");
  AVFilterInOut* inputs = avfilter_inout_alloc();
  inputs->name = av_strdup("out");
  inputs->filter_ctx = sink_;
  inputs->pad_idx = 0;
  inputs->next = nullptr;
  const int parsed =
      avfilter_graph_parse_ptr(graph_, description.c_str(), &inputs, &outputs, nullptr);
  avfilter_inout_free(&inputs);
  avfilter_inout_free(&outputs);
  CheckAv(parsed, output_, "cannot build the filters '" + description + "'");
  CheckAv(avfilter_graph_config(graph_, nullptr), output_, "cannot set up '" + description + "'");
}

FilterGraph::~FilterGraph() { avfilter_graph_free(&graph_); }

void FilterGraph::Push(int index, const AVFrame* frame) {
  // PUSH runs the filters now: without it the source queues every frame until the sink is asked,
  // and the palette pass, which asks only at the end, held the whole animation in memory (9 GB
  // for 10,000 frames of 640x480); KEEP_REF leaves the caller's frame as it was
  CheckAv(av_buffersrc_add_frame_flags(sources_[index], const_cast<AVFrame*>(frame),
                                       AV_BUFFERSRC_FLAG_PUSH | AV_BUFFERSRC_FLAG_KEEP_REF),
          output_, "cannot filter a frame");
}

bool FilterGraph::Pull(AVFrame* frame) {
  av_frame_unref(frame);
  const int result = av_buffersink_get_frame(sink_, frame);
  if (result == AVERROR(EAGAIN) || result == AVERROR_EOF) return false;
  CheckAv(result, output_, "cannot filter a frame");
  return true;
}

}  // namespace urdfsnap::video
