// Query keys looked up in render's option table (request::TextOptions/FlagOptions).
#include "serve/query_request.h"

#include <string_view>

#include "common/error.h"
#include "request/settings_parsing.h"

namespace urdfsnap::serve {

namespace {

constexpr std::string_view kJointPrefix = "j.";

const request::TextOption* FindText(std::string_view key) {
  for (const auto& option : request::TextOptions()) {
    if (key == option.name) return &option;
  }
  return nullptr;
}

const request::FlagOption* FindFlag(std::string_view key) {
  for (const auto& option : request::FlagOptions()) {
    if (key == option.name) return &option;
  }
  return nullptr;
}

std::string KnownKeys() {
  std::string keys;
  for (const auto& option : request::TextOptions()) {
    if (!option.is_path) keys += std::string(option.name) + ", ";
  }
  for (const auto& option : request::FlagOptions()) keys += std::string(option.name) + ", ";
  return keys + "j.NAME";
}

bool FlagValue(const std::string& key, const std::string& value) {
  if (value.empty() || value == "true" || value == "1") return true;
  if (value == "false" || value == "0") return false;
  throw Error(request::CommandLineLabel(key) + " '" + value + "': expected true, false, 1, 0 or no value");
}

}  // namespace

request::RenderRequest RequestFromQuery(const Query& query, const request::RenderRequest& base) {
  request::RenderRequest r = base;
  for (auto it = query.begin(); it != query.end(); ++it) {
    const auto& [key, value] = *it;
    if (std::next(it) != query.end() && std::next(it)->first == key) {
      throw Error("'" + key + "' is given more than once");
    }
    if (key.starts_with(kJointPrefix)) {
      // the same words and messages as `render -j NAME=VALUE`
      model::ParseJointAssignment(key.substr(kJointPrefix.size()) + "=" + value, r.joints);
    } else if (const request::FlagOption* flag = FindFlag(key)) {
      r.*flag->field = FlagValue(key, value);
    } else if (const request::TextOption* text = FindText(key); text && !text->is_path) {
      if (value.empty()) throw Error(request::CommandLineLabel(key) + " needs a value (" + key + "=...)");
      r.*text->field = value;
    } else if (text) {
      throw Error(request::CommandLineLabel(key) + " names a file, which a URL cannot: start urdfsnap serve with " +
                  request::CommandLineLabel(key) + " FILE instead");
    } else {
      throw Error("unknown option '" + key + "'; the keys are render's options: " + KnownKeys());
    }
  }
  return r;
}

}  // namespace urdfsnap::serve
