// A render's pictures (render_outputs.hpp): --flip-map is drawn from the FLIP map alone, so a render asking for
// it and no other picture keeps no reference (RenderRequest::keep_reference): before, the whole reference (its
// ideal and exact values in doubles, coverage, visible triangles: 57 bytes a pixel) was kept to the end for it.
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "parashade/image.hpp"
#include "parashade/render_outputs.hpp"

namespace parashade {
namespace {

namespace fs = std::filesystem;

TEST(RenderOutputs, AFlipMapAloneNeedsNoReference) {
  const fs::path dir = fs::temp_directory_path() / ("parashade-render-outputs-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  RenderOutputs o;
  o.image = dir / "frame.png";
  o.flip_map = dir / "flip.png";
  EXPECT_TRUE(o.pictures());  // the error figures are computed for it
  EXPECT_FALSE(o.needs_reference());
  o.error_map = dir / "map.png";
  EXPECT_TRUE(o.needs_reference());
  o.error_map.clear();

  RenderResult r;
  r.image.width = 4;
  r.image.height = 2;
  r.image.rgba.assign(4 * 8, 255);
  r.errors.emplace();  // no reference in it, as a render keeps none for --flip-map alone
  r.errors->flip_map = {0.0f, 0.25f, 0.5f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  const std::vector<std::string> lines = o.write(r);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("FLIP map " + o.flip_map.string(), 0), 0u) << lines[0];
  const RenderedImage map = read_image(o.flip_map);
  EXPECT_EQ(map.width, 4);
  EXPECT_EQ(map.height, 2);
  // Magma: black at 0, its brightest entry at 1.
  EXPECT_EQ(int(map.rgba[0]) + map.rgba[1] + map.rgba[2], 0 + 0 + 4);
  EXPECT_GT(int(map.rgba[4 * 3]), 250);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace parashade
