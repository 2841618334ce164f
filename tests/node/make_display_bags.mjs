// Writes displays_moving.mcap, the bag of urdfsnap's animated-display tests, with the MCAP project's
// own writer and Foxglove's ROS 2 CDR serialiser: 3 s (or SECONDS) of the mrm arm turning its first joint
// (/joint_states at 30 Hz) while /tf drives odom -> base_link forward, a 10 Hz PointCloud2 ring in
// the lidar frame (/cloud, POINTS points), a 2 Hz nav_msgs/Path, and a MarkerArray (/markers): a
// sphere every 0.5 s living 0.6 s, a cube frame_locked to link_05, a DELETEALL at 2.5 s, and at
// 1.5 s a line strip that claims 10^8 points over the bytes of two (a hostile message).
// usage: node make_display_bags.mjs OUT_DIR [POINTS [SECONDS [NAME]]]   (2000 points, 3 s, displays_moving.mcap:
// the tests'; the memory test asks for 10 s and 60 s; bench/animate/display_bag_bench.sh asks for a lidar's size and a
// longer recording)
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { ros2humble } from "@foxglove/rosmsg-msgs-common";
import { MessageWriter } from "@foxglove/rosmsg2-serialization";
import { nanos, writeBag } from "./bag_writing.mjs";
import { kSeparator } from "./ros2_schemas.mjs";

const out = process.argv[2];
if (!out) throw new Error("usage: node make_display_bags.mjs OUT_DIR [POINTS [SECONDS [NAME]]]");
const cloudPoints = Number(process.argv[3] ?? 2000);
const seconds = Number(process.argv[4] ?? 3);
const name = process.argv[5] ?? "displays_moving.mcap";
mkdirSync(out, { recursive: true });

// ROS 1 style time primitives of the definitions package, as ROS 2 names them
const kBuiltin = { time: "builtin_interfaces/Time", duration: "builtin_interfaces/Duration" };
const kStampText = "int32 sec\nuint32 nanosec\n";

// The .msg text of `name` (pkg/Type) from Foxglove's parsed ROS 2 Humble definitions.
function msgText(name) {
  if (Object.values(kBuiltin).includes(name)) return kStampText;
  return ros2humble[name].definitions
    .map((f) => {
      if (f.isConstant) return `${f.type} ${f.name}=${f.valueText}`;
      const array = f.isArray ? `[${f.arrayLength ?? ""}]` : "";
      return `${kBuiltin[f.type] ?? f.type}${array} ${f.name}`;
    })
    .join("\n") + "\n";
}
// The types `name` uses, directly or not, in the order met.
function dependencies(name, seen = new Set()) {
  if (!ros2humble[name]) return seen;
  for (const f of ros2humble[name].definitions) {
    const type = kBuiltin[f.type] ?? f.type;
    if (f.isConstant || seen.has(type) || !(f.isComplex || kBuiltin[f.type])) continue;
    seen.add(type);
    dependencies(type, seen);
  }
  return seen;
}
// The ros2msg schema text rosbag2 stores for `type` ("pkg/msg/Type"): its own text, then each type
// it uses after a separator line and "MSG: pkg/Type".
function schemaText(type) {
  const name = type.replace("/msg/", "/");
  return [msgText(name), ...[...dependencies(name)].map((d) => `${kSeparator}\nMSG: ${d}\n${msgText(d)}`)].join("");
}
const types = ["std_msgs/msg/String", "sensor_msgs/msg/JointState", "tf2_msgs/msg/TFMessage",
               "sensor_msgs/msg/PointCloud2", "nav_msgs/msg/Path", "visualization_msgs/msg/MarkerArray"];
const writers = {};
for (const type of types) {
  const name = type.replace("/msg/", "/");
  writers[type] = new MessageWriter([ros2humble[name], ...[...dependencies(name)].filter((d) => ros2humble[d]).map((d) => ros2humble[d])]);
}
const topics = [["/robot_description", types[0]], ["/joint_states", types[1]], ["/tf_static", types[2]], ["/tf", types[2]],
                ["/cloud", types[3]], ["/path", types[4]], ["/markers", types[5]]];
const channels = topics.map(([topic, type]) =>
  ({ topic, type, schema: { name: type, encoding: "ros2msg", data: new TextEncoder().encode(schemaText(type)) } }));
const channelOf = Object.fromEntries(topics.map(([topic], i) => [topic, i]));

const kStart = 1;   // the first message's stamp, seconds
const stampAt = (t) => ({ sec: Math.floor(kStart + t + 1e-9), nanosec: Math.round(((kStart + t) % 1) * 1e9) % 1_000_000_000 });
const header = (frame_id, t) => ({ stamp: stampAt(t), frame_id });
const messages = [];
const add = (topic, t, type, message) => messages.push([channelOf[topic], nanos(stampAt(t)), writers[type].writeMessage(message)]);

