// The located-YAML reader every YAML input goes through: parse errors and bad values at the line
// of the file they stand on, also in a later document of a file of several (unit).
#include "common/internal/yaml_reader.h"

#include <gtest/gtest.h>

#include "support/error_text.h"

namespace urdfsnap {
namespace {

using test::ErrorText;

TEST(YamlReaderTest, ParseErrorsNameTheLineInTheWholeFile) {
  EXPECT_EQ(ErrorText([] { LoadYaml("a: 1\nb: [1, 2\n", "f.yaml"); }).substr(0, 20), "f.yaml:3: bad YAML: ");
  // a document that starts at line 10 of its file
  EXPECT_EQ(ErrorText([] { YamlReader("f.yaml", 10).Load("a: 1\nb: {\n"); }).substr(0, 21), "f.yaml:12: bad YAML: ");
}

TEST(YamlReaderTest, NodesAreLocatedInTheWholeFile) {
  const YamlReader reader("f.yaml", 10);
  const YAML::Node root = reader.Load("a: 1\nb:\n  - x\n");
  EXPECT_EQ(reader.Line(root["a"]), 10);
  EXPECT_EQ(reader.Line(root["b"][0]), 12);
  EXPECT_EQ(reader.Line(root["missing"]), 0);   // the whole file
  EXPECT_EQ(LineOf(LoadYaml("a: 1\nb: 2\n", "f.yaml")["b"]), 2);
  EXPECT_EQ(LineOf(YAML::Node(YAML::NodeType::Undefined)), 0);
  EXPECT_EQ(reader.Where(root["b"][0]).ToString(), "f.yaml:12");
  EXPECT_EQ(ErrorText([&] { reader.Fail(root["a"], "wrong"); }), "f.yaml:10: wrong");
}

TEST(YamlReaderTest, BadValuesNameWhatWasExpectedAndWhatWasThere) {
  const YamlReader reader("m.yaml");
  const YAML::Node root = reader.Load("n: x\nlist: [1, 2]\nnull_value: ~\nnames: [a, [b]]\nmap: {k: 1}\n");
  EXPECT_EQ(ErrorText([&] { reader.Number(root["n"], "n"); }), "m.yaml:1: n: expected a finite number, got 'x'");
  EXPECT_EQ(ErrorText([&] { reader.Number(root["list"], "list"); }),
            "m.yaml:2: list: expected a finite number, got a list or map");
  EXPECT_EQ(ErrorText([&] { reader.Number(root["null_value"], "v"); }),
            "m.yaml:3: v: expected a finite number, got nothing");
  EXPECT_EQ(ErrorText([&] { reader.Numbers(root["n"], "n"); }), "m.yaml:1: 'n' is not a list of numbers");
  EXPECT_EQ(ErrorText([&] { reader.Names(root["names"], "names"); }),
            "m.yaml:4: 'names' holds something not a name");
  EXPECT_EQ(ErrorText([&] { reader.Field(root["map"], "j", "the map"); }), "m.yaml:5: the map has no 'j'");
  EXPECT_EQ(ErrorText([&] { reader.Field(root["list"], "j", "the list"); }), "m.yaml:2: the list is not a map");
}

TEST(YamlReaderTest, GoodValuesAreRead) {
  const YamlReader reader("m.yaml");
  const YAML::Node root = reader.Load("n: -2.5e-1\nlist: [1, 2]\nnames: [a, b]\n");
  EXPECT_EQ(reader.Number(root["n"], "n"), -0.25);
  EXPECT_EQ(reader.Numbers(root["list"], "list"), (std::vector<double>{1, 2}));
  EXPECT_EQ(reader.Names(root["names"], "names"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(reader.Field(root, "n", "the file").Scalar(), "-2.5e-1");
  EXPECT_EQ(DescribeYaml(root["list"]), "a list");
  EXPECT_EQ(DescribeYaml(root), "a map");
}

}  // namespace
}  // namespace urdfsnap
