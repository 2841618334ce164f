// WriteResults / ReadResults: RunResults to and from JSON with nlohmann_json. Reading checks every
// field's presence and type, naming its place, since a results file travels between machines
// (CI artifacts) and may be truncated, edited or of another tool.
#include "snapshot/results_file.h"

#include <filesystem>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/json_text.h"
#include "common/atomic_file.h"
#include "common/confined_path.h"
#include "snapshot/suite_file.h"

namespace urdfsnap::snapshot {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "urdfsnap-snapshot-results";

// `report_dir` as seen from the folder of the results file `path` (relative when it can be).
std::string RelativeToResults(const std::string& report_dir, const std::string& path) {
  const fs::path report = fs::absolute(report_dir).lexically_normal();
  const fs::path relative = report.lexically_relative(fs::absolute(path).parent_path().lexically_normal());
  return relative.empty() ? report.string() : relative.string();
}

// The bounding box of a comparison's pixels over its tolerance, or null when there are none.
template <typename Stats>
Json RegionJson(const Stats& f) {
  if (f.pixels_over == 0) return nullptr;
  return {{"min_x", f.min_x}, {"min_y", f.min_y}, {"max_x", f.max_x}, {"max_y", f.max_y}};
}

Json FiguresJson(const image::DiffStats& f) {
  Json figures = {{"max_delta", f.max_delta},
                  {"mean_delta", f.mean_delta},
                  {"pixels_over", f.pixels_over},
                  {"fraction_over", f.fraction_over},
                  {"region", nullptr}};
  figures["region"] = RegionJson(f);
  return figures;
}

Json ImagesJson(const ReportImages& images) {
  Json json = Json::object();
  for (const auto& [kind, file] : {std::pair{"expected", &images.expected},
                                   std::pair{"actual", &images.actual}, std::pair{"diff", &images.diff}}) {
    if (!file->empty()) json[kind] = *file;
  }
  return json;
}

Json Gray16Json(const Gray16Record& r) {
  Json figures = nullptr;
  if (r.figures) {
    const image::Gray16DiffStats& f = *r.figures;
    figures = {{"max_delta", f.max_delta},
               {"pixels_over", f.pixels_over},
               {"pixels_coverage", f.pixels_coverage},
               {"fraction_over", f.fraction_over},
               {"region", nullptr}};
    figures["region"] = RegionJson(f);
  }
  return {{"golden", r.golden},
          {"status", StatusName(r.status)},
          {"message", r.message},
          {"tolerance", {{"max_delta", r.tolerance.max_delta}, {"max_fraction", r.tolerance.max_fraction}}},
          {"figures", figures},
          {"images", ImagesJson(r.images)}};
}

Json CaseJson(const CaseRecord& r) {
  Json c = {{"name", r.name},
            {"index", r.index},
            {"line", r.line},
            {"status", StatusName(r.status)},
            {"message", r.message},
            {"seconds", r.seconds},
            {"golden", r.golden},
            {"tolerance", {{"max_delta", r.tolerance.max_delta},
                           {"max_fraction", r.tolerance.max_fraction},
                           {"max_mean", r.tolerance.max_mean}}},
            {"figures", r.figures ? FiguresJson(*r.figures) : Json(nullptr)},
            {"images", ImagesJson(r.images)}};
  if (r.depth) c["depth"] = Gray16Json(*r.depth);
  if (r.labels) c["labels"] = Gray16Json(*r.labels);
  if (!r.camera.empty()) c["camera"] = r.camera;
  if (!r.shard.empty()) c["shard"] = r.shard;
  return c;
}

// Reads fields of a parsed results file, each error naming the file and the field's place.
class FieldReader {
 public:
  explicit FieldReader(const std::string& path) : path_(path) {}

  Error Bad(const std::string& place, const std::string& what) const {
    return Error(path_ + ": " + place + ": " + what);
  }

  const Json& Member(const Json& object, const char* key, const std::string& place) const {
    if (!object.is_object()) throw Bad(place, "expected an object, got " + Short(object));
    if (!object.contains(key)) throw Bad(Place(place, key), "missing");
    return object[key];
  }

  // A value in a message about a value of the wrong kind: a scalar as JSON text, cut short; a
  // list or object by its kind only (dumping one nested a million deep would recurse as deep).
  static std::string Short(const Json& value) {
    if (value.is_array()) return "a list";
    if (value.is_object()) return "an object";
    const std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
    return text.size() <= 40 ? text : text.substr(0, 37) + "...";
  }

  std::string Text(const Json& object, const char* key, const std::string& place) const {
    const Json& value = Member(object, key, place);
    if (!value.is_string()) throw Bad(Place(place, key), "expected a string, got " + Short(value));
    return value.get<std::string>();
  }

