// The ros2msg schema texts the test bags carry, as rosbag2 stores them: the type's .msg text, then
// each type it uses after a line of '=' and "MSG: pkg/Name". Shared by make_test_bags.mjs and
// make_cloud_bags.mjs.
export const kSeparator = "=".repeat(80);
export const kHeaderSections = `${kSeparator}
MSG: std_msgs/Header
builtin_interfaces/Time stamp
string frame_id
${kSeparator}
MSG: builtin_interfaces/Time
int32 sec
uint32 nanosec
`;
export const kJointStateSchema = `std_msgs/Header header
string[] name
float64[] position
float64[] velocity
float64[] effort
${kHeaderSections}`;

export const kTfMessageSchema = `geometry_msgs/TransformStamped[] transforms
${kSeparator}
MSG: geometry_msgs/TransformStamped
std_msgs/Header header
string child_frame_id
Transform transform
${kHeaderSections}${kSeparator}
MSG: geometry_msgs/Transform
Vector3 translation
Quaternion rotation
${kSeparator}
MSG: geometry_msgs/Vector3
float64 x
float64 y
float64 z
${kSeparator}
MSG: geometry_msgs/Quaternion
float64 x 0
float64 y 0
float64 z 0
float64 w 1
`;
export const kStringSchema = "string data\n";
