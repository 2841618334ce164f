// McapReader: the record loop over the data section, chunk loading with size checks before any
// allocation, decompression and CRC check, and the Schema/Channel/Message records inside.
#include "bag/mcap_reader.h"

#include <zlib.h>

#include <cstring>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "bag/internal/byte_reader.h"
#include "bag/internal/chunk_decompressor.h"
#include "bag/internal/file_cursor.h"
#include "common/error.h"

namespace urdfsnap::bag {
namespace {

// record opcodes (mcap.dev/spec "Records")
enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

constexpr std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
constexpr std::size_t kRecordPrefixBytes = 1 + 8;  // opcode, uint64 content length
constexpr std::size_t kMessageHeaderBytes = 2 + 4 + 8 + 8;
// topic, encoding and schema names longer than this are taken for corruption
constexpr std::size_t kMaxNameBytes = 4096;
constexpr const char* kRecoverHint =
    " (was the recording cut short? `mcap recover` can often repair such a file)";

std::string OpcodeName(std::uint8_t opcode) {
  static constexpr const char* kNames[] = {"",           "Header",           "Footer",
                                           "Schema",     "Channel",          "Message",
                                           "Chunk",      "Message Index",    "Chunk Index",
                                           "Attachment", "Attachment Index", "Statistics",
                                           "Metadata",   "Metadata Index",   "Summary Offset",
                                           "Data End"};
  if (opcode >= 1 && opcode <= kDataEnd) return kNames[opcode];
  return "unknown (opcode " + std::to_string(opcode) + ")";
}

// A byte buffer that grows without zeroing: memory a corrupt size claims is not touched (so not
// committed) until data is actually written there.
class Buffer {
 public:
  std::uint8_t* Reserve(std::size_t size) {
    if (size > capacity_) {
      data_.reset();
      data_ = std::make_unique_for_overwrite<std::uint8_t[]>(size);
      capacity_ = size;
    }
    return data_.get();
  }

 private:
  std::unique_ptr<std::uint8_t[]> data_;
  std::size_t capacity_ = 0;
};

std::string Text(std::string_view text) {
  if (text.size() > kMaxNameBytes) {
    throw std::runtime_error("a name of " + std::to_string(text.size()) + " bytes");
  }
  return std::string(text);
}

}  // namespace

struct McapReader::State {
  struct Callbacks {
    const std::function<bool(const McapChannel&)>& want;
    const std::function<void(const McapMessage&)>& deliver;
  };

  explicit State(const std::string& path) : file(path) {}

  [[noreturn]] void Corrupt(const std::string& what) const {
    throw Error(file.path() + ": corrupt MCAP: " + what);
  }
  [[noreturn]] void Truncated(const std::string& what) const {
    throw Error(file.path() + ": truncated MCAP: " + what + kRecoverHint);
  }

  // Reads the next record's opcode and length, checking that the content fits in the file.
  std::pair<std::uint8_t, std::uint64_t> NextRecord() {
    const std::uint64_t at = file.offset();
    if (file.remaining() < kRecordPrefixBytes) {
      Truncated("the file ends at byte " + std::to_string(file.size()) +
                ", in the data section, without a Data End record");
    }
    std::uint8_t prefix[kRecordPrefixBytes];
    file.Read(prefix, sizeof prefix);
    ByteReader reader(prefix);
    const std::uint8_t opcode = reader.U8("opcode");
    const std::uint64_t length = reader.U64("record length");
    if (length > file.remaining()) {
      Truncated("the " + OpcodeName(opcode) + " record at byte " + std::to_string(at) + " claims " +
                std::to_string(length) + " bytes but the file ends " +
                std::to_string(file.remaining()) + " bytes later");
    }
    return {opcode, length};
  }

  // Reads a whole record's content (outside chunks) into `record_buffer`.
  std::span<const std::uint8_t> ReadContent(std::uint8_t opcode, std::uint64_t length,
                                            std::uint64_t at) {
    if (length > kMaxRecordBytes) {
      Corrupt("the " + OpcodeName(opcode) + " record at byte " + std::to_string(at) + " claims " +
              std::to_string(length) + " bytes, more than urdfsnap's limit of " +
              std::to_string(kMaxRecordBytes >> 20) + " MiB for such a record");
    }
    std::uint8_t* data = record_buffer.Reserve(static_cast<std::size_t>(length));
    file.Read(data, static_cast<std::size_t>(length));
    return {data, static_cast<std::size_t>(length)};
  }

