// WriteHtmlReport: index.html with inline CSS and JavaScript and the PNGs beside it. The swipe
// view stacks the actual image over the expected one and clips it at the slider position.
#include <filesystem>
#include <sstream>

#include "common/atomic_file.h"
#include "image/png_writer.h"
#include "snapshot/markup_text.h"
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
         "\"><figcaption>" + EscapeMarkup(caption) + "</figcaption></figure>\n";
}

// The images of one case that did not pass, written beside index.html, and its section.
std::string CaseSection(const fs::path& dir, const CaseResult& r) {
  const SnapshotCase& c = *r.snapshot_case;
  const std::string expected = c.name + ".expected.png", actual = c.name + ".actual.png",
                    diff = c.name + ".diff.png";
  std::ostringstream html;
  html << "<section id=\"" << EscapeMarkup(c.name) << "\">\n<h2>" << EscapeMarkup(c.name)
       << " <span class=\"" << StatusWord(r.status) << "\">" << StatusWord(r.status)
       << "</span></h2>\n<p class=\"figures\">" << EscapeMarkup(r.message) << "</p>\n";
  html << "<div class=\"trio\">\n";
  if (!r.expected.rgb.empty()) {
    image::WritePng(r.expected, (dir / expected).string());
    html << Figure(expected, "expected: " + c.golden);
  }
  if (!r.actual.rgb.empty()) {
    image::WritePng(r.actual, (dir / actual).string());
    html << Figure(actual, r.status == CaseStatus::kMissing
                               ? "actual (no golden yet: urdfsnap snapshot update creates it)"
                               : "actual");
  }
  if (!r.diff.rgb.empty()) {
    image::WritePng(r.diff, (dir / diff).string());
    html << Figure(diff, "diff: magenta over the delta, yellow changed less, over the dimmed expected image");
  }
  html << "</div>\n";
  if (!r.expected.rgb.empty() && !r.actual.rgb.empty() && !r.diff.rgb.empty()) {
    html << "<h3>Swipe: expected on the left, actual on the right</h3>\n<div class=\"swipe\">"
         << "<img class=\"expected\" src=\"" << EscapeMarkup(expected) << "\" alt=\"expected\">"
         << "<img class=\"actual\" src=\"" << EscapeMarkup(actual) << "\" alt=\"actual\">"
         << "<div class=\"line\"></div><span class=\"tag\" style=\"left:6px\">expected</span>"
         << "<span class=\"tag\" style=\"right:6px\">actual</span></div>\n"
         << "<input class=\"slider\" type=\"range\" min=\"0\" max=\"100\" value=\"50\" "
         << "aria-label=\"swipe between expected and actual\">\n";
  }
  html << "</section>\n";
  return html.str();
}

}  // namespace

void WriteHtmlReport(const std::string& dir, const Suite& suite, const std::vector<CaseResult>& results) {
  fs::create_directories(dir);
  std::ostringstream html;
  html << kHead << "<h1>Snapshot report: " << EscapeMarkup(suite.path) << "</h1>\n<p>"
       << EscapeMarkup(Summary(results)) << "</p>\n<table>\n<tr><th>case</th><th>status</th>"
       << "<th>figures</th></tr>\n";
  for (const CaseResult& r : results) {
    const std::string name = EscapeMarkup(r.snapshot_case->name);
    const bool passed = r.status == CaseStatus::kPassed;
    html << "<tr><td>" << (passed ? name : "<a href=\"#" + name + "\">" + name + "</a>")
         << "</td><td class=\"" << StatusWord(r.status) << "\">" << StatusWord(r.status)
         << "</td><td class=\"figures\">" << EscapeMarkup(r.message) << "</td></tr>\n";
  }
  html << "</table>\n";
  for (const CaseResult& r : results) {
    if (r.status != CaseStatus::kPassed) html << CaseSection(dir, r);
  }
  html << kScript << "</body>\n</html>\n";
  WriteFileAtomically((fs::path(dir) / "index.html").string(), html.str());
}

}  // namespace urdfsnap::snapshot
