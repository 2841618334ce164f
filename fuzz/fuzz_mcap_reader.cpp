// Fuzz target: an MCAP bag read for the JointStates on /joint_states (McapReader, chunk
// decompression, CDR decoding), or, when the first byte is not MCAP's, the rest decoded as one CDR
// JointState. Only urdfsnap::Error (and CdrError from the bare decoder) may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "bag/cdr_reader.h"
#include "bag/joint_state_bag.h"
#include "bag/joint_state_message.h"
#include "common/error.h"
#include "fuzz_work_dir.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  urdfsnap::fuzz::EnterFreshWorkDir();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  if (size > 0 && data[0] != 0x89) {
    static const bag::MessageSchema schema = *bag::MessageSchema::Shipped(bag::kJointStateType);
    bag::JointStateMessage message;
    try {
      bag::DecodeJointState(schema, {data + 1, size - 1}, message);
    } catch (const bag::CdrError&) {
    }
    return 0;
  }
  const std::string path = fuzz::WriteInput("bag.mcap", data, size);
  try {
    bag::ReadJointStates(path, bag::kDefaultJointStateTopic, [](const bag::BagJointState&) {});
  } catch (const Error&) {
  }
  return 0;
}