  int Whole(const Json& object, const char* key, const std::string& place, int low, int high) const {
    const Json& value = Member(object, key, place);
    if (!value.is_number_integer() || value.get<long long>() < low || value.get<long long>() > high) {
      throw Bad(Place(place, key), "expected a whole number from " + std::to_string(low) + " to " +
                                       std::to_string(high) + ", got " + Short(value));
    }
    return static_cast<int>(value.get<long long>());
  }

  double Number(const Json& object, const char* key, const std::string& place) const {
    const Json& value = Member(object, key, place);
    if (!value.is_number()) throw Bad(Place(place, key), "expected a number, got " + Short(value));
    return value.get<double>();
  }

  static std::string Place(const std::string& place, const char* key) {
    return place.empty() ? key : place + "." + key;
  }

 private:
  std::string path_;
};

constexpr int kMaxInt = 2'147'483'647;

template <typename Stats>
void ReadRegion(const FieldReader& in, const Json& f, const std::string& place, Stats& stats) {
  const Json& region = in.Member(f, "region", place);
  if (region.is_null()) return;
  const std::string here = place + ".region";
  stats.min_x = in.Whole(region, "min_x", here, 0, kMaxInt);
  stats.min_y = in.Whole(region, "min_y", here, 0, kMaxInt);
  stats.max_x = in.Whole(region, "max_x", here, 0, kMaxInt);
  stats.max_y = in.Whole(region, "max_y", here, 0, kMaxInt);
}

image::DiffStats ReadFigures(const FieldReader& in, const Json& f, const std::string& place) {
  image::DiffStats stats;
  stats.max_delta = in.Whole(f, "max_delta", place, 0, 255);
  stats.mean_delta = in.Number(f, "mean_delta", place);
  stats.pixels_over = in.Whole(f, "pixels_over", place, 0, kMaxInt);
  stats.fraction_over = in.Number(f, "fraction_over", place);
  ReadRegion(in, f, place, stats);
  return stats;
}

// The report image names of `object` at `place` ("cases[3].images"): file names inside the report
// folder, never a path out of it.
ReportImages ReadImages(const FieldReader& in, const Json& images, const std::string& place) {
  if (!images.is_object()) throw in.Bad(place, "expected an object");
  ReportImages r;
  for (const auto& [kind, file] : {std::pair{"expected", &r.expected}, std::pair{"actual", &r.actual},
                                   std::pair{"diff", &r.diff}}) {
    if (!images.contains(kind)) continue;
    *file = in.Text(images, kind, place);
    if (fs::path(*file).filename() != *file || *file == "." || *file == "..") {
      throw in.Bad(place + "." + kind, "'" + *file + "' is not a file name");
    }
  }
  return r;
}

CaseStatus ReadStatus(const FieldReader& in, const Json& c, const std::string& place) {
  const std::string status = in.Text(c, "status", place);
  const auto parsed = StatusFromName(status);
  if (!parsed) throw in.Bad(place + ".status", "expected passed, failed, missing or error, got '" + status + "'");
  return *parsed;
}

// A case's "depth" or "labels" object.
Gray16Record ReadGray16(const FieldReader& in, const Json& g, const std::string& place) {
  Gray16Record r;
  r.golden = in.Text(g, "golden", place);
  r.status = ReadStatus(in, g, place);
  if (r.status == CaseStatus::kError) throw in.Bad(place + ".status", "expected passed, failed or missing, got 'error'");
  r.message = in.Text(g, "message", place);
  const Json& tolerance = in.Member(g, "tolerance", place);
  r.tolerance.max_delta = in.Whole(tolerance, "max_delta", place + ".tolerance", 0, 65535);
  r.tolerance.max_fraction = in.Number(tolerance, "max_fraction", place + ".tolerance");
  const Json& f = in.Member(g, "figures", place);
  if (!f.is_null()) {
    const std::string here = place + ".figures";
    image::Gray16DiffStats stats;
    stats.max_delta = in.Whole(f, "max_delta", here, 0, 65535);
    stats.pixels_over = in.Whole(f, "pixels_over", here, 0, kMaxInt);
    stats.pixels_coverage = in.Whole(f, "pixels_coverage", here, 0, kMaxInt);
    stats.fraction_over = in.Number(f, "fraction_over", here);
    ReadRegion(in, f, here, stats);
    r.figures = stats;
  }
  r.images = ReadImages(in, in.Member(g, "images", place), place + ".images");
  return r;
}

CaseRecord ReadCase(const FieldReader& in, const Json& c, const std::string& place) {
  CaseRecord r;
  r.name = in.Text(c, "name", place);
  if (!IsCaseName(r.name)) throw in.Bad(place + ".name", "'" + r.name + "' is not a case name");
  r.index = in.Whole(c, "index", place, 0, kMaxInt);
  r.line = in.Whole(c, "line", place, 0, kMaxInt);
  r.status = ReadStatus(in, c, place);
  r.message = in.Text(c, "message", place);
  r.seconds = in.Number(c, "seconds", place);
  r.golden = in.Text(c, "golden", place);
  const Json& tolerance = in.Member(c, "tolerance", place);
  r.tolerance.max_delta = in.Whole(tolerance, "max_delta", place + ".tolerance", 0, 255);
  r.tolerance.max_fraction = in.Number(tolerance, "max_fraction", place + ".tolerance");
  r.tolerance.max_mean = in.Number(tolerance, "max_mean", place + ".tolerance");
  const Json& figures = in.Member(c, "figures", place);
  if (!figures.is_null()) r.figures = ReadFigures(in, figures, place + ".figures");
  r.images = ReadImages(in, in.Member(c, "images", place), place + ".images");
  if (c.contains("depth")) r.depth = ReadGray16(in, c["depth"], place + ".depth");
  if (c.contains("labels")) r.labels = ReadGray16(in, c["labels"], place + ".labels");
  if (c.contains("camera")) r.camera = in.Text(c, "camera", place);
  if (c.contains("shard")) r.shard = in.Text(c, "shard", place);
  return r;
}

}  // namespace

