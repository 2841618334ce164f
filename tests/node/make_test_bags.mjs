// Writes the MCAP bags urdfsnap's tests read, with the MCAP project's own TypeScript writer
// (@mcap/core) and Foxglove's ROS 2 CDR serialiser, so that urdfsnap's reader is checked against
// implementations it shares no code with; rosbag2 folders (split, SQLite through write_db3.py,
// zstd-compressed per file or per message). Also writes corrupt and truncated variants.
// usage: node make_test_bags.mjs OUT_DIR [--large] [--seeds SEED_DIR]
//   --large: also a ~350 MB bag for benchmarks; --seeds: also tiny bags (a few messages, one with
//   its chunk CRC zeroed so that mutations inside the chunk get past the check) as fuzz seeds, e.g.
//   into tests/fuzz/mcap_reader/
//
// Every JointState bag carries message i (i = 0, 1, ...) with header.stamp = 1700000000 s + i * 10 ms,
// log time = stamp + 1 ms, and positions shoulder = 0.01 i, elbow = -0.02 i, wrist = 0.5 (the C++
// tests recompute these).
import { execFileSync } from "node:child_process";
import zlib from "node:zlib";
import { mkdirSync, writeFileSync, readFileSync, rmSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { CdrWriter, EncapsulationKind } from "@foxglove/cdr";
import { ros2humble } from "@foxglove/rosmsg-msgs-common";
import { MessageWriter } from "@foxglove/rosmsg2-serialization";
import zstd from "@foxglove/wasm-zstd";
import { nanos, writeBag } from "./bag_writing.mjs";
import { kJointStateSchema, kStringSchema, kTfMessageSchema } from "./ros2_schemas.mjs";

const out = process.argv[2];
if (!out) throw new Error("usage: node make_test_bags.mjs OUT_DIR [--large]");
const large = process.argv.includes("--large");
const seeds = process.argv.includes("--seeds") ? process.argv[process.argv.indexOf("--seeds") + 1] : null;
mkdirSync(out, { recursive: true });
await zstd.isLoaded;

const kStartSec = 1700000000;
const kJoints = ["shoulder", "elbow", "wrist"];

const jointStateWriter = new MessageWriter([
  ros2humble["sensor_msgs/JointState"],
  ros2humble["std_msgs/Header"],
  ros2humble["builtin_interfaces/Time"],
]);

function stampOf(i) {
  const nanos = i * 10_000_000;
  return { sec: kStartSec + Math.floor(nanos / 1e9), nanosec: nanos % 1e9 };
}

function jointState(i, { names = kJoints, positions, stamp = stampOf(i) } = {}) {
  return {
    header: { stamp, frame_id: "" },
    name: names,
    position: positions ?? [0.01 * i, -0.02 * i, 0.5].slice(0, names.length),
    velocity: [],
    effort: [],
  };
}

// A JointState in big-endian CDR, written field by field with @foxglove/cdr.
function bigEndianJointState(message) {
  const writer = new CdrWriter({ kind: EncapsulationKind.CDR_BE });
  writer.int32(message.header.stamp.sec).uint32(message.header.stamp.nanosec);
  writer.string(message.header.frame_id);
  writer.sequenceLength(message.name.length);
  for (const name of message.name) writer.string(name);
  writer.float64Array(message.position, true);
  writer.float64Array([], true).float64Array([], true);
  return writer.data;
}

const jointStateChannel = {
  topic: "/joint_states",
  schema: { name: "sensor_msgs/msg/JointState", encoding: "ros2msg", data: new TextEncoder().encode(kJointStateSchema) },
};
const tfChannel = {
  topic: "/tf",
  schema: { name: "tf2_msgs/msg/TFMessage", encoding: "ros2msg", data: new Uint8Array() },
};
const cameraChannel = {
  topic: "/camera/image_raw",
  schema: { name: "sensor_msgs/msg/Image", encoding: "ros2msg", data: new Uint8Array() },
};

// `count` joint states interleaved with /tf and camera messages (opaque bytes: they are skipped)
function robotMessages(count, { encode = (m) => jointStateWriter.writeMessage(m), cameraBytes = 3000 } = {}) {
  const messages = [];
  for (let i = 0; i < count; ++i) {
    const message = jointState(i);
    const logTime = nanos(message.header.stamp) + 1_000_000n;
    messages.push([1, logTime - 500_000n, new Uint8Array(64).fill(i & 255)]);
    messages.push([0, logTime, encode(message)]);
    if (i % 10 === 0) messages.push([2, logTime + 100n, new Uint8Array(cameraBytes).fill(i & 255)]);
  }
  return messages;
}

const robotChannels = [jointStateChannel, tfChannel, cameraChannel];
const bags = {};
for (const compression of ["none", "zstd", "lz4"]) {
  bags[`joint_states_${compression}.mcap`] = await writeBag({
    channels: robotChannels,
    messages: robotMessages(200),
    compression,
  });
}
bags["joint_states_unchunked.mcap"] = await writeBag({
  channels: robotChannels,
  messages: robotMessages(200),
  useChunks: false,
});
bags["joint_states_big_endian.mcap"] = await writeBag({
  channels: robotChannels,
  messages: robotMessages(50, { encode: bigEndianJointState }),
});
// two publishers on /joint_states: the arm (three joints) and a gripper (one), as on real robots
{
  const messages = [];
  for (let i = 0; i < 100; ++i) {
    const arm = jointState(i);
    messages.push([0, nanos(arm.header.stamp), jointStateWriter.writeMessage(arm)]);
    if (i % 2 === 0) {
      const gripper = jointState(i, { names: ["finger"], positions: [0.001 * i] });
      messages.push([1, nanos(gripper.header.stamp) + 1n, jointStateWriter.writeMessage(gripper)]);
    }
  }
  bags["two_publishers.mcap"] = await writeBag({ channels: [jointStateChannel, jointStateChannel], messages });
}
bags["no_joint_states.mcap"] = await writeBag({
  channels: [tfChannel, cameraChannel],
  messages: [[0, 1n, new Uint8Array(8)], [1, 2n, new Uint8Array(8)]],
});
bags["wrong_type.mcap"] = await writeBag({
  channels: [{ topic: "/joint_states", schema: { name: "std_msgs/msg/String", encoding: "ros2msg", data: new Uint8Array() } }],
  messages: [[0, 1n, new Uint8Array(8)]],
});
bags["no_messages.mcap"] = await writeBag({ channels: robotChannels, messages: [[1, 1n, new Uint8Array(8)]] });
// header.stamp left at zero by the publisher: times come from the log times
{
  const messages = [];
  for (let i = 0; i < 20; ++i) {
    const message = jointState(i, { stamp: { sec: 0, nanosec: 0 } });
    messages.push([0, nanos(stampOf(i)) + 1_000_000n, jointStateWriter.writeMessage(message)]);
  }
  bags["zero_stamps.mcap"] = await writeBag({ channels: robotChannels, messages });
}
// bad content: a NaN position in message 7, a stamp going back in message 5, lists of different
// lengths in message 3
function badBag(index, change) {
  const messages = [];
  for (let i = 0; i < 10; ++i) {
    const message = jointState(i);
    if (i === index) change(message);
    messages.push([0, nanos(stampOf(i)) + 1_000_000n, jointStateWriter.writeMessage(message)]);
  }
  return writeBag({ channels: robotChannels, messages });
}
bags["nan_position.mcap"] = await badBag(7, (m) => (m.position[1] = NaN));
bags["time_goes_back.mcap"] = await badBag(5, (m) => (m.header.stamp = stampOf(2)));
bags["length_mismatch.mcap"] = await badBag(3, (m) => (m.position = [1, 2]));
bags["garbage_message.mcap"] = await writeBag({
  channels: robotChannels,
  messages: [[0, 5n, new Uint8Array([0, 1, 0, 0, 1, 2, 3])]],
});

// corrupt and truncated variants of the zstd, lz4 and uncompressed bags
const kMagicBytes = 8;
function firstChunkOffset(bytes) {
  let at = kMagicBytes;
  while (bytes[at] !== 0x06) at += 1 + 8 + Number(bytes.readBigUInt64LE(at + 1));
  return at;
}
function patched(bytes, change) {
  const copy = Buffer.from(bytes);
  change(copy);
  return copy;
}
// chunk fields after the 9-byte record prefix: start time 8, end time 8, uncompressed_size 8,
// uncompressed_crc 4, compression (4 + n), records (8 + n)
function chunkRecordsOffset(bytes, chunk) {
  const compressionLength = bytes.readUInt32LE(chunk + 9 + 28);
  return chunk + 9 + 32 + compressionLength + 8;
}
const zstdBag = bags["joint_states_zstd.mcap"];
const lz4Bag = bags["joint_states_lz4.mcap"];
const plainBag = bags["joint_states_none.mcap"];
const zstdChunk = firstChunkOffset(zstdBag);
bags["corrupt_truncated_half.mcap"] = zstdBag.subarray(0, Math.floor(zstdBag.length / 2));
bags["corrupt_truncated_header.mcap"] = zstdBag.subarray(0, 20);
bags["corrupt_cut_without_end.mcap"] = zstdBag.subarray(0, zstdChunk);
bags["corrupt_zstd_data.mcap"] = patched(zstdBag, (b) => {
  const records = chunkRecordsOffset(b, zstdChunk);
  for (let k = 20; k < 60; ++k) b[records + k] ^= 0x5a;
});
bags["corrupt_lz4_data.mcap"] = patched(lz4Bag, (b) => {
  const records = chunkRecordsOffset(b, firstChunkOffset(b));
  for (let k = 10; k < 40; ++k) b[records + k] ^= 0xff;
});
bags["corrupt_crc.mcap"] = patched(plainBag, (b) => {
  const records = chunkRecordsOffset(b, firstChunkOffset(b));
  b[records + 200] ^= 0x01;
});
bags["corrupt_huge_chunk.mcap"] = patched(zstdBag, (b) => b.writeBigUInt64LE(1n << 40n, zstdChunk + 9 + 16));
bags["corrupt_huge_record.mcap"] = patched(zstdBag, (b) => b.writeBigUInt64LE(1n << 62n, zstdChunk + 1));
bags["corrupt_unknown_compression.mcap"] = patched(zstdBag, (b) => b.write("zztd", zstdChunk + 9 + 32));
bags["corrupt_no_header.mcap"] = patched(zstdBag, (b) => (b[kMagicBytes] = 0x03));
bags["corrupt_not_mcap.mcap"] = Buffer.from("time,shoulder\n0,1\n");
bags["corrupt_empty.mcap"] = Buffer.alloc(0);

for (const [name, bytes] of Object.entries(bags)) writeFileSync(join(out, name), bytes);

// a rosbag2 folder split into eleven files (NAME_0.mcap ... NAME_10.mcap), 5 messages each
const split = join(out, "split_bag");
mkdirSync(split, { recursive: true });
for (let part = 0; part <= 10; ++part) {
  const messages = [];
  for (let i = part * 5; i < part * 5 + 5; ++i) {
    const message = jointState(i);
    messages.push([0, nanos(message.header.stamp), jointStateWriter.writeMessage(message)]);
  }
  writeFileSync(join(split, `split_bag_${part}.mcap`), await writeBag({ channels: [jointStateChannel], messages }));
}
writeFileSync(join(split, "metadata.yaml"), "rosbag2_bagfile_information:\n  storage_identifier: mcap\n");

// rosbag2 folders as `ros2 bag record` writes them, each split into two files of 100 joint states
// (with /tf rows beside them): metadata.yaml naming the storage, the files and their compression
function metadataYaml(storage, files, compressionMode = "") {
  return [
    "rosbag2_bagfile_information:",
    "  version: 5",
    `  storage_identifier: ${storage}`,
    "  relative_file_paths:",
    ...files.map((file) => `    - ${file}`),
    `  compression_format: "${compressionMode ? "zstd" : ""}"`,
    `  compression_mode: "${compressionMode}"`,
    "",
  ].join("\n");
}
const hex = (bytes) => Buffer.from(bytes).toString("hex");
function splitMessages(part) {
  return robotMessages(200).filter(([channel]) => channel !== 2).slice(part * 200, part * 200 + 200);
}
const db3Specs = [];
function addDb3(file, messages, { sql = [], topics } = {}) {
  db3Specs.push({
    file,
    topics: topics ?? [
      [1, "/joint_states", "sensor_msgs/msg/JointState", "cdr"],
      [2, "/tf", "tf2_msgs/msg/TFMessage", "cdr"],
    ],
    messages: messages.map(([channel, logTime, data]) => [channel + 1, Number(logTime), hex(data)]),
    sql,
  });
}
for (const [name, storage, mode] of [
  ["rosbag2_sqlite", "sqlite3", ""],
  ["rosbag2_mcap", "mcap", ""],
  ["rosbag2_mcap_file_zstd", "mcap", "FILE"],
  ["rosbag2_mcap_message_zstd", "mcap", "MESSAGE"],
  ["rosbag2_sqlite_file_zstd", "sqlite3", "FILE"],
]) {
  const folder = join(out, name);
  mkdirSync(folder, { recursive: true });
  const extension = storage === "mcap" ? "mcap" : "db3";
  const files = [0, 1].map((part) => `${name}_${part}.${extension}${mode === "FILE" ? ".zstd" : ""}`);
  for (const part of [0, 1]) {
    let messages = splitMessages(part);
    if (mode === "MESSAGE") messages = messages.map(([c, t, data]) => [c, t, zstd.compress(data, 3)]);
    const path = join(folder, files[part]);
    if (storage === "sqlite3") {
      addDb3(mode === "FILE" ? `${path}.db3` : path, messages);
    } else {
      const bytes = await writeBag({ channels: [jointStateChannel, tfChannel], messages });
      writeFileSync(path, mode === "FILE" ? zstd.compress(bytes, 3) : bytes);
    }
  }
  writeFileSync(join(folder, "metadata.yaml"), metadataYaml(storage, files, mode));
}
// a bare .db3 file, and SQLite files that are no rosbag2 bags
addDb3(join(out, "joint_states.db3"), splitMessages(0));
addDb3(join(out, "bad_no_messages_table.db3"), splitMessages(0), { sql: ["DROP TABLE messages"] });
addDb3(join(out, "bad_text_data.db3"), splitMessages(0), { sql: ["UPDATE messages SET data = 'junk' WHERE id = 4"] });
addDb3(join(out, "bad_null_name.db3"), splitMessages(0), { sql: ["UPDATE topics SET name = x'00ff' WHERE id = 2"] });
writeFileSync(join(out, "bad_not_sqlite.db3"), "SQLite format 3\0but nothing else");
// transforms: a base driving +x while turning on /tf (odom -> base_link every 100 ms, x = 0.1 i m,
// yaw = 0.1 i rad, i = 0 .. 10) with its laser on /tf_static (base_link -> laser at 0.1, 0, 0.3),
// as MCAP with definitions and as SQLite without; and broken trees
const tfWriter = new MessageWriter([
  ros2humble["tf2_msgs/TFMessage"], ros2humble["geometry_msgs/TransformStamped"], ros2humble["std_msgs/Header"],
  ros2humble["builtin_interfaces/Time"], ros2humble["geometry_msgs/Transform"], ros2humble["geometry_msgs/Vector3"],
  ros2humble["geometry_msgs/Quaternion"],
]);
const tfSchema = { name: "tf2_msgs/msg/TFMessage", encoding: "ros2msg", data: new TextEncoder().encode(kTfMessageSchema) };
const tfChannels = [{ topic: "/tf", schema: tfSchema }, { topic: "/tf_static", schema: tfSchema }];
function transform(parent, child, stamp, [x, y, z], yaw, rotation = null) {
  return {
    header: { stamp, frame_id: parent },
    child_frame_id: child,
    transform: {
      translation: { x, y, z },
      rotation: rotation ?? { x: 0, y: 0, z: Math.sin(yaw / 2), w: Math.cos(yaw / 2) },
    },
  };
}
function tfMessages(change = (i, t) => t) {
  const start = { sec: kStartSec, nanosec: 0 };
  const messages = [[1, nanos(start), tfWriter.writeMessage({ transforms: [transform("base_link", "laser", start, [0.1, 0, 0.3], 0)] })]];
  for (let i = 0; i <= 10; ++i) {
    const stamp = { sec: kStartSec + Math.floor(i / 10), nanosec: (i % 10) * 100_000_000 };
    const t = change(i, transform("odom", "base_link", stamp, [0.1 * i, 0, 0], 0.1 * i));
    messages.push([0, nanos(stamp), tfWriter.writeMessage({ transforms: [t] })]);
  }
  return messages;
}
const tfBags = {
  "tf_drive.mcap": tfMessages(),
  "tf_nan.mcap": tfMessages((i, t) => (i === 2 ? { ...t, transform: { ...t.transform, rotation: { x: NaN, y: 0, z: 0, w: 1 } } } : t)),
  "tf_loop.mcap": tfMessages((i, t) => (i === 3 ? transform("laser", "odom", t.header.stamp, [0, 0, 0], 0) : t)),
  "tf_two_parents.mcap": tfMessages((i, t) => (i === 4 ? { ...t, header: { ...t.header, frame_id: "map" } } : t)),
  "tf_backwards.mcap": tfMessages((i, t) => (i === 5 ? { ...t, header: { ...t.header, stamp: { sec: kStartSec, nanosec: 0 } } } : t)),
};
for (const [name, messages] of Object.entries(tfBags)) {
  writeFileSync(join(out, name), await writeBag({ channels: tfChannels, messages }));
}
// Camera images of 40x24 pixels for the underlay tests (tests/cli/bag_underlay_test.cpp recomputes
// them): picture A at 0 s, picture B at 1 s on /camera/rgb8 (rows padded by 4 bytes); picture A in
// every other encoding RViz shows, as a PNG and tests/data/jpeg/gradients.jpg (40x24) as
// CompressedImage; and hostile messages (a step that lies, data too short, an unknown encoding);
// CameraInfo messages; a moving sequence on /camera/moving. Each is logged at its stamp, but the
// moving ones later.
const kCameraWidth = 40, kCameraHeight = 24;
function picture(x, y, b) {
  return b ? [255 - x * 6, 255 - y * 10, x * 6] : [x * 6, y * 10, 255 - x * 6];
}
function pngFile(width, height, rgb) {
  const chunk = (type, data) => {
    const body = Buffer.concat([Buffer.from(type, "latin1"), data]);
    const length = Buffer.alloc(4);
    length.writeUInt32BE(data.length);
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(zlib.crc32(body));
    return Buffer.concat([length, body, crc]);
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header.set([8, 2, 0, 0, 0], 8);   // 8-bit RGB
  const rows = [];
  for (let y = 0; y < height; ++y) rows.push(Buffer.from([0]), Buffer.from(rgb.subarray(y * width * 3, (y + 1) * width * 3)));
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk("IHDR", header),
    chunk("IDAT", zlib.deflateSync(Buffer.concat(rows))), chunk("IEND", Buffer.alloc(0))]);
}
function cameraImages() {
  const imageWriter = new MessageWriter([ros2humble["sensor_msgs/Image"], ros2humble["std_msgs/Header"], ros2humble["builtin_interfaces/Time"]]);
  const compressedWriter = new MessageWriter([ros2humble["sensor_msgs/CompressedImage"], ros2humble["std_msgs/Header"], ros2humble["builtin_interfaces/Time"]]);
  const w = kCameraWidth, h = kCameraHeight;
  // pixel bytes of picture A or B: `pixel(rgb, x, y)` gives one pixel's bytes; rows padded by `pad`
  const pixels = (pixel, bytes, pad = 0, b = false) => {
    const data = new Uint8Array((w * bytes + pad) * h);
    for (let y = 0; y < h; ++y) for (let x = 0; x < w; ++x) data.set(pixel(picture(x, y, b), x, y), y * (w * bytes + pad) + x * bytes);
    return data;
  };
  const image = (encoding, bytes, data, { step = w * bytes, height = h, is_bigendian = 0 } = {}) => (sec) =>
    imageWriter.writeMessage({ header: { stamp: { sec, nanosec: 0 }, frame_id: "camera" }, height, width: w, encoding, is_bigendian, step, data });
  const grey = (x, y) => 5 * x + y;   // mono8 and the 16/32-bit scaled images: one value per pixel
  const word16 = (v, big) => (big ? [v >> 8, v & 255] : [v & 255, v >> 8]);
  const float32 = (v) => new Uint8Array(new Float32Array([v]).buffer);
  const jpeg = readFileSync(join(dirname(fileURLToPath(import.meta.url)), "../data/jpeg/gradients.jpg"));
  const topics = {
    "/camera/rgb8": [image("rgb8", 3, pixels((p) => p, 3, 4), { step: w * 3 + 4 }),
                     image("rgb8", 3, pixels((p) => p, 3, 4, true), { step: w * 3 + 4 })],
    "/camera/bgr8": [image("bgr8", 3, pixels(([r, g, b]) => [b, g, r], 3))],
    "/camera/rgba8": [image("rgba8", 4, pixels(([r, g, b]) => [r, g, b, 7], 4))],
    "/camera/bgra8": [image("bgra8", 4, pixels(([r, g, b]) => [b, g, r, 7], 4))],
    "/camera/mono8": [image("mono8", 1, pixels((p, x, y) => [grey(x, y)], 1))],
    "/camera/mono16": [image("mono16", 2, pixels((p, x, y) => word16(1000 + 10 * grey(x, y), true), 2), { is_bigendian: 1 })],
    "/camera/depth": [image("32FC1", 4, pixels((p, x, y) => float32(x === 0 && y === 0 ? NaN : 0.5 + grey(x, y) / 1000), 4))],
    "/camera/short": [image("rgb8", 3, pixels((p) => p, 3).subarray(0, w * 3 * h - 1))],
    "/camera/step_lies": [image("rgb8", 3, pixels((p) => p, 3), { step: w * 3 - 1 })],
    "/camera/huge": [image("rgb8", 3, new Uint8Array(12), { height: 4000000000 })],
    "/camera/yuv": [image("yuv422", 2, pixels(() => [0, 0], 2))],
  };
  const compressed = {
    "/camera/png": compressedWriter.writeMessage({ header: { stamp: { sec: kStartSec, nanosec: 0 }, frame_id: "camera" }, format: "png", data: pngFile(w, h, pixels((p) => p, 3)) }),
    "/camera/jpeg": compressedWriter.writeMessage({ header: { stamp: { sec: kStartSec, nanosec: 0 }, frame_id: "camera" }, format: "jpeg", data: jpeg }),
    "/camera/not_an_image": compressedWriter.writeMessage({ header: { stamp: { sec: kStartSec, nanosec: 0 }, frame_id: "camera" }, format: "tiff", data: new Uint8Array(64) }),
  };
  // a calibration of the 40x24 camera (tests/cli/bag_underlay_test.cpp repeats it as a file), and
  // one whose focal length is zero
  const infoWriter = new MessageWriter([ros2humble["sensor_msgs/CameraInfo"], ros2humble["sensor_msgs/RegionOfInterest"],
    ros2humble["std_msgs/Header"], ros2humble["builtin_interfaces/Time"]]);
  const info = (fx) => infoWriter.writeMessage({
    header: { stamp: { sec: kStartSec, nanosec: 0 }, frame_id: "camera" }, height: h, width: w,
    distortion_model: "plumb_bob", d: [-0.2, 0.05, 0.001, -0.002, 0],
    k: [fx, 0, 21.25, 0, 31, 11.75, 0, 0, 1], r: [1, 0, 0, 0, 1, 0, 0, 0, 1],
    p: [fx + 1, 0, 20.5, 0, 0, 32, 12.25, 0, 0, 0, 1, 0], binning_x: 0, binning_y: 0,
    roi: { x_offset: 0, y_offset: 0, height: 0, width: 0, do_rectify: false } });
  const infos = { "/camera/camera_info": info(30), "/camera/zero_focal": info(0) };
  const channels = [], messages = [];
  for (const [topic, bytes] of Object.entries(infos)) {
    channels.push({ topic, schema: { name: "sensor_msgs/msg/CameraInfo", encoding: "ros2msg", data: new Uint8Array() } });
    messages.push([2 + channels.length, nanos({ sec: kStartSec, nanosec: 1000 }), bytes]);
  }
  for (const [topic, writers] of Object.entries(topics)) {
    channels.push({ topic, schema: { name: "sensor_msgs/msg/Image", encoding: "ros2msg", data: new Uint8Array() } });
    writers.forEach((write, k) => messages.push([2 + channels.length, nanos({ sec: kStartSec + k, nanosec: 0 }), write(kStartSec + k)]));
  }
  // a moving camera: picture k (blue k * 40) stamped at k / 2 s and logged 0.15 s later, as a camera
  // driver's images arrive
  channels.push({ topic: "/camera/moving", schema: { name: "sensor_msgs/msg/Image", encoding: "ros2msg", data: new Uint8Array() } });
  for (let k = 0; k < 5; ++k) {
    const data = pixels(([r, g]) => [r, g, k * 40], 3);
    const stamp = { sec: kStartSec + Math.floor(k / 2), nanosec: (k % 2) * 500_000_000 };
    messages.push([2 + channels.length, nanos(stamp) + 150_000_000n,
      imageWriter.writeMessage({ header: { stamp, frame_id: "camera" }, height: h, width: w, encoding: "rgb8", is_bigendian: 0, step: w * 3, data })]);
  }
  for (const [topic, bytes] of Object.entries(compressed)) {
    channels.push({ topic, schema: { name: "sensor_msgs/msg/CompressedImage", encoding: "ros2msg", data: new Uint8Array() } });
    messages.push([2 + channels.length, nanos({ sec: kStartSec, nanosec: 0 }), bytes]);
  }
  return { channels, messages };
}

