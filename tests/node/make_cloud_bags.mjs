// Writes the MCAP bags of urdfsnap's point-cloud display tests with the MCAP project's own writer
// and Foxglove's ROS 2 CDR serialiser: the mrm arm (its description on /robot_description, zero
// joint states, /tf_static base_link -> lidar) with a PointCloud2 coloured by rgb (/cloud_rgb), one
// coloured by intensity (/cloud_intensity) and a LaserScan with intensities (/scan), all at
// t = 1 s, also as a rosbag2 SQLite file without definitions (clouds.db3, through write_db3.py);
// and a 10 Hz cloud for animations (clouds_10hz.mcap, POINTS points per message).
// usage: node make_cloud_bags.mjs OUT_DIR [POINTS]   (POINTS defaults to 2000)
import { execFileSync } from "node:child_process";
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { ros2humble } from "@foxglove/rosmsg-msgs-common";
import { MessageWriter } from "@foxglove/rosmsg2-serialization";
import { nanos, writeBag } from "./bag_writing.mjs";
import { kHeaderSections, kJointStateSchema, kSeparator, kStringSchema, kTfMessageSchema } from "./ros2_schemas.mjs";

const out = process.argv[2];
if (!out) throw new Error("usage: node make_cloud_bags.mjs OUT_DIR [POINTS]");
const animatedPoints = Number(process.argv[3] ?? 2000);
mkdirSync(out, { recursive: true });

// the schemas of the display messages, and the robot's from ros2_schemas.mjs
const schemas = {
  "sensor_msgs/msg/PointCloud2": `std_msgs/Header header
uint32 height
uint32 width
sensor_msgs/PointField[] fields
bool is_bigendian
uint32 point_step
uint32 row_step
uint8[] data
bool is_dense
${kHeaderSections}${kSeparator}
MSG: sensor_msgs/PointField
uint8 INT8=1
uint8 UINT8=2
uint8 INT16=3
uint8 UINT16=4
uint8 INT32=5
uint8 UINT32=6
uint8 FLOAT32=7
uint8 FLOAT64=8
string name
uint32 offset
uint8 datatype
uint32 count
`,
  "sensor_msgs/msg/LaserScan": `std_msgs/Header header
float32 angle_min
float32 angle_max
float32 angle_increment
float32 time_increment
float32 scan_time
float32 range_min
float32 range_max
float32[] ranges
float32[] intensities
${kHeaderSections}`,
  "std_msgs/msg/String": kStringSchema,
  "sensor_msgs/msg/JointState": kJointStateSchema,
  "tf2_msgs/msg/TFMessage": kTfMessageSchema,
};
const writers = {};
for (const type of Object.keys(schemas)) {
  const name = type.replace("/msg/", "/");
  const dependencies = Object.keys(ros2humble).filter((key) => schemas[type].includes(`MSG: ${key}\n`));
  writers[type] = new MessageWriter([ros2humble[name], ...dependencies.map((key) => ros2humble[key])]);
}
function channel(topic, type) {
  return { topic, type, schema: { name: type, encoding: "ros2msg", data: new TextEncoder().encode(schemas[type]) } };
}

const kStart = { sec: 1, nanosec: 0 };
const header = (frame_id, stamp = kStart) => ({ stamp, frame_id });
const kFloat32 = 7;

// A PointCloud2 of float32 fields `names`, one row, a point per entry of `points` (arrays of values).
function cloud(frame_id, names, points, stamp = kStart) {
  const step = 4 * names.length;
  const data = new Uint8Array(points.length * step);
  const view = new DataView(data.buffer);
  points.forEach((values, i) => values.forEach((v, f) => view.setFloat32(i * step + 4 * f, v, true)));
  return {
    header: header(frame_id, stamp),
    height: 1,
    width: points.length,
    fields: names.map((name, f) => ({ name, offset: 4 * f, datatype: kFloat32, count: 1 })),
    is_bigendian: false,
    point_step: step,
    row_step: step * points.length,
    data,
    is_dense: true,
  };
}
// the float whose bits are 0x00RRGGBB, as PCL packs rgb
function packedRgb(r, g, b) {
  const view = new DataView(new ArrayBuffer(4));
  view.setUint32(0, (r << 16) | (g << 8) | b, true);
  return view.getFloat32(0, true);
}

