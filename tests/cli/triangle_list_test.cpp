// render --triangle-choice list:FILE: Phong for the screen triangles FILE names, Gouraud for the rest, numbered as
// --triangle-map numbers them (minus one). Every pixel of a listed triangle must be exact Phong's and every other
// Gouraud's, each from its own render; bad files are refused with the file named.
#include <set>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/image.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class CliTriangleList : public CliTest {
 protected:
  fs::path scene_ = input("ball.json", sphere_scene());
  fs::path list(const std::string& name, const std::string& text) const { return input(name, text); }
  RunResult listed(const fs::path& file, std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {"--method", "combined:0", "--triangle-choice", "list:" + file.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return render(scene_, args, ErrorFigures::compute);
  }
  std::string rendered_as(const std::string& method, const std::string& name) const {
    const fs::path out = out_dir() / name;
    const RunResult r =
        run_parashade({"render", scene_.string(), "-o", out.string(), "--method", method, "--no-error", "-q"});
    EXPECT_EQ(r.exit_code, kOk) << r;
    return bytes_of(out);
  }
};

TEST_F(CliTriangleList, EveryTriangleListedIsPhongNoneIsGouraud) {
  ASSERT_TRUE(succeeds(listed(list("none.txt", ""))));
  const int screen = read_report()["triangles"]["after_culling"].get<int>();  // the front half of the ball
  ASSERT_GT(screen, 10);
  std::string every;
  for (int t = 0; t < screen; ++t) every += std::to_string(t) + "\n";
  ASSERT_TRUE(succeeds(listed(list("every.txt", every))));
  const std::string all_phong = bytes_of(image());
  ASSERT_TRUE(succeeds(listed(in_dir() / "none.txt")));
  const std::string all_gouraud = bytes_of(image());
  EXPECT_EQ(all_phong, rendered_as("phong", "phong.png"));
  EXPECT_EQ(all_gouraud, rendered_as("gouraud", "gouraud.png"));
  EXPECT_NE(all_phong, all_gouraud);
}

TEST_F(CliTriangleList, ListedPixelsArePhongsTheOthersGourauds) {
  const std::set<int> phong = {0, 3, 4, 7, 10, 11, 12, 20, 21, 27};  // a few of the 28 screen triangles
  std::string text;
  for (int t : phong) text += std::to_string(t) + " ";
  const fs::path map_file = out_dir() / "ids.png";
  ASSERT_TRUE(succeeds(listed(list("some.txt", text), {"--triangle-map", map_file.string()})));
  const auto c = read_report()["stats"]["triangle_choice"];
  const RenderedImage mix = read_image(image()), ids = read_image(map_file);
  rendered_as("phong", "phong.png");
  rendered_as("gouraud", "gouraud.png");
  const RenderedImage p = read_image(out_dir() / "phong.png"), g = read_image(out_dir() / "gouraud.png");
  int from_phong = 0, from_gouraud = 0;
  for (std::size_t px = 0; px < ids.rgba.size() / 4; ++px) {
    const int id = (ids.rgba[4 * px] << 16) | (ids.rgba[4 * px + 1] << 8) | ids.rgba[4 * px + 2];
    if (id == 0) continue;
    const bool is_phong = phong.count(id - 1) > 0;
    const RenderedImage& expected = is_phong ? p : g;
    for (int ch = 0; ch < 3; ++ch)
      ASSERT_EQ(mix.rgba[4 * px + ch], expected.rgba[4 * px + ch])
          << "pixel " << px << " of triangle " << id - 1 << (is_phong ? " (listed)" : " (not listed)");
    ++(is_phong ? from_phong : from_gouraud);
  }
  EXPECT_GT(from_phong, 20);
  EXPECT_GT(from_gouraud, 200);
  EXPECT_EQ(c["triangles"].get<int>() - c["gouraud"].get<int>(), int(phong.size())) << c;
  EXPECT_EQ(read_report()["triangle_choice_rule"], "list");
}

// The boundary of the range check (issue 46, "tests that bind"): of an N-triangle frame, triangle N - 1 is the
// last one and N is one past it. With `> n` for `>= n` a list naming N rendered, exited 0 and wrote one past
// the frame's flag array; the suite passed.
TEST_F(CliTriangleList, TheTriangleOnePastTheLastIsRefused) {
  ASSERT_TRUE(succeeds(listed(list("none.txt", ""))));
  const int screen = read_report()["triangles"]["after_culling"].get<int>();
  ASSERT_GT(screen, 10);
  ASSERT_TRUE(succeeds(listed(list("last.txt", std::to_string(screen - 1)))));
  std::filesystem::remove_all(out_dir());
  std::filesystem::create_directories(out_dir());
  EXPECT_TRUE(fails_with(listed(list("past.txt", "0 " + std::to_string(screen))), kBadInput,
                         {"past.txt", "names triangle " + std::to_string(screen) + ", the frame has " +
                                          std::to_string(screen)}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliTriangleList, BadListsAreNamed) {
  EXPECT_TRUE(fails_with(listed(in_dir() / "missing.txt"), kBadInput, {"missing.txt"}));
  EXPECT_TRUE(fails_with(listed(list("words.txt", "1 2 three")), kBadInput, {"words.txt", "three"}));
  EXPECT_TRUE(fails_with(listed(list("negative.txt", "-4")), kBadInput, {"negative.txt", "-4"}));
  EXPECT_TRUE(fails_with(listed(list("far.txt", "5 100000")), kBadInput, {"far.txt", "100000"}));
  const fs::path fine = list("fine.txt", "1 2");
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "combined:0", "--triangle-choice", "list"}), kUsage,
                         {"list", "FILE"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "phong", "--triangle-choice", "list:" + fine.string()}),
                         kUsage, {"--triangle-choice"}));
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
