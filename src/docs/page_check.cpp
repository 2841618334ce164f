// ComparePages: both folders listed, then each file compared by its kind.
#include "docs/page_check.h"

#include <algorithm>
#include <set>

#include "common/confined_path.h"
#include "common/error.h"
#include "common/file_reading.h"
#include "common/number_text.h"
#include "image/png_reader.h"
#include "video/animation_reader.h"

namespace urdfsnap::docs {

namespace fs = std::filesystem;

namespace {

// The files below `folder`, as sorted relative paths with '/'. Each must be a regular file inside
// the folder (a link may point to one): a committed page is input, and a pipe in it would block
// the comparison, a link out of it would read another file. Throws urdfsnap::Error otherwise.
std::set<std::string> Listing(const fs::path& folder) {
  std::set<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_directory() && !entry.is_symlink()) continue;
    const std::string file = entry.path().lexically_relative(folder).generic_string();
    ConfineRegularFile(folder.string(), file, folder.string() + ": the page's file '" + file + "'");
    files.insert(file);
  }
  return files;
}

std::string Bytes(const fs::path& path) {
  try {
    return ReadFileBounded(path.string(), image::kMaxPngFileBytes);
  } catch (const FileReadError& e) {
    throw Error(path.string() + ": cannot read: " + e.what());
  }
}

// The part of a line around `column` (where it differs from the other side), quoted: at most 30
// bytes before and 60 after, with "..." where it is cut.
std::string Excerpt(const std::string& line, size_t column) {
  // cuts move to the start of a UTF-8 character
  const auto boundary = [&](size_t at) {
    while (at > 0 && at < line.size() && (static_cast<unsigned char>(line[at]) & 0xC0) == 0x80) --at;
    return std::min(at, line.size());
  };
  const size_t from = boundary(column > 30 ? column - 30 : 0), to = boundary(column + 60);
  std::string text = from > 0 ? "'..." : "'";
  text.append(line, from, to - from);
  text += to < line.size() ? "...'" : "'";
  return text;
}

// "" when the texts are equal, else where they first differ.
std::string TextDifference(const std::string& committed, const std::string& fresh) {
  if (committed == fresh) return "";
  size_t start = 0;
  int line = 1;
  while (true) {
    const size_t a = committed.find('\n', start), b = fresh.find('\n', start);
    const std::string left = committed.substr(start, a == std::string::npos ? std::string::npos : a - start);
    const std::string right = fresh.substr(start, b == std::string::npos ? std::string::npos : b - start);
    if (left != right || a != b || a == std::string::npos) {
      const size_t column = std::mismatch(left.begin(), left.end(), right.begin(), right.end()).first - left.begin();
      return "line " + std::to_string(line) + " differs: committed " + Excerpt(left, column) + ", now " +
             Excerpt(right, column);
    }
    start = a + 1;
    ++line;
  }
}

// "" when the pictures match within `tolerance`.
std::string PictureDifference(const fs::path& committed, const fs::path& fresh, const image::DiffTolerance& tolerance) {
  const image::Image expected = image::ReadPng(committed.string());
  const image::Image actual = image::ReadPng(fresh.string());
  if (expected.width != actual.width || expected.height != actual.height) {
    return "size " + image::SizeText(expected) + ", now " + image::SizeText(actual);
  }
  const image::DiffStats stats = image::CompareImages(expected, actual, tolerance.max_delta);
  return image::WithinTolerance(stats, tolerance) ? "" : image::DescribeDiff(stats, tolerance);
}

// "" when the animations have the same frames, each shown as long, and every frame matches within
// kAnimationTolerance.
std::string AnimationDifference(const fs::path& committed, const fs::path& fresh) {
  const auto expected = video::OpenAnimationReader(committed.string());
  const auto actual = video::OpenAnimationReader(fresh.string());
  image::Image old_frame, new_frame;
  double old_end = 0, new_end = 0;
  for (int k = 0;; ++k) {
    const bool has_old = expected->Next(old_frame, old_end), has_new = actual->Next(new_frame, new_end);
    if (!has_old || !has_new) {
      if (has_old == has_new) return "";
      // count the longer one's frames to the end
      int old_count = k + has_old, new_count = k + has_new;
      while (has_old && expected->Next(old_frame, old_end)) ++old_count;
      while (has_new && actual->Next(new_frame, new_end)) ++new_count;
      return std::to_string(old_count) + " frames, now " + std::to_string(new_count);
    }
    const std::string frame = "frame " + std::to_string(k) + ": ";
    if (old_frame.width != new_frame.width || old_frame.height != new_frame.height) {
      return frame + "size " + image::SizeText(old_frame) + ", now " + image::SizeText(new_frame);
    }
    if (old_end != new_end) {
      return frame + "shown until " + FormatNumber(old_end) + " ms, now " + FormatNumber(new_end) + " ms";
    }
    const image::DiffStats stats = image::CompareImages(old_frame, new_frame, kAnimationTolerance.max_delta);
    if (!image::WithinTolerance(stats, kAnimationTolerance)) {
      return frame + image::DescribeDiff(stats, kAnimationTolerance);
    }
  }
}

std::string Difference(const fs::path& committed, const fs::path& fresh, const image::DiffTolerance& tolerance) {
  const std::string extension = committed.extension().string();
  if (extension == ".png") return PictureDifference(committed, fresh, tolerance);
  if (extension == ".gif" || extension == ".webp") return AnimationDifference(committed, fresh);
  if (extension == ".md" || extension == ".html") return TextDifference(Bytes(committed), Bytes(fresh));
  return Bytes(committed) == Bytes(fresh) ? "" : "the bytes differ";
}

}  // namespace

std::vector<std::string> ComparePages(const fs::path& committed, const fs::path& fresh,
                                      const image::DiffTolerance& tolerance) {
  const std::set<std::string> old_files = Listing(committed), new_files = Listing(fresh);
  std::set<std::string> all = old_files;
  all.insert(new_files.begin(), new_files.end());
  std::vector<std::string> differences;
  for (const std::string& file : all) {
    if (!old_files.count(file)) {
      differences.push_back(file + ": missing from the committed page");
    } else if (!new_files.count(file)) {
      differences.push_back(file + ": not in a fresh page");
    } else {
      std::string difference;
      try {
        difference = Difference(committed / file, fresh / file, tolerance);
      } catch (const Error& e) {
        difference = e.what();   // a committed file that does not decode is a difference too
      }
      if (!difference.empty()) differences.push_back(file + ": " + difference);
    }
  }
  return differences;
}

}  // namespace urdfsnap::docs
