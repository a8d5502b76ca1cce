// The hard-case scenes of scenes/hard/ (issue 7, item 6; the meshes come from scenes/hard/generate.py).
// Every scene renders without error in float and fixed point; its float Gouraud values stay within the
// derived bound of the ideal (docs/error-bounds.md); its coverage is what the geometry says: the planar
// tilings cover each pixel of their region exactly once (no crack, no double hit along shared edges,
// however thin, small, large or many the triangles), the closed sphere is watertight.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "gouraud_bound.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/metrics.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"
#include "parashade/unit_error.hpp"

namespace parashade {
namespace {

using namespace testing_support;

Scene hard_scene(const std::string& name) {
  return load_scene(std::filesystem::path(PARASHADE_SOURCE_DIR) / "scenes" / "hard" / (name + ".json"));
}

struct CoverageSummary {
  std::size_t covered = 0, most = 0;
};

CoverageSummary summarize(const std::vector<std::uint32_t>& counts) {
  CoverageSummary s;
  for (std::uint32_t c : counts) {
    s.covered += c > 0;
    s.most = std::max<std::size_t>(s.most, c);
  }
  return s;
}

struct HardCase {
  const char* name;
  std::size_t covered;  // pixels the scene's geometry covers (0: not checked here)
};

void PrintTo(const HardCase& c, std::ostream* os) { *os << c.name; }

class HardScene : public ::testing::TestWithParam<HardCase> {};
using PlanarTiling = HardScene;

// Planar tilings: each pixel of the tiled region once, nothing else (counts in scenes/hard/generate.py).
TEST_P(PlanarTiling, CoversItsRegionExactlyOnce) {  const Scene scene = hard_scene(GetParam().name);
  for (int tile : {16, 64}) {
    Renderer renderer(test_device(), render_options(Method::flat, false, tile));
    const CoverageSummary s = summarize(renderer.coverage_counts(scene));
    EXPECT_EQ(s.covered, GetParam().covered) << "tile " << tile;
    EXPECT_EQ(s.most, 1u) << "tile " << tile << ": some pixel is covered twice";
  }
}

// The hard meshes are planar and most have no vertex normals, so as loaded every image is one colour and
// any bound holds trivially (measured max 0 against 1.1e-4). Here every vertex gets a normal that varies
// across the mesh (a few degrees per pixel at most, up to 50 degrees overall) and the material a highlight,
// so intensities vary over each triangle and the planes' increments are far from 0; the material keeps
// every value inside 0..255 (no clamping to hide an error).
Scene with_varying_normals(Scene scene) {
  for (Object& o : scene.objects) {
    auto mesh = std::make_shared<Mesh>(*o.mesh);
    mesh->normals.resize(mesh->positions.size());
    for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
      const glm::vec3 p = mesh->positions[i];
      mesh->normals[i] = glm::normalize(glm::vec3(0.8f * std::sin(0.05f * p.x + 0.02f * p.y), 0.8f * std::cos(0.04f * p.y), 1.0f));
    }
    o.mesh = mesh;
  }
  scene.lights = {Light{LightType::directional, glm::normalize(glm::vec3(0.4f, -0.3f, -1.0f)), {}, glm::vec3(1.0f)}};
  scene.ambient_light = glm::vec3(1.0f);
  scene.materials = {Material{"lit", glm::vec3(0.1f), glm::vec3(0.55f), glm::vec3(0.3f), 8.0f}};
  for (Object& o : scene.objects) o.material = 0;
  return scene;
}

// The widest box of the frame's triangles, at most the frame's width, pixels: no span is longer.
int widest_span(const ScreenGeometry& g, int width) {
  int widest = 1;
  for (const glm::uvec3& t : g.triangles) {
    const double x[3] = {double(g.xy[t.x].x), double(g.xy[t.y].x), double(g.xy[t.z].x)};
    const double lo = std::min({x[0], x[1], x[2]}) / kSubpixel, hi = std::max({x[0], x[1], x[2]}) / kSubpixel;
    widest = std::max(widest, int(std::ceil(hi) - std::floor(lo)) + 1);
  }
  return std::min(widest, width);
}

TEST_P(HardScene, RendersInFloatAndFixedPointWithinTheErrorBound) {
  const Scene scene = with_varying_normals(hard_scene(GetParam().name));
  Renderer renderer(test_device(), render_options(Method::gouraud, true, 16));
  const Frame& frame = renderer.render(scene);
  ASSERT_EQ(frame.image.rgba.size(), std::size_t(scene.width) * scene.height * 4);
  ScreenGeometry geometry;
  build_screen_geometry(scene, {Method::gouraud, true}, geometry);
  const ReferenceImage reference = render_reference(scene, geometry, Method::gouraud);
  // The bound must have something to bind: the reference spans levels, and no value is clamped.
  double lo = 255, hi = 0;
  for (std::size_t p = 0; p < reference.ideal.size(); ++p)
    if (reference.covered[p]) lo = std::min(lo, reference.ideal[p].x), hi = std::max(hi, reference.ideal[p].x);
  EXPECT_GT(hi - lo, 2.0) << "the reference is (nearly) one colour: the bound would not bind";
  EXPECT_GT(lo, 0.0);
  EXPECT_LT(hi, 255.0);

  const ErrorMetrics e = compare_to_reference(frame.image, reference.covered, reference.ideal, "ideal");
  const double bound = gouraud_bound(geometry);
  RecordProperty("bound_levels", std::to_string(bound));
  RecordProperty("max_abs_levels", std::to_string(e.max_abs));
  EXPECT_GT(e.pixels_compared, 0u);
  EXPECT_EQ(e.coverage_mismatch, 0u);
  // Coplanar included: the reference breaks exact depth ties for the earlier triangle as the kernel does
  // (before, its barycentric rounding picked the later quad on 336 of the 3 200 overlap pixels).
  EXPECT_LE(e.max_abs, bound) << "pixels compared " << e.pixels_compared << ", over one level " << e.pixels_over_1_level;

  // Fixed point through the classic unit: the float output holds the span register in levels (exact for
  // I + F <= 24), within the register model's bound (1 + z)(h + e) at pixel z of a span (docs/unit-error.md),
  // largest for the widest span.
  RenderOptions fixed = render_options(Method::gouraud, true, 16);
  fixed.arith = parse_arith("fixed:10.4");
  Renderer fixed_renderer(test_device(), fixed);
  const Frame& fixed_frame = fixed_renderer.render(scene);
  const ErrorMetrics f = compare_to_reference(fixed_frame.image, reference.covered, reference.ideal, "ideal");
  const int widest = widest_span(geometry, scene.width);
  const double fixed_bound = unit_error_bound(UnitConfig{}, fixed.arith, widest, widest - 1);
  RecordProperty("fixed_bound_levels", std::to_string(fixed_bound));
  RecordProperty("fixed_max_abs_levels", std::to_string(f.max_abs));
  EXPECT_EQ(f.coverage_mismatch, 0u);
  EXPECT_GT(f.max_abs, 0.0) << "fixed:10.4 cannot represent every value exactly";
  EXPECT_LE(f.max_abs, fixed_bound) << "widest span " << widest << " pixels";
}

const HardCase kPlanar[] = {{"slivers", 400},           {"fan", 10000},         {"one_pixel", 400 + 16},
                            {"pixel_centres", 19 * 19}, {"big", 256 * 192},     {"limit_12bit", 4096 * 8 + 64}};
const HardCase kOthers[] = {{"t_junction", 0}, {"coplanar", 0}, {"back_faces", 0}, {"near_plane", 0}};
const auto kName = [](const auto& info) { return std::string(info.param.name); };

INSTANTIATE_TEST_SUITE_P(Scenes, PlanarTiling, ::testing::ValuesIn(kPlanar), kName);
INSTANTIATE_TEST_SUITE_P(Planar, HardScene, ::testing::ValuesIn(kPlanar), kName);
INSTANTIATE_TEST_SUITE_P(Others, HardScene, ::testing::ValuesIn(kOthers), kName);

// The T-junction covers exactly the pixels of the same diamond made of two triangles without one.
TEST(HardScenes, TJunctionCoversTheSamePixelsAsItsOutline) {
  const Scene scene = hard_scene("t_junction");
  auto outline = std::make_shared<Mesh>();
  outline->positions = {{-40, 0, 0}, {40, 0, 0}, {0, -40, 0}, {0, 40, 0}};
  outline->triangles = {{0, 2, 1}, {0, 1, 3}};
  compute_vertex_normals(*outline);
  Scene plain = scene;
  plain.objects.clear();
  add_object(plain, outline);
  Renderer renderer(test_device(), render_options(Method::flat, false, 16));
  const std::vector<std::uint32_t> t = renderer.coverage_counts(scene);
  const std::vector<std::uint32_t> o = renderer.coverage_counts(plain);
  EXPECT_EQ(summarize(t).most, 1u);
  EXPECT_GT(summarize(o).covered, 3000u);
  EXPECT_TRUE(t == o) << "the T-junction leaves a crack or a double hit";
}

// Coplanar overlapping quads: a depth tie goes to the earlier triangle (the first object, red), in the
// kernel as in the reference, and the image does not depend on tile size or work-items.
TEST(HardScenes, CoplanarDepthTiesGoToTheEarlierTriangleDeterministically) {
  const Scene scene = hard_scene("coplanar");
  Renderer reference_renderer(test_device(), render_options(Method::gouraud, false, 16));
  const auto& first = reference_renderer.render(scene).image.rgba;
  const std::vector<std::uint8_t> image(first.begin(), first.end());
  // The overlap [-20, 20] x [-40, 40]: screen columns 108..147, rows 56..135.
  std::size_t red = 0;
  for (int y = 56; y < 136; ++y)
    for (int x = 108; x < 148; ++x) {
      const std::size_t p = (std::size_t(y) * scene.width + x) * 4;
      red += image[p] > 4 * image[p + 2];
    }
  EXPECT_EQ(red, 40u * 80u) << "the earlier (red) quad must win every tie";
  for (int tile : {32, 64})
    for (int items : {1, 5}) {
      RenderOptions o = render_options(Method::gouraud, false, tile);
      o.work_items = items;
      Renderer renderer(test_device(), o);
      const auto& rgba = renderer.render(scene).image.rgba;
      EXPECT_TRUE(std::equal(rgba.begin(), rgba.end(), image.begin(), image.end())) << "tile " << tile << ", work-items " << items;
    }
}

// The clockwise quad is culled (background where it lies); the closed sphere beside it is watertight
// with back-face culling: front faces cover each pixel of its outline once, and exactly where the
// back faces (the flipped mesh) do.
TEST(HardScenes, BackFacesAreCulledAndTheClosedSphereIsWatertight) {
  Scene scene = hard_scene("back_faces");
  Renderer renderer(test_device(), render_options(Method::gouraud, false, 16));
  const auto& rgba = renderer.render(scene).image.rgba;
  const std::vector<std::uint8_t> image(rgba.begin(), rgba.end());
  const std::size_t centre = (std::size_t(scene.height / 2) * scene.width + scene.width / 2) * 4;
  EXPECT_EQ(image[centre] + image[centre + 1] + image[centre + 2], 0) << "a culled back face was drawn";
  scene.cull_backfaces = false;
  EXPECT_GT(renderer.render(scene).image.rgba[centre], 0) << "without culling the quad shows";

  Scene front = hard_scene("back_faces"), back = front;
  front.objects.erase(front.objects.begin());  // the sphere alone
  back.objects = front.objects;
  Mesh flipped = *back.objects[0].mesh;
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  for (auto& n : flipped.normals) n = -n;
  back.objects[0].mesh = std::make_shared<const Mesh>(flipped);
  Renderer counter(test_device(), render_options(Method::flat, false, 16));
  const std::vector<std::uint32_t> f = counter.coverage_counts(front), b = counter.coverage_counts(back);
  EXPECT_GT(summarize(f).covered, 1000u);
  EXPECT_EQ(summarize(f).most, 1u);
  EXPECT_TRUE(f == b) << "front and back faces of the closed sphere cover different pixels";
}

// The ground quad runs under and behind the camera, crossing the near plane: clipped, it covers every
// pixel of the bottom row and none of the top row, each at most once.
TEST(HardScenes, TrianglesCrossingTheNearPlaneAreClipped) {
  const Scene scene = hard_scene("near_plane");
  Renderer renderer(test_device(), render_options(Method::flat, false, 16));
  const std::vector<std::uint32_t> c = renderer.coverage_counts(scene);
  EXPECT_EQ(summarize(c).most, 1u);
  std::size_t bottom = 0, top = 0;
  for (int x = 0; x < scene.width; ++x) {
    bottom += c[std::size_t(scene.height - 1) * scene.width + x];
    top += c[std::size_t(x)];
  }
  EXPECT_EQ(bottom, std::size_t(scene.width));
  EXPECT_EQ(top, 0u);
}

}  // namespace
}  // namespace parashade