// the rover sample (models/rover_description) driving a loop of 1 m radius anticlockwise in
// `seconds` at `hz`: its wheels on /joint_states (each turning by the distance it rolls over its
// 0.1 m radius), its head panning, odom -> base_link on /tf, its description on /robot_description;
// `tf(i, base)` gives the transforms of message i (a hostile bag's change), `description` the bytes
// of the /robot_description message
const roverUrdf = readFileSync(join(dirname(fileURLToPath(import.meta.url)), "../../models/rover_description/urdf/rover.urdf"), "utf8");
const stringWriter = new MessageWriter([ros2humble["std_msgs/String"]]);
// of the /robot_description message, `extra` more channels (numbered from 3) and their messages
function roverLoop(seconds, hz, { tf = (i, base) => [base], description = stringWriter.writeMessage({ data: roverUrdf }), extra = { channels: [], messages: [] } } = {}) {
  const radius = 1, track = 0.46, wheel = 0.1;
  const channels = [
    jointStateChannel,
    { topic: "/tf", schema: tfSchema },
    { topic: "/robot_description", schema: { name: "std_msgs/msg/String", encoding: "ros2msg", data: new TextEncoder().encode(kStringSchema) } },
    ...extra.channels,
  ];
  const start = { sec: kStartSec, nanosec: 0 };
  const messages = [[2, nanos(start), description], ...extra.messages];
  const count = Math.round(seconds * hz);
  for (let i = 0; i <= count; ++i) {
    const t = i / hz;
    const heading = (2 * Math.PI * t) / seconds;
    const nanosec = Math.round((t % 1) * 1e9);
    const stamp = { sec: kStartSec + Math.floor(t), nanosec: nanosec >= 1e9 ? 0 : nanosec };
    const left = (heading * (radius - track / 2)) / wheel;
    const right = (heading * (radius + track / 2)) / wheel;
    const names = ["front_left_wheel_joint", "rear_left_wheel_joint", "front_right_wheel_joint", "rear_right_wheel_joint", "head_pan_joint"];
    const state = { header: { stamp, frame_id: "" }, name: names, position: [left, left, right, right, Math.sin(heading * 2)], velocity: [], effort: [] };
    const base = transform("odom", "base_link", stamp, [radius * Math.sin(heading), radius * (1 - Math.cos(heading)), 0], heading);
    messages.push([0, nanos(stamp), jointStateWriter.writeMessage(state)]);
    messages.push([1, nanos(stamp), tfWriter.writeMessage({ transforms: tf(i, base) })]);
  }
  return writeBag({ channels, messages, chunkSize: 1 << 20 });
}
writeFileSync(join(out, "rover_loop.mcap"), await roverLoop(8, 20));
writeFileSync(join(out, "rover_camera.mcap"), await roverLoop(2, 10, { extra: cameraImages() }));
// hostile rover bags: each is the loop with one thing wrong at message 3 (or in its description)
const atThree = (change) => ({ tf: (i, base) => (i === 3 ? change(base) : [base]) });
// a description whose CDR string claims 100 MB (the length after the 4-byte encapsulation header)
const hugeDescription = stringWriter.writeMessage({ data: "<robot/>" });
new DataView(hugeDescription.buffer, hugeDescription.byteOffset).setUint32(4, 100_000_000, true);
const hostileRovers = {
  "rover_tf_nan.mcap": atThree((t) => [{ ...t, transform: { ...t.transform, rotation: { x: NaN, y: 0, z: 0, w: 1 } } }]),
  "rover_tf_loop.mcap": atThree((t) => [t, transform("base_link", "odom", t.header.stamp, [0, 0, 0], 0)]),
  "rover_tf_two_parents.mcap": atThree((t) => [{ ...t, header: { ...t.header, frame_id: "map" } }]),
  "rover_tf_backwards.mcap": atThree((t) => [{ ...t, header: { ...t.header, stamp: { sec: kStartSec, nanosec: 0 } } }]),
  "rover_description_huge.mcap": { description: hugeDescription },
};
for (const [name, options] of Object.entries(hostileRovers)) {
  writeFileSync(join(out, name), await roverLoop(1, 10, options));
}
// a description whose body is a mesh named relative to it: found next to the bag
const relativeMeshUrdf = roverUrdf.replace('<geometry><box size="0.6 0.4 0.14"/></geometry>', '<geometry><mesh filename="meshes/base_plate.stl"/></geometry>');
writeFileSync(join(out, "rover_relative_mesh.mcap"), await roverLoop(1, 10, { description: stringWriter.writeMessage({ data: relativeMeshUrdf }) }));
// a description that is no URDF
writeFileSync(join(out, "description_junk.mcap"), await writeBag({
  channels: [jointStateChannel, { topic: "/robot_description", schema: { name: "std_msgs/msg/String", encoding: "ros2msg", data: new TextEncoder().encode(kStringSchema) } }],
  messages: [[1, 5n, stringWriter.writeMessage({ data: "<robot name='x'><link name='a'/><joint" })], ...robotMessages(3).filter(([c]) => c === 0)],
}));
if (large) writeFileSync(join(out, "rover_loop_60s.mcap"), await roverLoop(60, 100));
addDb3(join(out, "tf_drive.db3"), tfMessages(), {
  topics: [
    [1, "/tf", "tf2_msgs/msg/TFMessage", "cdr"],
    [2, "/tf_static", "tf2_msgs/msg/TFMessage", "cdr"],
  ],
});
const specFile = join(out, "db3_specs.json");
writeFileSync(specFile, JSON.stringify(db3Specs));
execFileSync("python3", [join(dirname(fileURLToPath(import.meta.url)), "write_db3.py"), specFile]);
// whole-file compression of the .db3 splits, once SQLite has written them
for (const part of [0, 1]) {
  const path = join(out, "rosbag2_sqlite_file_zstd", `rosbag2_sqlite_file_zstd_${part}.db3.zstd`);
  writeFileSync(path, zstd.compress(readFileSync(`${path}.db3`), 3));
  rmSync(`${path}.db3`);
}
rmSync(specFile);

