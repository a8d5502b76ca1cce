// `render` without --tile (and without a tuned entry) takes the tile size that follows the frame
// (include/parashade/tile_choice.hpp): 64 for a plain frame (Gouraud, flat, Phong, combined) that is not streamed
// in bands, 32 for a streamed one, for per-span normalization and for the unit paths; --tile always wins, and the
// image never depends on it.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliDefaultTile : public CliTest {
 protected:
  int tile_of(const std::filesystem::path& scene, std::vector<std::string> options) {
    options.push_back("--no-tuned");
    EXPECT_TRUE(succeeds(render(scene, options)));
    return read_report()["tile"].get<int>();
  }
};

TEST_F(CliDefaultTile, FollowsTheFrame) {
  const auto scene = input("fine.json", many_triangles_scene());
  EXPECT_EQ(tile_of(scene, {}), 64) << "an unstreamed Gouraud frame";
  const std::string by_default = bytes_of(image());
  EXPECT_EQ(tile_of(scene, {"--method", "flat"}), 64);
  EXPECT_EQ(tile_of(scene, {"--band-mib", "1"}), 32) << "a streamed frame keeps 32-pixel tiles";
  EXPECT_GT(read_report()["stats"]["bands"].get<int>(), 1);
  EXPECT_EQ(bytes_of(image()), by_default);
  EXPECT_EQ(tile_of(scene, {"--method", "phong"}), 64);
  EXPECT_EQ(tile_of(scene, {"--method", "phong", "--band-mib", "1"}), 32) << "a streamed Phong frame";
  EXPECT_EQ(tile_of(scene, {"--method", "combined:auto"}), 64);
  EXPECT_EQ(tile_of(scene, {"--method", "combined:0", "--band-mib", "1"}), 32) << "records that would stream";
  EXPECT_EQ(tile_of(scene, {"--method", "phong", "--normalize", "slerp"}), 32) << "per-span normalization";
  EXPECT_EQ(tile_of(scene, {"--units", "classic", "--arith", "fixed"}), 32) << "the unit path";
  EXPECT_EQ(tile_of(scene, {"--tile", "32"}), 32) << "--tile wins";
  EXPECT_EQ(bytes_of(image()), by_default) << "the tile size changed the image";
  EXPECT_EQ(tile_of(scene, {"--tile", "16", "--band-mib", "0"}), 16);
}

}  // namespace
}  // namespace parashade
