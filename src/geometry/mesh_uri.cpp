// Mesh URI resolution. RViz hands every URI to resource_retriever, which knows package:// and
// passes the rest to libcurl (so file:///abs works and plain paths fail); urdfsnap also accepts
// plain paths, relative ones against the model file's folder, because it reads the URDF from a
// file.
#include "geometry/mesh_uri.h"

#include <filesystem>
#include <system_error>

#include "common/error.h"
#include "common/package_finder.h"

namespace urdfsnap::geometry {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kPackageScheme = "package://";
constexpr std::string_view kFileScheme = "file://";

std::string Existing(const fs::path& file, const std::string& uri, const std::string& searched) {
  std::error_code ec;
  if (fs::is_regular_file(file, ec)) return fs::absolute(file, ec).lexically_normal().string();
  // a folder, a device such as /dev/zero or a pipe is no mesh (and could be read forever)
  if (fs::exists(file, ec)) {
    throw Error("mesh '" + uri + "': " + file.string() + " is not a regular file");
  }
  throw Error("mesh '" + uri + "' not found, searched: " + searched);
}

}  // namespace

std::string ResolveMeshUri(const std::string& uri, const std::string& model_file,
                           const std::map<std::string, std::string>& packages) {
  if (uri.starts_with(kPackageScheme)) {
    const std::string rest = uri.substr(kPackageScheme.size());
    const size_t slash = rest.find('/');
    if (slash == 0 || slash == std::string::npos || slash + 1 == rest.size()) {
      throw Error("mesh '" + uri + "': expected package://PACKAGE/PATH");
    }
    const std::string name = rest.substr(0, slash);
    std::string dir;
    try {
      dir = FindPackage(name, PackageSearch{packages, model_file});
    } catch (const Error& e) {
      throw Error("mesh '" + uri + "' not found: " + e.what());
    }
    const fs::path file = fs::path(dir) / rest.substr(slash + 1);
    return Existing(file, uri, file.string() + " (package '" + name + "' is " + dir + ")");
  }
  if (uri.starts_with(kFileScheme)) {
    const std::string path = uri.substr(kFileScheme.size());
    if (!path.starts_with('/')) {
      throw Error("mesh '" + uri + "': expected file:///ABSOLUTE/PATH");
    }
    return Existing(path, uri, path);
  }
  if (const size_t scheme = uri.find("://"); scheme != std::string::npos) {
    throw Error("mesh '" + uri + "': unsupported URI scheme '" + uri.substr(0, scheme) +
                "://' (expected package:// or file://)");
  }
  const fs::path path(uri);
  const fs::path file =
      path.is_absolute() || model_file.empty() ? path : fs::path(model_file).parent_path() / path;
  return Existing(file, uri, fs::absolute(file).lexically_normal().string());
}

bool IsPlainPath(const std::string& uri) { return uri.find("://") == std::string::npos; }

}  // namespace urdfsnap::geometry
