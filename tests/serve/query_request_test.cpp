// /render.png's query keys mapped onto a RenderRequest: render's option names, flags both ways,
// joints, and render's messages for bad values.
#include "serve/query_request.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace urdfsnap::serve {
namespace {

request::RenderRequest Base() {
  request::RenderRequest base;
  base.model.path = "robot.urdf";
  base.no_grid = true;  // as `urdfsnap serve robot.urdf --no-grid` would give
  base.yaw = std::string(1, '1');  // (not a literal: GCC 12 warns falsely on that)
  return base;
}

std::string ErrorOf(const Query& query) {
  try {
    RequestFromQuery(query, Base());
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(QueryRequest, TextOptionsReplaceTheServersOptions) {
  const auto r = RequestFromQuery({{"yaw", "0.5"}, {"size", "800x600"}, {"focal", "0,0,1"}}, Base());
  EXPECT_EQ(r.yaw, "0.5");
  EXPECT_EQ(r.size, "800x600");
  EXPECT_EQ(r.focal, "0,0,1");
  EXPECT_EQ(r.model.path, "robot.urdf");
  EXPECT_TRUE(r.no_grid);  // not in the query: the server's
}

TEST(QueryRequest, FlagsTurnOnAndOff) {
  for (const char* on : {"", "1", "true"}) EXPECT_TRUE(RequestFromQuery({{"tf", on}}, Base()).tf) << on;
  for (const char* off : {"0", "false"}) {
    EXPECT_FALSE(RequestFromQuery({{"no-grid", off}}, Base()).no_grid) << off;
  }
  EXPECT_EQ(ErrorOf({{"tf", "yes"}}), "--tf 'yes': expected true, false, 1, 0 or no value");
}

TEST(QueryRequest, JointsAsRenderTakesThem) {
  const auto r = RequestFromQuery({{"j.elbow", "-1.5"}, {"j.shoulder", "+0.25"}}, Base());
  ASSERT_EQ(r.joints.size(), 2u);
  EXPECT_EQ(r.joints[0], (std::pair<std::string, double>{"elbow", -1.5}));
  EXPECT_EQ(r.joints[1], (std::pair<std::string, double>{"shoulder", 0.25}));
  // the message of `render -j elbow=bent`
  EXPECT_EQ(ErrorOf({{"j.elbow", "bent"}}),
            "--joint 'elbow=bent': expected NAME=VALUE with VALUE a number in radians or metres");
  EXPECT_NE(ErrorOf({{"j.", "1"}}).find("expected NAME=VALUE"), std::string::npos);
}

TEST(QueryRequest, RefusesUnknownRepeatedEmptyAndFileKeys) {
  EXPECT_NE(ErrorOf({{"jaw", "1"}}).find("unknown option 'jaw'; the keys are render's options: size, yaw"),
            std::string::npos);
  EXPECT_EQ(ErrorOf({{"yaw", "1"}, {"yaw", "2"}}), "'yaw' is given more than once");
  EXPECT_EQ(ErrorOf({{"yaw", ""}}), "--yaw needs a value (yaw=...)");
  // no URL may name a file on the server's disk
  EXPECT_EQ(ErrorOf({{"rviz", "/etc/passwd"}}),
            "--rviz names a file, which a URL cannot: start urdfsnap serve with --rviz FILE instead");
  EXPECT_NE(ErrorOf({{"joints", "/etc/passwd"}}).find("unknown option 'joints'"), std::string::npos);
  EXPECT_NE(ErrorOf({{"model", "/etc/passwd"}}).find("unknown option 'model'"), std::string::npos);
}

TEST(QueryRequest, ValuesAreCheckedWhereRenderChecksThem) {
  // the text is passed on as given; RenderSession checks it and names the option as render does
  EXPECT_EQ(RequestFromQuery({{"yaw", "abc"}}, Base()).yaw, "abc");
}

}  // namespace
}  // namespace urdfsnap::serve