// a 1 m x 1 m wall of 20 x 20 points at x = 1.5 m in front of the arm, red to the left, blue up
const rgbPoints = [];
for (let i = 0; i < 20; ++i) {
  for (let j = 0; j < 20; ++j) rgbPoints.push([1.5, -0.5 + i / 19, 0.2 + j / 19, packedRgb(255 - 12 * i, 80, 12 * j)]);
}
// a ring of radius 1.2 m on the floor, intensity growing with the angle
const intensityPoints = [];
for (let k = 0; k < 360; ++k) {
  const a = (k * Math.PI) / 180;
  intensityPoints.push([1.2 * Math.cos(a), 1.2 * Math.sin(a), 0.05, k]);
}
const mrmUrdf = readFileSync(join(dirname(fileURLToPath(import.meta.url)), "../../models/mrm_description/urdf/mrm.urdf"), "utf8");
const kJoints = ["base_link__link_01", "link_01__link_02", "link_02__link_03", "link_03__link_04", "link_04__link_05"];
const robotChannels = [
  channel("/robot_description", "std_msgs/msg/String"),
  channel("/joint_states", "sensor_msgs/msg/JointState"),
  channel("/tf_static", "tf2_msgs/msg/TFMessage"),
];
const robotMessages = (time) => [
  [0, time, writers["std_msgs/msg/String"].writeMessage({ data: mrmUrdf })],
  [1, time, writers["sensor_msgs/msg/JointState"].writeMessage({ header: header(""), name: kJoints, position: kJoints.map(() => 0), velocity: [], effort: [] })],
  [2, time, writers["tf2_msgs/msg/TFMessage"].writeMessage({
    transforms: [{ header: header("base_link"), child_frame_id: "lidar",
                   transform: { translation: { x: 0, y: 0, z: 0.4 }, rotation: { x: 0, y: 0, z: 0, w: 1 } } }],
  })],
];
async function write(name, channels, messages) {
  writeFileSync(join(out, name), await writeBag({ channels, messages, chunkSize: 1 << 20 }));
}

const t1 = nanos(kStart);
const scan = {
  header: header("lidar"),
  angle_min: -Math.PI / 2, angle_max: Math.PI / 2, angle_increment: Math.PI / 180,
  time_increment: 0, scan_time: 0.1, range_min: 0.1, range_max: 10,
  ranges: Array.from({ length: 181 }, (_, i) => (i % 30 === 0 ? Infinity : 1 + 0.5 * Math.sin(i / 10))),
  intensities: Array.from({ length: 181 }, (_, i) => i),
};
const cloudChannels = [...robotChannels, channel("/cloud_rgb", "sensor_msgs/msg/PointCloud2"),
  channel("/cloud_intensity", "sensor_msgs/msg/PointCloud2"), channel("/scan", "sensor_msgs/msg/LaserScan")];
const cloudMessages = [...robotMessages(t1),
  [3, t1, writers["sensor_msgs/msg/PointCloud2"].writeMessage(cloud("base_link", ["x", "y", "z", "rgb"], rgbPoints))],
  [4, t1, writers["sensor_msgs/msg/PointCloud2"].writeMessage(cloud("base_link", ["x", "y", "z", "intensity"], intensityPoints))],
  [5, t1, writers["sensor_msgs/msg/LaserScan"].writeMessage(scan)]];
await write("clouds.mcap", cloudChannels, cloudMessages);
// the same messages as rosbag2's SQLite storage before Jazzy writes them: type names, no definitions
const db3Spec = join(out, "clouds_db3.json");
writeFileSync(db3Spec, JSON.stringify([{
  file: join(out, "clouds.db3"),
  topics: cloudChannels.map(({ topic, type }, i) => [i + 1, topic, type, "cdr"]),
  messages: cloudMessages.map(([c, time, data]) => [c + 1, Number(time), Buffer.from(data).toString("hex")]),
}]));
execFileSync("python3", [join(dirname(fileURLToPath(import.meta.url)), "write_db3.py"), db3Spec]);

// a cloud that lies: 10^8 points claimed over 16 bytes of data
const liar = { ...cloud("base_link", ["x", "y", "z", "rgb"], [[0, 0, 0, 0]]), width: 100_000_000 };
await write("cloud_lies.mcap", [...robotChannels, channel("/cloud_rgb", "sensor_msgs/msg/PointCloud2")],
  [...robotMessages(t1), [3, t1, writers["sensor_msgs/msg/PointCloud2"].writeMessage(liar)]]);

// 3 s of a 10 Hz cloud in the lidar frame: a spinning ring of `animatedPoints` points
const animated = [...robotMessages(t1)];
for (let f = 0; f < 30; ++f) {
  const stamp = { sec: 1 + Math.floor(f / 10), nanosec: (f % 10) * 100_000_000 };
  const points = [];
  for (let k = 0; k < animatedPoints; ++k) {
    const a = (2 * Math.PI * k) / animatedPoints + f * 0.1;
    points.push([2 * Math.cos(a), 2 * Math.sin(a), 0.3 * Math.sin(5 * a), k % 256]);
  }
  animated.push([3, nanos(stamp), writers["sensor_msgs/msg/PointCloud2"].writeMessage(cloud("lidar", ["x", "y", "z", "intensity"], points, stamp))]);
}
await write("clouds_10hz.mcap", [...robotChannels, channel("/cloud", "sensor_msgs/msg/PointCloud2")], animated);
