// Message files: a message as `ros2 topic echo` prints it (YAML, field by field, nested messages
// as maps, arrays as lists; several messages separated by "---", of which the last counts, as a
// display keeps the latest), read into the same bag::MessageValue tree a bag's CDR decodes into,
// so that the displays draw it without a bag. Fields left out take ROS's defaults (0, "", empty).
#pragma once

#include <memory>
#include <string>

#include "bag/cdr_message.h"

namespace urdfsnap::display {

struct MessageFile {
  std::shared_ptr<const bag::MessageSchema> schema;   // the definition `value` points into
  bag::MessageValue value;
};

// Reads the last message of the file at `path` as a `type` ("pkg/msg/Type") by the definition
// urdfsnap ships. Throws urdfsnap::Error "PATH:LINE: ..." for an unreadable file, bad YAML, a key
// that is no field of its message, a value of the wrong kind, and for a type urdfsnap ships no
// definition of.
MessageFile ReadMessageFile(const std::string& path, const std::string& type);

}  // namespace urdfsnap::display