void WriteResults(OutputPlan& outputs, const std::string& path, const RunResults& results) {
  const Json head = {
      {"format", kFormat},
      {"format_version", kResultsFormatVersion},
      {"urdfsnap_version", results.urdfsnap_version},
      {"suite", {{"path", results.suite.path},
                 {"digest", results.suite.digest},
                 {"cases", results.suite.case_count}}},
      {"shard", {{"index", results.shard.index},
                 {"count", results.shard.count},
                 {"source", results.shard_source}}},
      {"report_dir", results.report_dir.empty() ? Json(nullptr)
                                                : Json(RelativeToResults(results.report_dir, path))}};
  // invalid UTF-8 (a file name in a message) is replaced, not an exception
  const auto dump = [](const Json& json) {
    return json.dump(-1, ' ', false, Json::error_handler_t::replace);
  };
  // the head, then one case per line, written as they go: never the whole file in memory
  AtomicFile& file = outputs.Open(path);
  std::string text = dump(head);
  text.pop_back();  // the closing brace; "cases" follows
  file.Write(text + ",\n\"cases\": [");
  for (std::size_t i = 0; i < results.cases.size(); ++i) {
    file.Write((i == 0 ? "\n" : ",\n") + dump(CaseJson(results.cases[i])));
  }
  file.Write("\n]}\n");
  file.Close();
}

RunResults ReadResults(const std::string& path) {
  std::string text;
  try {
    text = ReadFileBounded(path);
  } catch (const FileReadError& e) {
    throw Error(path + ": cannot read the results file: " + e.what());
  }
  const Json root = ParseJson(text, path);
  const FieldReader in(path);
  if (!root.is_object() || !root.contains("format") || root["format"] != kFormat) {
    throw Error(path + ": not a urdfsnap results file (expected \"format\": \"" + kFormat +
                "\", as `urdfsnap snapshot check --results` writes)");
  }
  const int version = in.Whole(root, "format_version", "", 0, kMaxInt);
  if (version != kResultsFormatVersion) {
    throw Error(path + ": results format version " + std::to_string(version) + "; this urdfsnap reads version " +
                std::to_string(kResultsFormatVersion));
  }
  RunResults results;
  results.urdfsnap_version = in.Text(root, "urdfsnap_version", "");
  const Json& suite = in.Member(root, "suite", "");
  results.suite.path = in.Text(suite, "path", "suite");
  results.suite.digest = in.Text(suite, "digest", "suite");
  results.suite.case_count = in.Whole(suite, "cases", "suite", 0, kMaxInt);
  const Json& shard = in.Member(root, "shard", "");
  const int count = in.Whole(shard, "count", "shard", 1, shard::kMaxShardCount);
  results.shard = shard::Shard{in.Whole(shard, "index", "shard", 1, count), count};
  results.shard_source = in.Text(shard, "source", "shard");
  const Json& report_dir = in.Member(root, "report_dir", "");
  if (!report_dir.is_null()) {
    // the images merge copies come from here: never from outside the results file's folder
    results.report_dir = ConfinePath(fs::path(path).parent_path().string(), in.Text(root, "report_dir", ""),
                                     path + ": report_dir");
  }
  const Json& cases = in.Member(root, "cases", "");
  if (!cases.is_array()) throw in.Bad("cases", "expected a list");
  results.cases.reserve(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    results.cases.push_back(ReadCase(in, cases[i], "cases[" + std::to_string(i) + "]"));
  }
  return results;
}

}  // namespace urdfsnap::snapshot
