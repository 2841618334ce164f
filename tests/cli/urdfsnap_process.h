// Running the urdfsnap binary from a test as a user's shell would: a command line, its exit
// status and output, a deadline that kills a hung run, and the peak memory it used.
#pragma once

#include <string>

namespace urdfsnap::test {

struct ProcessResult {
  int status = -1;        // exit status; -1 when killed by a signal or the deadline
  bool timed_out = false;
  std::string out;        // stdout
  std::string err;        // stderr
  long peak_rss_kb = 0;   // the process's largest resident set
};

// Runs `/bin/sh -c "exec URDFSNAP ARGUMENTS"` (so shell quoting and redirections work) with stdin
// from /dev/null and kills it after `deadline_seconds`. `address_space_limit_mb` > 0 caps its
// virtual memory (RLIMIT_AS), turning runaway allocations into failures; sanitizer builds need
// terabytes of address space, so callers pass 0 there.
ProcessResult RunUrdfsnap(const std::string& arguments, int deadline_seconds = 120,
                          long address_space_limit_mb = 0);

// True when this test binary (and so urdfsnap, built alike) has AddressSanitizer.
bool BuiltWithAddressSanitizer();

}  // namespace urdfsnap::test
