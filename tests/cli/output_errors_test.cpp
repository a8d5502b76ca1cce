// Destinations that cannot be written: exit 3 naming the path, and neither the image nor the report nor
// a temporary file left behind (the outputs are whole or absent, README).
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliOutput : public CliTest {
 protected:
  // -o and --report given explicitly (render_args' own come first; CLI11 refuses a second -o, so the
  // arguments are built here).
  RunResult render_to(const std::filesystem::path& image_path, const std::filesystem::path& report_path) const {
    std::vector<std::string> args = {"render", scene_.string(), "-o", image_path.string(), "--report",
                                     report_path.string(), "--frames", "1", "--warmup", "0", "-q", "--no-error"};
    const std::vector<std::string> device = device_args();
    args.insert(args.end(), device.begin(), device.end());
    return run_parashade(args);
  }

  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

TEST_F(CliOutput, ImageIntoMissingDirectory) {
  const auto missing = out_dir() / "no_such_dir";
  EXPECT_TRUE(fails_with(render_to(missing / "image.png", report()), kBadInput, {"no_such_dir"}));
  EXPECT_FALSE(std::filesystem::exists(missing));
  EXPECT_TRUE(nothing_written());
}

// The report is written after the image: refusing it late would leave the image alone.
TEST_F(CliOutput, ReportIntoMissingDirectory) {
  EXPECT_TRUE(fails_with(render_to(image(), out_dir() / "no_such_dir" / "report.json"), kBadInput, {"no_such_dir"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliOutput, UnknownImageExtensionIsNamed) {
  EXPECT_TRUE(fails_with(render_to(out_dir() / "image.xyz", report()), kBadInput, {"image.xyz", ".xyz"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliOutput, ImageWithoutExtension) {
  EXPECT_TRUE(fails_with(render_to(out_dir() / "image", report()), kBadInput, {"image", "extension"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliOutput, ImageThatIsADirectory) {
  std::filesystem::create_directories(out_dir() / "taken.png");
  EXPECT_TRUE(fails_with(render_to(out_dir() / "taken.png", report()), kBadInput, {"taken.png"}));
  EXPECT_EQ(out_entries(), std::vector<std::string>{"taken.png"});
}

TEST_F(CliOutput, ReportThatIsADirectory) {
  std::filesystem::create_directories(out_dir() / "taken.json");
  EXPECT_TRUE(fails_with(render_to(image(), out_dir() / "taken.json"), kBadInput, {"taken.json"}));
  EXPECT_EQ(out_entries(), std::vector<std::string>{"taken.json"});
}

// A folder that exists but refuses new files fails only when the report is written, after the image:
// the image must go again. Root writes anywhere, so the case cannot be made there.
TEST_F(CliOutput, UnwritableReportFolderTakesTheImageAlong) {
  const auto locked = out_dir() / "locked";
  std::filesystem::create_directories(locked);
  std::filesystem::permissions(locked, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const bool blocked = !std::ofstream(locked / "probe");
  std::error_code ec;
  std::filesystem::remove(locked / "probe", ec);
  if (!blocked) {
    std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
    GTEST_SKIP() << "a read-only folder is writable for this user (root?): cannot make the report fail";
  }
  const RunResult r = render_to(image(), locked / "report.json");
  std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
  EXPECT_TRUE(fails_with(r, kBadInput, {"report.json"}));
  EXPECT_EQ(out_entries(), std::vector<std::string>{"locked"});
}

}  // namespace
}  // namespace parashade
