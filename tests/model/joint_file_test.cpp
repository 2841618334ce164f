// Joint files: both shapes in YAML and JSON, and errors that name the file and line.
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "model/joint_values.h"
#include "test_names.h"

namespace urdfsnap::model {
namespace {

using ::testing::ElementsAre;
using ::testing::Pair;

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

struct JointFileCase {
  const char* file;
  const char* text;
};

class GoodJointFileTest : public ::testing::TestWithParam<JointFileCase> {};

TEST_P(GoodJointFileTest, ReadsNamesAndValuesInOrder) {
  const std::string path = WriteFile(GetParam().file, GetParam().text);
  EXPECT_THAT(ReadJointFile(path), ElementsAre(Pair("shoulder", 0.5), Pair("elbow", -1.25)));
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, GoodJointFileTest,
    ::testing::Values(
        JointFileCase{"map.yaml", "shoulder: 0.5\nelbow: -1.25\n"},
        JointFileCase{"state.yaml",
                      "header: {frame_id: ''}\nname: [shoulder, elbow]\nposition: [0.5, -1.25]\n"
                      "velocity: []\n"},
        JointFileCase{"block_state.yml", "name:\n  - shoulder\n  - elbow\nposition:\n  - 0.5\n"
                                         "  - -1.25\n"},
        JointFileCase{"map.json", "{\"shoulder\": 0.5, \"elbow\": -1.25}"},
        JointFileCase{"state.json",
                      "{\"name\": [\"shoulder\", \"elbow\"],\n \"position\": [0.5, -1.25],\n"
                      " \"effort\": []}"}),
    [](const ::testing::TestParamInfo<JointFileCase>& info) {
      return test::TestName(info.param.file);
    });

struct BadJointFileCase {
  const char* file;
  const char* text;
  const char* message;  // after "<temp dir>/"
};

class BadJointFileTest : public ::testing::TestWithParam<BadJointFileCase> {};

TEST_P(BadJointFileTest, ErrorNamesFileAndLine) {
  const std::string path = GetParam().text ? WriteFile(GetParam().file, GetParam().text)
                                           : ::testing::TempDir() + GetParam().file;
  try {
    ReadJointFile(path);
    FAIL() << "no error for " << GetParam().text;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), ::testing::TempDir() + GetParam().message);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Errors, BadJointFileTest,
    ::testing::Values(
        BadJointFileCase{"not_number.yaml", "shoulder: 0.5\nelbow: bent\n",
                         "not_number.yaml:2: joint 'elbow': expected a number (radians or "
                         "metres), got 'bent'"},
        BadJointFileCase{"bad.yaml", "shoulder: 0.5\nelbow: [1, 2\n",
                         "bad.yaml:3: bad YAML: end of sequence flow not found"},
        BadJointFileCase{"list.yaml", "shoulder: [1, 2]\n",
                         "list.yaml:1: joint 'shoulder': expected a number, got a list (a "
                         "JointState-style file needs both 'name' and 'position' lists)"},
        BadJointFileCase{"lengths.yaml", "name: [a, b]\nposition: [1]\n",
                         "lengths.yaml:2: 'name' lists 2 joints but 'position' 1 values"},
        BadJointFileCase{"scalar.yaml", "0.5\n",
                         "scalar.yaml:1: expected a map of joint names to values, or name: and "
                         "position: lists"},
        BadJointFileCase{"not_number.json", "{\n  \"shoulder\": 0.5,\n  \"elbow\": \"bent\"\n}\n",
                         "not_number.json:3: joint 'elbow': expected a number (radians or "
                         "metres), got 'bent'"},
        BadJointFileCase{"state.json", "{\"name\": [\"a\"],\n\"position\": [null]}",
                         "state.json:2: joint 'a': expected a number (radians or metres), got "
                         "'null'"},
        BadJointFileCase{"bad.json", "{\n  \"shoulder\": 0.5,\n}\n",
                         "bad.json:3: bad JSON: syntax error while parsing object key - "
                         "unexpected '}'; expected string literal"},
        BadJointFileCase{"list_key.yaml", "shoulder: 1\n[a, b]: 2\n",
                         "list_key.yaml:2: expected a joint name as the key, got a list"},
        BadJointFileCase{"overflow.json", "{\"shoulder\": 1e999}",
                         "overflow.json: bad JSON: number overflow parsing '1e999'"},
        BadJointFileCase{"array.json", "[1, 2]",
                         "array.json:1: expected an object of joint names to values, or "
                         "\"name\" and \"position\" arrays"},
        BadJointFileCase{"missing.yaml", nullptr, "missing.yaml: cannot read the joint file: No such file or directory"}),
    [](const ::testing::TestParamInfo<BadJointFileCase>& info) {
      return test::TestName(info.param.file);
    });

}  // namespace
}  // namespace urdfsnap::model
