// The MODEL argument's words: NAME:=VALUE xacro arguments and PKG=DIR package folders.
#include "cli/model_source.h"

#include "common/error.h"

namespace urdfsnap::cli {

void ModelSource::AddOptions(CLI::App& command, bool optional) {
  command.add_option("MODEL", path, "URDF or xacro file")->required(!optional);
  command.add_option("NAME:=VALUE", xacro_words, "xacro arguments, as for ROS's xacro");
  command.add_option("--package", packages,
                     "where $(find PKG) and package://PKG point (PKG=DIR, repeatable)");
  command.add_flag("--xacro-ns", xacro_ns,
                   "modern xacro's strict rule: only xacro:-prefixed tags are macro calls");
}

request::ModelRequest ModelSource::ToRequest() const {
  request::ModelRequest request{path, {}, {}, xacro_ns};
  // words that look like NAME:=VALUE are xacro arguments; anything else is a usage error
  for (const auto& word : xacro_words) {
    const auto at = word.find(":=");
    if (at == std::string::npos || at == 0) {
      throw Error("unexpected argument '" + word + "' (xacro arguments are written NAME:=VALUE)");
    }
    request.xacro_args.emplace_back(word.substr(0, at), word.substr(at + 2));
  }
  for (const auto& word : packages) {
    const auto at = word.find('=');
    if (at == std::string::npos || at == 0) {
      throw Error("--package '" + word + "': expected PKG=DIR");
    }
    request.packages[word.substr(0, at)] = word.substr(at + 1);
  }
  return request;
}

}  // namespace urdfsnap::cli