  void HandleSchema(ByteReader& reader) {
    const std::uint16_t id = reader.U16("id");
    std::string name = Text(reader.String("name"));
    std::string encoding = Text(reader.String("encoding"));
    const std::span<const std::uint8_t> data = reader.Bytes(reader.U32("data"), "data");
    if (id != 0) {  // 0 is invalid
      schemas.try_emplace(id, std::move(name), std::move(encoding),
                          std::string(data.begin(), data.end()));
    }
  }

  // Stores a channel met for the first time and returns it; nullptr for a repeated one.
  const McapChannel* HandleChannel(ByteReader& reader) {
    McapChannel channel;
    channel.id = reader.U16("id");
    const std::uint16_t schema_id = reader.U16("schema_id");
    channel.topic = Text(reader.String("topic"));
    channel.message_encoding = Text(reader.String("message_encoding"));
    reader.Skip(reader.U32("metadata"), "metadata");
    if (channels.contains(channel.id)) return nullptr;  // identical, by the specification
    if (const auto schema = schemas.find(schema_id); schema != schemas.end()) {
      std::tie(channel.schema_name, channel.schema_encoding, channel.schema_data) = schema->second;
    }
    return &channels.emplace(channel.id, std::move(channel)).first->second;
  }

  // The message if its channel is wanted.
  std::optional<McapMessage> HandleMessage(ByteReader& reader) {
    McapMessage message;
    const std::uint16_t channel_id = reader.U16("channel_id");
    message.sequence = reader.U32("sequence");
    message.log_time = reader.U64("log_time");
    message.publish_time = reader.U64("publish_time");
    message.data = reader.Bytes(reader.remaining(), "data");
    const auto channel = channels.find(channel_id);
    if (channel == channels.end()) {
      throw std::runtime_error("a message on channel " + std::to_string(channel_id) +
                               ", which no Channel record before it defines");
    }
    if (!wanted[channel_id]) return std::nullopt;
    message.channel = &channel->second;
    return message;
  }

  // Schema, Channel and Message records, in or out of chunks; `where` locates it for errors. The
  // callbacks run outside the parsing: their exceptions are theirs, not corruption.
  void HandleRecord(std::uint8_t opcode, std::span<const std::uint8_t> content,
                    const std::function<std::string()>& where, const Callbacks& callbacks) {
    ByteReader reader(content);
    const McapChannel* new_channel = nullptr;
    std::optional<McapMessage> message;
    try {
      if (opcode == kSchema) HandleSchema(reader);
      if (opcode == kChannel) new_channel = HandleChannel(reader);
      if (opcode == kMessage) message = HandleMessage(reader);
    } catch (const std::runtime_error& e) {
      Corrupt("the " + OpcodeName(opcode) + " record " + where() + ": " + e.what());
    }
    if (new_channel) wanted[new_channel->id] = callbacks.want(*new_channel);
    if (message) callbacks.deliver(*message);
  }

  // A Message record outside chunks: its header first, the data only if its channel is wanted.
  void ReadLooseMessage(std::uint64_t at, std::uint64_t length, const Callbacks& callbacks) {
    const auto where = [&] { return "at byte " + std::to_string(at); };
    if (length < kMessageHeaderBytes) {
      Corrupt("the Message record " + where() + " is " + std::to_string(length) +
              " bytes, shorter than a message's fields");
    }
    std::uint8_t header[kMessageHeaderBytes];
    file.Read(header, sizeof header);
    const std::uint16_t channel_id = ByteReader(header).U16("channel_id");
    if (channels.contains(channel_id) && !wanted[channel_id]) {
      file.Skip(length - sizeof header);
      return;
    }
    if (length > kMaxRecordBytes) {
      Corrupt("the Message record " + where() + " claims " + std::to_string(length) +
              " bytes, more than urdfsnap's limit of " + std::to_string(kMaxRecordBytes >> 20) +
              " MiB for a message it reads");
    }
    std::uint8_t* content = record_buffer.Reserve(static_cast<std::size_t>(length));
    std::memcpy(content, header, sizeof header);
    file.Read(content + sizeof header, static_cast<std::size_t>(length - sizeof header));
    HandleRecord(kMessage, {content, static_cast<std::size_t>(length)}, where, callbacks);
  }

