// Parsing JSON text (joint files, snapshot results files) into nlohmann_json's ordered values, with
// urdfsnap's located errors instead of the library's exceptions.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace urdfsnap {

// Parses `text`, the contents of the file `path`. Throws urdfsnap::Error "PATH:LINE: bad JSON: ..."
// for malformed JSON, and "PATH: bad JSON: ..." for a number beyond a double ("1e999").
nlohmann::ordered_json ParseJson(const std::string& text, const std::string& path);

// The 1-based line of byte `offset` in `text`.
int LineAt(const std::string& text, std::size_t offset);

}  // namespace urdfsnap