// for benchmarks: 1 kHz joint states for 20 s beside 30 Hz 640x480 RGB camera images whose noise
// lets zstd shrink them only by about a third, as real images (553 MB of messages, ~350 MB file)
if (large) {
  const messages = [];
  const images = [];
  let seed = 12345;
  for (let n = 0; n < 4; ++n) {
    const image = new Uint8Array(640 * 480 * 3);
    for (let k = 0; k < image.length; ++k) {
      seed = (seed * 1103515245 + 12345) >>> 0;
      image[k] = ((k % 1920) >> 3) + ((seed >>> 16) & 31);
    }
    images.push(image);
  }
  for (let i = 0; i < 20000; ++i) {
    const message = jointState(i / 10);
    message.header.stamp = { sec: kStartSec + Math.floor(i / 1000), nanosec: (i % 1000) * 1e6 };
    const logTime = nanos(message.header.stamp);
    messages.push([0, logTime, jointStateWriter.writeMessage(message)]);
    if (i % 33 === 0) messages.push([2, logTime + 1n, images[(i / 33) % 4]]);
  }
  writeFileSync(
    join(out, "large_zstd.mcap"),
    await writeBag({ channels: robotChannels, messages, chunkSize: 4 << 20 }),
  );
}
if (seeds) {
  mkdirSync(seeds, { recursive: true });
  const tiny = {};
  for (const compression of ["none", "zstd", "lz4"]) {
    tiny[`seed_${compression}.mcap`] = await writeBag({ channels: robotChannels, messages: robotMessages(4, { cameraBytes: 16 }), compression });
  }
  tiny["seed_unchunked.mcap"] = await writeBag({ channels: robotChannels, messages: robotMessages(4, { cameraBytes: 16 }), useChunks: false });
  tiny["seed_big_endian.mcap"] = await writeBag({ channels: robotChannels, messages: robotMessages(3, { encode: bigEndianJointState, cameraBytes: 16 }) });
  tiny["seed_none_no_crc.mcap"] = patched(tiny["seed_none.mcap"], (b) => b.writeUInt32LE(0, firstChunkOffset(b) + 9 + 24));
  // bare CDR JointStates behind a byte that is not MCAP's first (the fuzz target decodes those alone)
  const state = jointState(3, { names: ["shoulder", "elbow"], positions: [0.25, -1.5] });
  tiny["seed_cdr_le.bin"] = Buffer.concat([Buffer.from("C"), jointStateWriter.writeMessage(state)]);
  tiny["seed_cdr_be.bin"] = Buffer.concat([Buffer.from("C"), bigEndianJointState(state)]);
  for (const [name, bytes] of Object.entries(tiny)) writeFileSync(join(seeds, name), bytes);
}
console.log(`make_test_bags: wrote ${Object.keys(bags).length} bags and a split bag to ${out}`);
