// The bounds the live view's server puts on each connection, against clients that connect and
// send nothing, or send a request a byte at a time, or headers without end (a slowloris), or do not
// take their responses: so that such clients cannot take every connection thread, and the server
// keeps answering the others.
#pragma once

#include <chrono>
#include <cstddef>

namespace urdfsnap::serve {

// Connections that wait for a request: past either limit, the one that has waited longest is
// closed (see ClientConnections).
struct ConnectionLimits {
  std::size_t per_client = 8;  // of one client address (a browser opens about 6 to one server)
  std::size_t total = 24;      // of all clients; fewer than the server's connection threads
};

// One request and one response on a connection (see DeadlineStream).
struct StreamLimits {
  std::chrono::milliseconds request_time{5000};    // to send one whole request, idle time included
  std::size_t request_bytes = 64 * 1024;           // of one request: line, headers and body
  std::chrono::milliseconds response_time{30000};  // for the client to take one whole response
};

}  // namespace urdfsnap::serve
