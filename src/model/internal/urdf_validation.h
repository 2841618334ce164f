// Checks a URDF document for the mistakes urdfdom rejects without saying where (and a few it
// lets through), so that each one is reported with its file, line and the element's name.
#pragma once

#include <string>

#include <tinyxml2.h>

namespace urdfsnap::model {

// Checks the <robot> element `robot` of a document read from `source`: names of links and joints
// present and unique, known joint types, parent and child links that exist, one root and no
// loops, <limit> on revolute and prismatic joints with lower <= upper, numbers where URDF wants
// numbers, non-zero axes, mimic joints that follow an existing joint and no circle of them.
// Throws Error "source:line: ..." for the first problem found.
void ValidateUrdfDocument(const tinyxml2::XMLElement& robot, const std::string& source);

}  // namespace urdfsnap::model