  // A chunk's fixed fields, checked against the chunk's length and urdfsnap's limits.
  struct ChunkHeader {
    std::uint64_t uncompressed_size = 0;
    std::uint32_t crc = 0;
    std::string compression;
    std::uint64_t records_length = 0;
  };

  ChunkHeader ReadChunkHeader(std::uint64_t length, std::uint64_t end, const std::string& chunk) {
    // message_start_time, message_end_time, uncompressed_size, uncompressed_crc, compression
    constexpr std::size_t kFixedBytes = 8 + 8 + 8 + 4 + 4;
    if (length < kFixedBytes + 8) Corrupt(chunk + " is too short for a chunk's fields");
    std::uint8_t fixed[kFixedBytes];
    file.Read(fixed, sizeof fixed);
    ByteReader fields(fixed);
    fields.Skip(16, "message times");
    ChunkHeader header;
    header.uncompressed_size = fields.U64("uncompressed_size");
    header.crc = fields.U32("uncompressed_crc");
    const std::uint32_t compression_length = fields.U32("compression");
    if (compression_length > 64 || compression_length + 8 > length - kFixedBytes) {
      Corrupt(chunk + ": a compression name of " + std::to_string(compression_length) + " bytes");
    }
    header.compression.assign(compression_length, '\0');
    file.Read(header.compression.data(), header.compression.size());
    std::uint8_t records_length_bytes[8];
    file.Read(records_length_bytes, 8);
    header.records_length = ByteReader(records_length_bytes).U64("records");
    if (header.records_length > end - file.offset()) {
      Corrupt(chunk + ": its records claim " + std::to_string(header.records_length) +
              " bytes, more than the chunk holds");
    }
    if (!header.compression.empty() && !ChunkDecompressor::Reads(header.compression)) {
      Corrupt(chunk + " is compressed with '" + header.compression +
              "'; urdfsnap reads zstd, lz4 and uncompressed chunks");
    }
    for (const std::uint64_t size : {header.uncompressed_size, header.records_length}) {
      if (size > kMaxChunkBytes) {
        Corrupt(chunk + " declares " + std::to_string(size) +
                " bytes, more than urdfsnap's limit of " + std::to_string(kMaxChunkBytes >> 20) +
                " MiB for a chunk");
      }
    }
    if (header.compression.empty() && header.records_length != header.uncompressed_size) {
      Corrupt(chunk + ": an uncompressed chunk of " + std::to_string(header.records_length) +
              " bytes declares " + std::to_string(header.uncompressed_size));
    }
    return header;
  }

  // The chunk's records as stored, decompressed and checked against their CRC32; the span lives
  // in this reader's buffers until the next chunk.
  std::span<const std::uint8_t> ReadChunkRecords(const ChunkHeader& header, std::uint64_t end,
                                                 const std::string& chunk) {
    const auto records_length = static_cast<std::size_t>(header.records_length);
    std::uint8_t* stored = stored_buffer.Reserve(records_length);
    file.Read(stored, records_length);
    file.Skip(end - file.offset());  // fields a later version of the format may add
    std::span<const std::uint8_t> records(stored, records_length);
    if (!header.compression.empty()) {
      const auto size = static_cast<std::size_t>(header.uncompressed_size);
      std::uint8_t* plain = chunk_buffer.Reserve(size);
      try {
        decompressor.Decompress(header.compression, records, {plain, size});
      } catch (const std::runtime_error& e) {
        Corrupt(chunk + ": " + e.what());
      }
      records = {plain, size};
    }
    if (header.crc != 0 && crc32_z(0, records.data(), records.size()) != header.crc) {
      Corrupt(chunk + ": its records do not match their CRC32");
    }
    return records;
  }

  // Each record inside a chunk's (decompressed) records, handed to HandleRecord.
  void DispatchChunkRecords(std::span<const std::uint8_t> records, const std::string& chunk,
                            const Callbacks& callbacks) {
    ByteReader reader(records);
    while (reader.remaining() > 0) {
      const std::size_t offset = reader.offset();
      const auto where = [&] { return "at offset " + std::to_string(offset) + " of " + chunk; };
      if (reader.remaining() < kRecordPrefixBytes) Corrupt("a record " + where() + " is cut off");
      const std::uint8_t opcode = reader.U8("opcode");
      const std::uint64_t record_length = reader.U64("length");
      if (record_length > reader.remaining()) {
        Corrupt("the " + OpcodeName(opcode) + " record " + where() + " claims " +
                std::to_string(record_length) + " bytes, more than the chunk holds");
      }
      HandleRecord(opcode, reader.Bytes(record_length, "record"), where, callbacks);
    }
  }

