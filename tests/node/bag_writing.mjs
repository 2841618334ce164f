// Writing MCAP bags with the MCAP project's own TypeScript writer (@mcap/core), shared by the
// scripts that make urdfsnap's test bags (make_test_bags.mjs, make_cloud_bags.mjs).
import { McapWriter } from "@mcap/core";
import zstd from "@foxglove/wasm-zstd";
import lz4 from "lz4js";

await zstd.isLoaded;

// builtin_interfaces/Time as nanoseconds
export function nanos({ sec, nanosec }) {
  return BigInt(sec) * 1_000_000_000n + BigInt(nanosec);
}

class BufferWritable {
  chunks = [];
  size = 0n;
  async write(buffer) {
    this.chunks.push(Buffer.from(buffer));
    this.size += BigInt(buffer.byteLength);
  }
  position() {
    return this.size;
  }
  bytes() {
    return Buffer.concat(this.chunks);
  }
}

const compressors = {
  none: undefined,
  zstd: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) }),
  lz4: (data) => ({ compression: "lz4", compressedData: lz4.compress(data) }),
};

// Writes a bag from `channels` ({topic, schema: {name, encoding, data}|null, encoding}) and
// `messages` ([channelIndex, logTime (bigint), data]) and returns its bytes.
export async function writeBag({ channels, messages, compression = "zstd", chunkSize = 4096, useChunks = true }) {
  const writable = new BufferWritable();
  const writer = new McapWriter({
    writable,
    useChunks,
    chunkSize,
    compressChunk: compressors[compression],
  });
  await writer.start({ profile: "ros2", library: "urdfsnap test bags (@mcap/core)" });
  const ids = [];
  for (const channel of channels) {
    const schemaId = channel.schema ? await writer.registerSchema(channel.schema) : 0;
    ids.push(
      await writer.registerChannel({
        schemaId,
        topic: channel.topic,
        messageEncoding: channel.encoding ?? "cdr",
        metadata: new Map([["offered_qos_profiles", ""]]),
      }),
    );
  }
  let sequence = 0;
  for (const [channel, logTime, data] of messages) {
    await writer.addMessage({ channelId: ids[channel], sequence: sequence++, logTime, publishTime: logTime, data });
  }
  await writer.end();
  return writable.bytes();
}

