// `GET /render.png?...` in `urdfsnap render`'s words: each query key is one of render's option
// names (yaw=0.5, size=800x600, no-grid, tf=true, ...) or j.NAME=VALUE for a joint, applied to the
// server's own request (the model and the options `urdfsnap serve` was started with).
#pragma once

#include <map>
#include <string>

#include "request/render_request.h"

namespace urdfsnap::serve {

// A URL's query, decoded and sorted by key (httplib::Params is this type).
using Query = std::multimap<std::string, std::string>;

// `base` with the query's options applied: a text option's value replaces base's; a flag takes
// "true", "1" or no value to switch it on and "false" or "0" to switch it off; j.NAME=VALUE adds a
// joint value as `render -j NAME=VALUE` does. Throws urdfsnap::Error with the message `render`
// prints for the same value ("--yaw 'x': expected a finite number"), and for unknown or repeated
// keys, empty values and `rviz` (a file path: the server reads no file a URL names).
request::RenderRequest RequestFromQuery(const Query& query, const request::RenderRequest& base);

}  // namespace urdfsnap::serve