  // A Chunk record: its header, then its records decompressed and checked, then each dispatched.
  void ReadChunk(std::uint64_t at, std::uint64_t length, const Callbacks& callbacks) {
    const std::uint64_t end = file.offset() + length;
    const std::string chunk = "the chunk at byte " + std::to_string(at);
    const ChunkHeader header = ReadChunkHeader(length, end, chunk);
    DispatchChunkRecords(ReadChunkRecords(header, end, chunk), chunk, callbacks);
  }

  FileCursor file;
  std::map<std::uint16_t, std::tuple<std::string, std::string, std::string>> schemas;  // name, encoding, data
  std::map<std::uint16_t, McapChannel> channels;
  std::map<std::uint16_t, bool> wanted;
  Buffer record_buffer;  // a record outside chunks
  Buffer stored_buffer;  // a chunk's records as stored
  Buffer chunk_buffer;   // a chunk's records decompressed
  ChunkDecompressor decompressor;
};

McapReader::McapReader(const std::string& path) : state_(std::make_unique<State>(path)) {
  FileCursor& file = state_->file;
  std::uint8_t magic[sizeof kMagic] = {};
  file.ReadAt(0, magic, std::min<std::uint64_t>(sizeof magic, file.size()));
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
    if (std::memcmp(magic, "SQLite f", 8) == 0) {
      throw Error(path +
                  ": a SQLite rosbag2 file (.db3); urdfsnap reads MCAP bags (convert it "
                  "with `ros2 bag convert`, or record with `--storage mcap`)");
    }
    throw Error(path + ": not an MCAP file (it does not start with MCAP's magic bytes)");
  }
  file.Skip(sizeof kMagic);
  std::uint8_t end_magic[sizeof kMagic] = {};
  if (file.size() >= 2 * sizeof kMagic) {
    file.ReadAt(file.size() - sizeof kMagic, end_magic, sizeof end_magic);
  }
  if (std::memcmp(end_magic, kMagic, sizeof kMagic) != 0) {
    state_->Truncated("it does not end with MCAP's magic bytes");
  }
  const auto [opcode, length] = state_->NextRecord();
  if (opcode != kHeader) {
    state_->Corrupt("the first record is " + OpcodeName(opcode) + ", not Header");
  }
  ByteReader header(state_->ReadContent(opcode, length, sizeof kMagic));
  try {
    profile_ = Text(header.String("profile"));
    library_ = Text(header.String("library"));
  } catch (const std::runtime_error& e) {
    state_->Corrupt(std::string("the Header record: ") + e.what());
  }
}

McapReader::~McapReader() = default;

void McapReader::ReadMessages(const std::function<bool(const McapChannel&)>& wanted,
                              const std::function<void(const McapMessage&)>& on_message) {
  State& state = *state_;
  const State::Callbacks callbacks{wanted, on_message};
  // after the data section, the summary's copies of the Schema and Channel records: they also name
  // channels that have no messages (writers put those in the data section only with a message)
  bool in_summary = false;
  while (true) {
    const std::uint64_t at = state.file.offset();
    const auto [opcode, length] = state.NextRecord();
    const auto where = [at] { return "at byte " + std::to_string(at); };
    if (opcode == kFooter) return;
    if (in_summary && opcode != kSchema && opcode != kChannel) {
      state.file.Skip(length);
      continue;
    }
    switch (opcode) {
      case kDataEnd:
        in_summary = true;
        state.file.Skip(length);
        break;
      case kChunk:
        state.ReadChunk(at, length, callbacks);
        break;
      case kMessage:
        state.ReadLooseMessage(at, length, callbacks);
        break;
      case kSchema:
      case kChannel:
        state.HandleRecord(opcode, state.ReadContent(opcode, length, at), where, callbacks);
        break;
      default:  // attachments, metadata, indexes and records of later versions: not needed here
        state.file.Skip(length);
    }
  }
}

std::vector<const McapChannel*> McapReader::channels() const {
  std::vector<const McapChannel*> list;
  for (const auto& [id, channel] : state_->channels) list.push_back(&channel);
  return list;
}

}  // namespace urdfsnap::bag
