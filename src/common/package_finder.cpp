// ROS package lookup without ROS: explicit folders, ROS_PACKAGE_PATH crawl, ament prefixes and
// the folders around the input file.
#include "common/package_finder.h"

#include <tinyxml2.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <system_error>
#include <vector>

#include "common/error.h"

namespace urdfsnap {

namespace fs = std::filesystem;

std::string PackageXmlName(const std::string& path) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) return {};
  const tinyxml2::XMLElement* root = doc.RootElement();
  const tinyxml2::XMLElement* name = root ? root->FirstChildElement("name") : nullptr;
  if (!name || !name->GetText()) return {};
  std::string text = name->GetText();
  const size_t b = text.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return text.substr(b, text.find_last_not_of(" \t\r\n") - b + 1);
}

namespace {

constexpr int kMaxCrawlDepth = 8;

std::vector<std::string> SplitPath(const char* value) {
  std::vector<std::string> parts;
  if (!value) return parts;
  std::stringstream in(value);
  std::string part;
  while (std::getline(in, part, ':')) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

bool Names(const fs::path& dir, const std::string& name) {
  std::error_code ec;
  const fs::path xml = dir / "package.xml";
  return fs::is_regular_file(xml, ec) && PackageXmlName(xml.string()) == name;
}

// rospack's crawl: a folder holding package.xml is a package and is not descended into
std::string Crawl(const fs::path& dir, const std::string& name, int depth) {
  std::error_code ec;
  if (fs::is_regular_file(dir / "package.xml", ec)) return Names(dir, name) ? dir.string() : std::string();
  if (depth >= kMaxCrawlDepth || fs::exists(dir / "CATKIN_IGNORE", ec) || fs::exists(dir / "COLCON_IGNORE", ec)) return {};
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string leaf = it->path().filename().string();
    if (leaf.empty() || leaf[0] == '.' || !it->is_directory(ec)) continue;
    std::string found = Crawl(it->path(), name, depth + 1);
    if (!found.empty()) return found;
  }
  return {};
}

std::string Absolute(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p, ec).lexically_normal();
  std::string s = a.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

}  // namespace

std::string FindPackage(const std::string& name, const PackageSearch& search) {
  std::vector<std::string> searched;
  std::error_code ec;
  if (auto it = search.explicit_dirs.find(name); it != search.explicit_dirs.end()) {
    if (fs::is_directory(it->second, ec)) return Absolute(it->second);
    searched.push_back("--package " + name + "=" + it->second + " (not a folder)");
  }
  for (const std::string& root : SplitPath(std::getenv("ROS_PACKAGE_PATH"))) {
    searched.push_back(root);
    std::string found = Crawl(root, name, 0);
    if (!found.empty()) return Absolute(found);
  }
  for (const std::string& prefix : SplitPath(std::getenv("AMENT_PREFIX_PATH"))) {
    const fs::path share = fs::path(prefix) / "share" / name;
    searched.push_back(share.string());
    if (fs::exists(fs::path(prefix) / "share/ament_index/resource_index/packages" / name, ec) ||
        fs::is_regular_file(share / "package.xml", ec)) {
      return Absolute(share);
    }
  }
  if (!search.near_file.empty()) {
    fs::path dir = fs::path(Absolute(search.near_file)).parent_path();
    fs::path package_root;
    for (fs::path d = dir; !d.empty(); d = d.parent_path()) {
      if (Names(d, name)) return Absolute(d);
      if (package_root.empty() && fs::is_regular_file(d / "package.xml", ec)) package_root = d;
      if (d == d.parent_path()) break;
    }
    searched.push_back("the folders above " + search.near_file);
    if (!package_root.empty()) {
      const fs::path parent = package_root.parent_path();
      searched.push_back("the siblings of " + package_root.string());
      for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_directory(ec) && Names(it->path(), name)) return Absolute(it->path());
      }
    }
  }
  std::string where;
  for (const std::string& s : searched) where += (where.empty() ? "" : ", ") + s;
  throw Error("package '" + name + "' not found, searched: " + (where.empty() ? "nothing (no --package, ROS_PACKAGE_PATH or AMENT_PREFIX_PATH)" : where));
}

}  // namespace urdfsnap
