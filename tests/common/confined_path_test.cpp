// Paths read from a file stay inside that file's folder: relative, absolute, with "..", and
// through symbolic links (unit).
#include "common/confined_path.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "common/error.h"
#include "support/temp_folder.h"

namespace urdfsnap {
namespace {

namespace fs = std::filesystem;

TEST(ConfinedPath, InsideAndOutside) {
  const test::TempFolder folder("confined_path_test");
  const std::string base = folder.Path("artifact");
  const std::string real_base = fs::weakly_canonical(base).string();
  fs::create_directories(folder.Path("artifact/report"));
  folder.Write("artifact/report/a.png", "png");
  folder.Write("secret.txt", "secret");
  fs::create_directory_symlink(folder.Path("."), folder.Path("artifact/up"));
  fs::create_symlink(folder.Path("secret.txt"), folder.Path("artifact/report/b.png"));
  fs::create_symlink("a.png", folder.Path("artifact/report/c.png"));
  EXPECT_EQ(ResolveInside(base, "report"), real_base + "/report");
  EXPECT_EQ(ResolveInside(base, "report/../report/a.png"), real_base + "/report/a.png");
  EXPECT_EQ(ResolveInside(base, "not/there/yet"), real_base + "/not/there/yet");
  EXPECT_EQ(ResolveInside(base, "."), real_base);
  EXPECT_EQ(ResolveInside(base, real_base + "/report"), real_base + "/report");  // absolute, inside
  EXPECT_EQ(ResolveInside(base, "report/c.png"), real_base + "/report/a.png");   // a link inside
  for (const std::string outside : {"..", "../secret.txt", "/etc/passwd", "report/../../secret.txt",
                                    "up/secret.txt", "report/b.png", "../artifactx"}) {
    EXPECT_EQ(ResolveInside(base, outside), "") << outside;
  }
  try {
    ConfinePath(base, "../../../../etc", "r.json: report_dir");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "r.json: report_dir: '../../../../etc' leads outside " + base +
                                         " (paths in this file must stay inside its folder)");
  }
  EXPECT_EQ(ConfineRegularFile(base, "report/a.png", "x"), real_base + "/report/a.png");
  EXPECT_THROW(ConfineRegularFile(base, "report", "x"), Error);
  EXPECT_THROW(ConfineRegularFile(base, "report/missing.png", "x"), Error);
  ASSERT_EQ(::mkfifo(folder.Path("artifact/report/pipe.png").c_str(), 0600), 0);
  EXPECT_THROW(ConfineRegularFile(base, "report/pipe.png", "x"), Error);  // would block a read
}

}  // namespace
}  // namespace urdfsnap