const mrmUrdf = readFileSync(join(dirname(fileURLToPath(import.meta.url)), "../../models/mrm_description/urdf/mrm.urdf"), "utf8");
const kJoints = ["base_link__link_01", "link_01__link_02", "link_02__link_03", "link_03__link_04", "link_04__link_05"];
const transform = (parent, child, t, x, y, z, yaw = 0) => ({
  header: header(parent, t), child_frame_id: child,
  transform: { translation: { x, y, z }, rotation: { x: 0, y: 0, z: Math.sin(yaw / 2), w: Math.cos(yaw / 2) } },
});
add("/robot_description", 0, types[0], { data: mrmUrdf });
add("/tf_static", 0, types[2], { transforms: [transform("base_link", "lidar", 0, 0, 0, 0.4)] });

const white = { r: 1, g: 1, b: 1, a: 1 };
const marker = (t, fields) => ({
  header: header("base_link", t), ns: "", id: 0, type: 2, action: 0,
  pose: { position: { x: 0, y: 0, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
  scale: { x: 0.3, y: 0.3, z: 0.3 }, color: white, lifetime: { sec: 0, nanosec: 0 }, frame_locked: false,
  points: [], colors: [], texture_resource: "", texture: { header: header("", 0), format: "", data: new Uint8Array() },
  uv_coordinates: [], text: "", mesh_resource: "", mesh_file: { filename: "", data: new Uint8Array() },
  mesh_use_embedded_materials: false, ...fields,
});
// a MarkerArray whose one LINE_STRIP's points count says 10^8 over the bytes of its two points
function hostileMarkers(t) {
  const kTell = 12345.5;   // the first point's x, found in the bytes to find the count before it
  const bytes = writers[types[5]].writeMessage({ markers: [marker(t, {
    ns: "liar", type: 4, scale: { x: 0.05, y: 0, z: 0 }, points: [{ x: kTell, y: 0, z: 0 }, { x: 0, y: 0, z: 1 }] })] });
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let at = 8; at + 8 <= bytes.byteLength; at += 4) {
    if (view.getFloat64(at, true) !== kTell) continue;
    const count = view.getUint32(at - 4, true) === 2 ? at - 4 : at - 8;
    if (view.getUint32(count, true) !== 2) throw new Error("the line strip's point count was not found");
    view.setUint32(count, 100_000_000, true);
    return bytes;
  }
  throw new Error("the line strip's first point was not found");
}

for (let k = 0; k <= 30 * seconds; ++k) {   // 30 Hz joints, 10 Hz base
  const t = k / 30;
  add("/joint_states", t, types[1], { header: header("", t), name: kJoints, position: kJoints.map((_, j) => (j === 0 ? t : 0.3 * Math.sin(t))), velocity: [], effort: [] });
  if (k % 3 === 0) add("/tf", t, types[2], { transforms: [transform("odom", "base_link", t, 0.4 * t, 0, 0, 0.2 * t)] });
  if (k % 3 === 0) {   // the 10 Hz cloud: a ring 2 m around the lidar, turning
    const step = 16;
    const data = new Uint8Array(cloudPoints * step);
    const view = new DataView(data.buffer);
    for (let i = 0; i < cloudPoints; ++i) {
      const a = (2 * Math.PI * i) / cloudPoints + t;
      [2 * Math.cos(a), 2 * Math.sin(a), 0.3 * Math.sin(5 * a), i % 256].forEach((v, f) => view.setFloat32(i * step + 4 * f, v, true));
    }
    add("/cloud", t, types[3], {
      header: header("lidar", t), height: 1, width: cloudPoints,
      fields: ["x", "y", "z", "intensity"].map((name, f) => ({ name, offset: 4 * f, datatype: 7, count: 1 })),
      is_bigendian: false, point_step: step, row_step: step * cloudPoints, data, is_dense: true,
    });
  }
  if (k % 15 === 0) {   // 2 Hz: a path from the base ahead of it, curving with time
    const poses = Array.from({ length: 20 }, (_, i) => ({ header: header("base_link", t), pose: {
      position: { x: 0.1 * i, y: 0.5 * Math.sin(0.2 * i + t), z: 0.05 }, orientation: { x: 0, y: 0, z: 0, w: 1 } } }));
    add("/path", t, types[4], { header: header("base_link", t), poses });
    const markers = [marker(t, { ns: "trail", id: k, pose: { position: { x: 1, y: -1 + 0.25 * (k / 15), z: 0.2 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
                                 color: { r: 1, g: 0.5, b: 0, a: 1 }, lifetime: { sec: 0, nanosec: 600_000_000 } })];
    if (k === 15) {
      markers.push(marker(t, { header: header("link_05", t), ns: "tool", type: 1, frame_locked: true,
                               pose: { position: { x: 0, y: 0, z: 0.3 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
                               scale: { x: 0.25, y: 0.25, z: 0.25 }, color: { r: 0, g: 0.8, b: 1, a: 1 } }));
    }
    if (k === 75) markers.unshift(marker(t, { action: 3 }));   // DELETEALL, then the new trail sphere
    add("/markers", t, types[5], { markers });
  }
  if (k === 45) messages.push([channelOf["/markers"], nanos(stampAt(t)) + 1n, hostileMarkers(t)]);
}
writeFileSync(join(out, name), await writeBag({ channels, messages, chunkSize: 1 << 20 }));
