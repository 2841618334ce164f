// WriteHtmlReport: index.html with inline CSS and JavaScript, referring to the PNGs beside it. The
// swipe view stacks the actual image over the expected one and clips it at the slider position.
#include <filesystem>
#include <optional>
#include <sstream>

#include "common/atomic_file.h"
#include "common/markup_text.h"
#include "snapshot/report_images.h"
#include "snapshot/reports.h"

namespace urdfsnap::snapshot {

namespace {

namespace fs = std::filesystem;

constexpr const char* kHead = R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>urdfsnap snapshot report</title>
<style>
body { font-family: sans-serif; background: #1e1f22; color: #e4e4e4; margin: 1.5em; }
a { color: #8ab4f8; }
table { border-collapse: collapse; margin-bottom: 2em; }
td, th { border-bottom: 1px solid #444; padding: 0.3em 0.8em; text-align: left; }
.ok { color: #6fcf73; } .FAILED, .MISSING, .ERROR { color: #ff6b6b; font-weight: bold; }
section { border: 1px solid #444; border-radius: 6px; padding: 0 1em 1em; margin-bottom: 2em; }
.figures { font-family: monospace; }
.legend { color: #aaa; font-size: 0.9em; }
.trio { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; }
figcaption { color: #aaa; font-size: 0.9em; margin-top: 0.3em; }
.trio img { width: 360px; max-width: 100%; border: 1px solid #555; }
.swipe { position: relative; display: inline-block; line-height: 0; cursor: ew-resize;
         border: 1px solid #555; max-width: 100%; user-select: none; }
.swipe img { display: block; max-width: 100%; }
.swipe .actual { position: absolute; top: 0; left: 0; clip-path: inset(0 0 0 50%); }
.swipe .line { position: absolute; top: 0; bottom: 0; left: 50%; width: 2px; background: #ffeb3b; }
.swipe .tag { position: absolute; top: 6px; line-height: 1.2; background: rgba(0,0,0,0.6);
              padding: 2px 6px; font-size: 0.85em; }
.slider { display: block; width: 100%; max-width: 640px; }
</style>
</head>
<body>
)";

// Moves each swipe view's clip and line with its slider, and lets the pointer drag on the image.
constexpr const char* kScript = R"(<script>
for (const view of document.querySelectorAll('.swipe')) {
  const slider = view.parentElement.querySelector('.slider');
  const show = () => {
    view.querySelector('.actual').style.clipPath = 'inset(0 0 0 ' + slider.value + '%)';
    view.querySelector('.line').style.left = slider.value + '%';
  };
  const drag = (event) => {
    if (event.buttons !== 1) return;
    const box = view.getBoundingClientRect();
    slider.value = Math.round(100 * (event.clientX - box.left) / box.width);
    show();
  };
  slider.addEventListener('input', show);
  view.addEventListener('pointerdown', drag);
  view.addEventListener('pointermove', drag);
  show();
}
</script>
)";

std::string Figure(const std::string& file, const std::string& caption) {
  return "<figure><img src=\"" + EscapeMarkup(file) + "\" alt=\"" + EscapeMarkup(caption) +
         "\" loading=\"lazy\"><figcaption>" + EscapeMarkup(caption) + "</figcaption></figure>\n";
}

// The images of one comparison (colour, depth or labels): the trio, then the swipe view when it
// has all three. `what` is "" for colour, else "depth" or "labels".
std::string ImageBlock(const ReportImages& images, const std::string& what, const std::string& golden,
                       CaseStatus status) {
  const std::string prefix = what.empty() ? "" : what + " ";
  std::ostringstream html;
  html << "<div class=\"trio\">\n";
  if (!images.expected.empty()) html << Figure(images.expected, prefix + "expected: " + golden);
  if (!images.actual.empty()) {
    html << Figure(images.actual, prefix + (status == CaseStatus::kMissing
                                                ? "actual (no golden yet: urdfsnap snapshot update creates it)"
                                                : "actual"));
  }
  if (!images.diff.empty()) {
    html << Figure(images.diff, prefix + (what.empty()
        ? "diff: magenta over the delta, yellow changed less, over the dimmed expected image"
        : "diff: magenta over the tolerance, cyan robot in one image only, yellow changed less, over the "
          "dimmed expected picture"));
  }
  html << "</div>\n";
  if (!images.expected.empty() && !images.actual.empty() && !images.diff.empty()) {
    html << "<h3>Swipe" << (what.empty() ? "" : " (" + what + ")")
         << ": expected on the left, actual on the right</h3>\n<div class=\"swipe\">"
         << "<img class=\"expected\" src=\"" << EscapeMarkup(images.expected) << "\" alt=\"expected\" loading=\"lazy\">"
         << "<img class=\"actual\" src=\"" << EscapeMarkup(images.actual) << "\" alt=\"actual\" loading=\"lazy\">"
         << "<div class=\"line\"></div><span class=\"tag\" style=\"left:6px\">expected</span>"
         << "<span class=\"tag\" style=\"right:6px\">actual</span></div>\n"
         << "<input class=\"slider\" type=\"range\" min=\"0\" max=\"100\" value=\"50\" "
         << "aria-label=\"swipe between expected and actual\">\n";
  }
  return html.str();
}

// The depth or labels part of a case that did not pass: its heading, figures and pictures.
std::string Gray16Block(const std::optional<Gray16Record>& part, const std::string& what, const char* legend) {
  if (!part || part->status == CaseStatus::kPassed) return "";
  return "<h3>" + EscapeMarkup(what) + " <span class=\"" + StatusWord(part->status) + "\">" +
         StatusWord(part->status) + "</span></h3>\n<p class=\"figures\">" + EscapeMarkup(part->message) +
         "</p>\n<p class=\"legend\">" + legend + "</p>\n" + ImageBlock(part->images, what, part->golden, part->status);
}

// The section of one case that did not pass: its figures and the images it has.
std::string CaseSection(const CaseRecord& r) {
  std::ostringstream html;
  html << "<section id=\"" << EscapeMarkup(r.name) << "\">\n<h2>" << EscapeMarkup(r.name)
       << " <span class=\"" << StatusWord(r.status) << "\">" << StatusWord(r.status) << "</span>"
       << (r.shard.empty() ? "" : " <small>shard " + EscapeMarkup(r.shard) + "</small>")
       << "</h2>\n<p class=\"figures\">" << EscapeMarkup(r.message) << "</p>\n";
  if (!r.camera.empty()) {
    html << "<p class=\"camera\">" << EscapeMarkup(r.camera)
         << ". Drawn with the camera stored beside the golden, so the differences below are the model's; "
            "<code>snapshot update</code> stores the new camera.</p>\n";
  }
  html << ImageBlock(r.images, "", r.golden, r.status);
  html << Gray16Block(r.depth, "depth",
                      "Depth in false colour: near yellow, through green and blue, to far purple (expected and "
                      "actual over the same range); black: no robot.");
  html << Gray16Block(r.labels, "labels", "One colour per link (the same link, the same colour); black: no robot.");
  html << "</section>\n";
  return html.str();
}

bool FromShards(const std::vector<CaseRecord>& records) {
  for (const CaseRecord& r : records) {
    if (!r.shard.empty()) return true;
  }
  return false;
}

}  // namespace

void WriteHtmlReport(OutputPlan& outputs, const std::string& dir, const std::string& suite_path,
                     const std::vector<CaseRecord>& records) {
  const bool shards = FromShards(records);
  // written row by row: a report of thousands of cases is never held whole in memory
  AtomicFile& html = outputs.Open(ReportIndexFile(dir));
  html.Write(kHead);
  html.Write("<h1>Snapshot report: " + EscapeMarkup(suite_path) + "</h1>\n<p>" +
             EscapeMarkup(Summary(records)) + "</p>\n<table>\n<tr><th>case</th><th>status</th>" +
             (shards ? "<th>shard</th>" : "") + "<th>figures</th></tr>\n");
  for (const CaseRecord& r : records) {
    const std::string name = EscapeMarkup(r.name);
    const bool passed = r.status == CaseStatus::kPassed;
    html.Write("<tr><td>" + (passed ? name : "<a href=\"#" + name + "\">" + name + "</a>") +
               "</td><td class=\"" + StatusWord(r.status) + "\">" + StatusWord(r.status) + "</td>" +
               (shards ? "<td>" + EscapeMarkup(r.shard) + "</td>" : "") + "<td class=\"figures\">" +
               EscapeMarkup(r.message) + "</td></tr>\n");
  }
  html.Write("</table>\n");
  for (const CaseRecord& r : records) {
    if (r.status != CaseStatus::kPassed) html.Write(CaseSection(r));
  }
  html.Write(kScript);
  html.Write("</body>\n</html>\n");
  html.Close();
}

}  // namespace urdfsnap::snapshot
