// $(find PKG) without ROS: the search order and the error listing where it looked.
#include "common/package_finder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "common/error.h"
#include "xacro_test_files.h"

namespace urdfsnap {
namespace {

using ::testing::HasSubstr;

TEST(FindPackage, SearchOrder) {
  xacro::TestFiles files;
  files.Write("explicit/package.xml", "<package><name>pkg</name></package>");
  files.Write("rpp/deep/er/pkg_folder/package.xml", "<package><name>pkg</name></package>");
  files.Write("ament/share/pkg/package.xml", "<package><name>pkg</name></package>");
  files.Write("near/pkg_a/package.xml", "<package><name>pkg_a</name></package>");
  files.Write("near/pkg_b/package.xml", "<package>\n  <name> pkg_b </name></package>");
  const std::string input = files.Write("near/pkg_a/urdf/robot.xacro", "<robot/>");

  unsetenv("ROS_PACKAGE_PATH");
  unsetenv("AMENT_PREFIX_PATH");
  PackageSearch search{{{"pkg", files.dir() + "/explicit"}}, input};
  EXPECT_EQ(FindPackage("pkg", search), files.dir() + "/explicit");
  search.explicit_dirs.clear();

  setenv("ROS_PACKAGE_PATH", (files.dir() + "/nothing:" + files.dir() + "/rpp").c_str(), 1);
  EXPECT_EQ(FindPackage("pkg", search), files.dir() + "/rpp/deep/er/pkg_folder");
  unsetenv("ROS_PACKAGE_PATH");

  setenv("AMENT_PREFIX_PATH", (files.dir() + "/ament").c_str(), 1);
  EXPECT_EQ(FindPackage("pkg", search), files.dir() + "/ament/share/pkg");
  unsetenv("AMENT_PREFIX_PATH");

  EXPECT_EQ(FindPackage("pkg_a", search), files.dir() + "/near/pkg_a");
  EXPECT_EQ(FindPackage("pkg_b", search), files.dir() + "/near/pkg_b");
  try {
    FindPackage("pkg", search);
    FAIL() << "found a package that is not there";
  } catch (const Error& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("package 'pkg' not found, searched: the folders above " + input));
    EXPECT_THAT(std::string(e.what()), HasSubstr("the siblings of " + files.dir() + "/near/pkg_a"));
  }
}

}  // namespace
}  // namespace urdfsnap
