// The unit kernels in fixed point against the golden models, bit for bit: every covered pixel's span
// register (read back through the float image, exact while I + F <= 24) equals what the golden model
// of its unit holds for it after stepping the span clock by clock, and the frame's modeled clocks
// equal the golden models' clocks summed over the spans.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "cl_fixture.hpp"
#include "parashade/dda_coverage.hpp"
#include "parashade/errors.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/golden_units.hpp"
#include "parashade/lighting.hpp"
#include "parashade/reference.hpp"
#include "parashade/renderer.hpp"
#include "parashade/setup.hpp"
#include "parashade/sierpinski_setup.hpp"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

using namespace testing_support;

// Triangles in a grid of cells, one per cell and inside it, so none overlap (visibility cannot blur
// the comparison); sizes from one pixel to the cell.
std::shared_ptr<Mesh> grid_triangles(int width, int height, int cell, std::mt19937& rng) {
  auto mesh = std::make_shared<Mesh>();
  std::uniform_real_distribution<float> u(0.0f, float(cell) - 0.01f), un(-1.0f, 1.0f), uz(-5.0f, 5.0f);
  for (int cy = 0; cy + cell <= height; cy += cell) {
    for (int cx = 0; cx + cell <= width; cx += cell) {
      const std::uint32_t base = std::uint32_t(mesh->positions.size());
      const float scale = std::uniform_real_distribution<float>(0.1f, 2.0f)(rng);
      for (int k = 0; k < 3; ++k) {
        const float x = float(cx) + std::min(u(rng) * scale, float(cell) - 0.01f) - 0.5f * width;
        const float y = 0.5f * height - float(cy) - std::min(u(rng) * scale, float(cell) - 0.01f);
        mesh->positions.push_back({x, y, uz(rng)});
        mesh->normals.push_back(glm::normalize(glm::vec3(un(rng), un(rng), 1.2f + std::abs(un(rng)))));
      }
      mesh->triangles.push_back({base, base + 1, base + 2});
    }
  }
  return mesh;
}

struct Span {
  int xl = 1, xr = 0;  // relative to the record's x0; empty when xl > xr
};

// Covered pixels of row dy of a record, straight from the definition of its edge functions.
Span record_span(const TriangleGeometry& t, int dy) {
  Span s;
  for (int dx = 0; dx <= t.x1 - t.x0; ++dx) {
    bool inside = true;
    for (int e = 0; e < 3; ++e) inside &= t.edge_c[e] + std::int64_t(t.edge_a[e]) * dx + std::int64_t(t.edge_b[e]) * dy >= 0;
    if (!inside) continue;
    if (s.xl > s.xr) s.xl = dx;
    s.xr = dx;
  }
  return s;
}

struct Check {
  std::uint64_t pixels = 0, mismatches = 0, golden_clocks = 0, spans = 0;
};

// Setup's records for the renderer's last frame, as the kernel got them: one per screen triangle, or
// one per sub-triangle for the sierpinski unit.
struct Records {
  std::vector<TriangleGeometry> geometry;
  std::vector<FixedPlanes> planes;
  std::vector<SierpinskiLeaf> leaves;
  DdaRowTable dda;  // --coverage dda: the spans
  Span span(std::size_t t, int dy) const {
    if (dda.first.empty()) return record_span(geometry[t], dy);
    const std::size_t at = 2 * (dda.first[t] + std::size_t(dy));
    return {dda.rows[at], dda.rows[at + 1]};
  }
};

Records frame_records(const ScreenGeometry& g, const UnitConfig& unit, bool dda_coverage = false,
                      Method method = Method::gouraud, std::vector<float>* attrs_out = nullptr) {
  const std::size_t n = g.triangles.size();
  Records r;
  r.geometry.resize(n);
  r.planes.resize(n);
  std::vector<float> attrs(n * attribute_floats(method));
  setup_triangles(g, method, r.geometry.data(), attrs.data(), r.planes.data());
  if (attrs_out) *attrs_out = attrs;
  if (dda_coverage) r.dda = apply_dda_coverage(g, r.geometry.data(), attrs.data(), r.planes.data());
  if (unit.kind != UnitKind::sierpinski) return r;
  const std::size_t m = n << (2 * unit.depth);
  Records split;
  split.geometry.resize(m);
  split.planes.resize(m);
  split.leaves.resize(m);
  std::vector<float> split_attrs(m * GOURAUD_ATTR_FLOATS);
  split_sierpinski(g, unit, r.geometry.data(), attrs.data(), r.planes.data(), split.geometry.data(), split_attrs.data(),
                   split.planes.data(), split.leaves.data());
  return split;
}

Check compare_with_golden(const Scene& scene, const UnitConfig& unit, const Arithmetic& arith,
                          const SpanDivision& division = {}, bool dda_coverage = false) {
  RenderOptions o;
  o.method = Method::gouraud;
  o.float_output = true;
  o.units = unit;
  o.arith = arith;
  o.division = division;
  o.dda_coverage = dda_coverage;
  Renderer renderer(test_device(), o);
  const Frame& frame = renderer.render(scene);
  const Records records = frame_records(renderer.geometry(), unit, dda_coverage);

  // Golden values per pixel and channel: normally one; a pixel that two sub-triangles of the
  // sierpinski unit both cover may take either (equal depths: whichever the kernel kept).
  Check c;
  const std::size_t slots = 3 * std::size_t(scene.width) * scene.height;
  std::vector<std::uint8_t> candidates(slots, 0);  // golden values per pixel and channel
  std::vector<std::int32_t> golden_at(slots);
  std::multimap<std::size_t, std::int32_t> more;   // second and further values (overlaps)
  for (std::size_t t = 0; t < records.geometry.size(); ++t) {
    const TriangleGeometry& r = records.geometry[t];
    if (r.x0 > r.x1) continue;
    const SierpinskiLeaf* leaf = records.leaves.empty() ? nullptr : &records.leaves[t];
    for (int dy = 0; dy <= r.y1 - r.y0; ++dy) {
      const Span s = records.span(t, dy);
      if (s.xl > s.xr) continue;
      const bool costs = !leaf || leaf->shaded;
      c.spans += costs;
      for (int ch = 0; ch < 3; ++ch) {
        const SpanTrace golden = run_unit(unit, arith, load_span(records.planes[t], ch, s.xl, s.xr, dy, unit, arith, leaf, division));
        if (ch == 0 && costs) c.golden_clocks += SPAN_LOAD_CLOCKS + golden.clocks;
        for (int i = 0; i < int(golden.values.size()); ++i) {
          const std::size_t p = std::size_t(r.y0 + dy) * scene.width + std::size_t(r.x0 + s.xl + i);
          const std::size_t at = 3 * p + std::size_t(ch);
          if (candidates[at]++ == 0) golden_at[at] = golden.values[std::size_t(i)];
          else more.emplace(at, golden.values[std::size_t(i)]);
        }
      }
    }
  }
  const double scale = double(1 << arith.frac_bits);
  for (std::size_t at = 0; at < slots; ++at) {
    if (candidates[at] == 0) continue;
    const double kernel = double(frame.image.rgb_float[at]) * scale;
    ++c.pixels;
    bool match = double(golden_at[at]) == kernel;
    for (auto [it, end] = more.equal_range(at); it != end && !match; ++it) match = double(it->second) == kernel;
    if (!match || !frame.image.covered(at / 3)) {
      if (c.mismatches++ < 5)
        ADD_FAILURE() << unit_name(unit) << " " << arith_name(arith) << ": pixel " << at / 3 << " channel " << at % 3
                      << ": kernel " << kernel << ", golden " << golden_at[at] << " (" << int(candidates[at])
                      << " candidates)";
    }
  }
  EXPECT_EQ(frame.stats.clocks.clocks, c.golden_clocks) << unit_name(unit);
  EXPECT_EQ(frame.stats.clocks.spans, c.spans) << unit_name(unit);
  return c;
}

// Phong through a unit: the registers carry the normal's components (x NORMAL_REGISTER_LEVELS). The golden
// model steps them clock by clock; the host shades its normals in double (lighting.hpp, written apart from
// the kernels) and the kernel's unclamped float output must agree within float rounding. Coarse formats
// must visibly differ from plain Phong, or the registers would not be what shades the pixels.
TEST(PhongUnitGolden, KernelShadesTheGoldenModelsNormals) {
  std::mt19937 rng(17);
  Scene scene = pixel_scene(401, 233);
  add_object(scene, grid_triangles(401, 233, 29, rng));
  RenderOptions plain_options;
  plain_options.method = Method::phong;
  plain_options.float_output = true;
  Renderer plain(test_device(), plain_options);
  const std::vector<float> phong = plain.render(scene).image.rgb_float;
  const struct {
    const char *unit, *arith, *division;
    int expect;  // +1: 1-2 fraction bits must show against float Phong; -1: 12 bits must not; 0: not asserted
  } cases[] = {{"classic", "fixed:12.12", "constant", -1}, {"counter", "fixed:9.2", "constant", 1},
               {"interleave:3", "fixed:9.1", "constant", 1}, {"interleave:2:own", "fixed:9.3", "constant", 0},
               {"segment:16", "fixed:10.4", "constant", 0}, {"classic", "fixed:10.6", "shiftadd:6", 0}};
  for (const auto& k : cases) {
    RenderOptions o;
    o.method = Method::phong;
    o.float_output = true;
    o.units = parse_units(k.unit);
    o.arith = parse_arith(k.arith);
    o.division = parse_division(k.division);
    Renderer renderer(test_device(), o);
    const Frame& frame = renderer.render(scene);
    std::vector<float> attrs;
    const Records records = frame_records(renderer.geometry(), *o.units, false, Method::phong, &attrs);
    const double scale = NORMAL_REGISTER_LEVELS * double(1 << o.arith.frac_bits);
    double worst = 0, from_phong = 0;
    std::uint64_t pixels = 0;
    for (std::size_t t = 0; t < records.geometry.size(); ++t) {
      const TriangleGeometry& r = records.geometry[t];
      if (r.x0 > r.x1) continue;
      const float* a = &attrs[t * PHONG_ATTR_FLOATS];
      const Material& m = scene.materials[std::size_t(a[PHONG_MATERIAL_SLOT])];
      for (int dy = 0; dy <= r.y1 - r.y0; ++dy) {
        const Span s = record_span(r, dy);
        if (s.xl > s.xr) continue;
        SpanTrace n[3];
        for (int c = 0; c < 3; ++c)
          n[c] = run_unit(*o.units, o.arith, load_span(records.planes[t], c, s.xl, s.xr, dy, *o.units, o.arith, nullptr, o.division));
        for (int i = 0; i <= s.xr - s.xl; ++i) {
          const glm::dvec3 normal(n[0].values[i] / scale, n[1].values[i] / scale, n[2].values[i] / scale);
          if (glm::length(normal) < 1e-3) continue;  // the kernel's zero-normal fallback is tested elsewhere
          const double rel = s.xl + i;
          const auto plane = [&](int slot) { return double(a[slot]) + double(a[slot + 6]) * dy + double(a[slot + 3]) * rel; };
          const glm::dvec3 golden = blinn_phong(scene, m, {plane(9), plane(10), plane(11)}, glm::normalize(normal));
          const std::size_t p = std::size_t(r.y0 + dy) * scene.width + std::size_t(r.x0 + s.xl + i);
          for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::abs(double(frame.image.rgb_float[3 * p + c]) - golden[c]));
            from_phong = std::max(from_phong, std::abs(double(frame.image.rgb_float[3 * p + c]) - double(phong[3 * p + c])));
          }
          ++pixels;
        }
      }
    }
    RecordProperty(std::string(k.unit) + "_" + k.arith + "_max_vs_phong", std::to_string(from_phong));
    EXPECT_GT(pixels, 5000u) << k.unit << " " << k.arith;
    EXPECT_LT(worst, 0.02) << k.unit << " " << k.arith << " " << k.division << ": kernel vs golden normals, levels";
    std::printf("phong %s %s %s: max %.3f levels from float Phong, %.4f from the golden normals\n", k.unit, k.arith,
                k.division, from_phong, worst);
    if (k.expect > 0) EXPECT_GT(from_phong, 1.0) << k.unit << " " << k.arith << ": registers seem not to shade the pixels";
    if (k.expect < 0) EXPECT_LT(from_phong, 1.0) << k.unit << " " << k.arith << ": fine registers should stay near float Phong";
  }
}

TEST(PhongUnits, SierpinskiAndFlatAreRefused) {
  RenderOptions o;
  o.method = Method::phong;
  o.units = parse_units("sierpinski:1");
  EXPECT_THROW(Renderer renderer(test_device(), o), UsageError);
  o.method = Method::flat;
  o.units = parse_units("classic");
  EXPECT_THROW(Renderer renderer(test_device(), o), UsageError);
}

// Every unit of the table, in each configuration its row names for the golden tests.
std::vector<std::string> golden_test_units() {
  std::vector<std::string> specs;
  for (const UnitRow& row : unit_table()) specs.insert(specs.end(), row.golden_tests.begin(), row.golden_tests.end());
  return specs;
}

class UnitGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(UnitGolden, KernelEqualsGoldenModelOnRandomTriangles) {
  std::mt19937 rng(11);
  Scene scene = pixel_scene(525, 301);  // odd sizes: partial tiles and segments
  add_object(scene, grid_triangles(525, 301, 29, rng));
  const UnitConfig unit = parse_units(GetParam());
  for (const char* arith : {"fixed:12.12", "fixed:9.3", "fixed:16.8"}) {
    const Check c = compare_with_golden(scene, unit, parse_arith(arith));
    EXPECT_GT(c.pixels, 3u * 5000u) << "too few pixels to mean much";
    EXPECT_EQ(c.mismatches, 0u) << GetParam() << " " << arith << " over " << c.pixels << " register values";
  }
}

INSTANTIATE_TEST_SUITE_P(Units, UnitGolden, ::testing::ValuesIn(golden_test_units()),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& ch : s) if (ch == ':') ch = '_';
                           return s;
                         });

// A division per span (exact, or by shifts and adds as the host's independent implementation forms it).
TEST(UnitGoldenDivision, KernelEqualsGoldenModelWithADivisionPerSpan) {
  std::mt19937 rng(13);
  Scene scene = pixel_scene(525, 301);
  add_object(scene, grid_triangles(525, 301, 29, rng));
  const std::pair<const char*, const char*> cases[] = {{"classic", "exact"},        {"classic", "shiftadd:8"},
                                                       {"classic", "shiftadd:5:trunc"}, {"counter", "shiftadd:8"},
                                                       {"segment:8", "exact"},      {"interleave:3", "shiftadd:12"}};
  for (const auto& [unit, division] : cases) {
    const Check c = compare_with_golden(scene, parse_units(unit), parse_arith("fixed:12.10"), parse_division(division));
    EXPECT_GT(c.pixels, 3u * 5000u);
    EXPECT_EQ(c.mismatches, 0u) << unit << " --div " << division;
  }
}

// --coverage dda: the spans of the sources' edge walk (host row table) through the same units.
TEST(UnitGoldenDda, KernelEqualsGoldenModelOnEdgeWalkedSpans) {
  std::mt19937 rng(17);
  Scene scene = pixel_scene(525, 301);
  add_object(scene, grid_triangles(525, 301, 29, rng));
  for (const char* unit : {"classic", "counter", "interleave:3:own", "segment:16"}) {
    const Check c = compare_with_golden(scene, parse_units(unit), parse_arith("fixed:12.12"), {}, true);
    EXPECT_GT(c.pixels, 3u * 5000u);
    EXPECT_EQ(c.mismatches, 0u) << unit << " --coverage dda";
  }
}

// One right triangle over a 4096 x 4096 screen: its rows have every span length from 1 to 4096 (odd and
// even, M not dividing them, P larger than the short ones), and its vertices sit at the 12-bit edge.
TEST(UnitGoldenLimits, EverySpanLengthUpTo4096AtTheAddressLimit) {
  Scene scene = pixel_scene(4096, 4096);
  auto mesh = std::make_shared<Mesh>();
  // The hypotenuse ends 0.3 pixel beyond the right edge, so row j covers exactly j + 1 pixel centres.
  mesh->positions = {{-2048.0f, 2048.0f, 0.0f}, {2048.3f, -2048.0f, 1.0f}, {-2048.0f, -2048.0f, -2.0f}};
  mesh->normals = {glm::normalize(glm::vec3(0.9f, 0.1f, 0.4f)), glm::normalize(glm::vec3(-0.5f, 0.2f, 1.0f)),
                   glm::normalize(glm::vec3(0.1f, -0.8f, 0.6f))};
  mesh->triangles = {{0, 1, 2}};
  add_object(scene, mesh);
  for (const char* u : {"counter", "interleave:3:own", "segment:64"}) {
    const Check c = compare_with_golden(scene, parse_units(u), parse_arith("fixed:10.14"));
    EXPECT_EQ(c.spans, 4096u) << u;
    EXPECT_EQ(c.mismatches, 0u) << u;
  }
}

}  // namespace
}  // namespace parashade

namespace parashade {
namespace {

// Triangles whose vertices already sit on pixel corners that are multiples of 2^depth, so parity
// normalization moves nothing and the sub-triangles' coverage can be held against the triangles' own.
std::shared_ptr<Mesh> corner_triangles(int width, int height, int cell, int depth, std::mt19937& rng) {
  auto mesh = std::make_shared<Mesh>();
  const int step = 1 << depth;
  std::uniform_int_distribution<int> u(0, (cell - 1) / step);
  for (int cy = 0; cy + cell <= height; cy += cell) {
    for (int cx = 0; cx + cell <= width; cx += cell) {
      const std::uint32_t base = std::uint32_t(mesh->positions.size());
      for (int k = 0; k < 3; ++k) {
        mesh->positions.push_back({float(cx + step * u(rng) - width / 2), float(height / 2 - cy - step * u(rng)), 0.0f});
        mesh->normals.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
      }
      mesh->triangles.push_back({base, base + 1, base + 2});
    }
  }
  return mesh;
}

struct CoverageComparison {
  std::uint64_t covered = 0, holes = 0, doubled = 0, outside = 0;
};

CoverageComparison sub_triangle_coverage(const Scene& scene, const char* unit_spec) {
  const UnitConfig unit = parse_units(unit_spec);
  RenderOptions o;
  o.method = Method::gouraud;
  o.units = unit;
  o.arith = parse_arith("fixed:12.12");
  Renderer renderer(test_device(), o);
  renderer.render(scene);
  const Records records = frame_records(renderer.geometry(), unit);
  std::vector<int> count(std::size_t(scene.width) * scene.height, 0);
  for (const TriangleGeometry& r : records.geometry) {
    if (r.x0 > r.x1) continue;
    for (int dy = 0; dy <= r.y1 - r.y0; ++dy) {
      const Span s = record_span(r, dy);
      for (int x = s.xl; x <= s.xr; ++x) ++count[std::size_t(r.y0 + dy) * scene.width + std::size_t(r.x0 + x)];
    }
  }
  ScreenGeometry g;
  build_screen_geometry(scene, {Method::gouraud, true}, g);
  const ReferenceImage ref = render_reference(scene, g, Method::gouraud);
  CoverageComparison c;
  for (std::size_t p = 0; p < count.size(); ++p) {
    c.covered += ref.covered[p];
    c.holes += ref.covered[p] && count[p] == 0;
    c.doubled += count[p] > 1;
    c.outside += !ref.covered[p] && count[p] > 0;
  }
  return c;
}

// With vertices already normalized, the sub-triangles never reach outside their triangle. Mirroring the
// top-left rule leaves centres on the midlines covered twice or not at all; `seal` covers the triangle
// exactly once, pixel for pixel.
TEST(SierpinskiCoverage, MirroredRuleLeavesHolesOnMidlinesSealCoversExactlyOnce) {
  for (int depth : {1, 2}) {
    std::mt19937 rng(5 + depth);
    Scene scene = pixel_scene(320, 240);
    add_object(scene, corner_triangles(320, 240, 40, depth, rng));
    const std::string d = std::to_string(depth);
    const CoverageComparison mirrored = sub_triangle_coverage(scene, ("sierpinski:" + d).c_str());
    const CoverageComparison sealed = sub_triangle_coverage(scene, ("sierpinski:" + d + ":seal").c_str());
    RecordProperty("depth" + d + "_mirrored_holes", std::to_string(mirrored.holes));
    RecordProperty("depth" + d + "_mirrored_doubled", std::to_string(mirrored.doubled));
    EXPECT_GT(sealed.covered, 3000u);
    EXPECT_EQ(mirrored.outside, 0u) << "depth " << depth;
    EXPECT_GT(mirrored.holes + mirrored.doubled, 0u) << "depth " << depth << ": the mirrored rule should show its seams";
    EXPECT_EQ(sealed.outside, 0u) << "depth " << depth;
    EXPECT_EQ(sealed.holes, 0u) << "depth " << depth;
    EXPECT_EQ(sealed.doubled, 0u) << "depth " << depth;
  }
}

// Pixel-corner triangles (vertices anywhere on the pixel grid, increments odd and even).
std::shared_ptr<Mesh> pixel_corner_triangles(int width, int height, int cell, std::mt19937& rng) {
  return corner_triangles(width, height, cell, 0, rng);
}

// Remedy (b) rounds the halves only where they are not whole pixels: on geometry already normalized for
// the depth, touch and overlap must give exactly the records of remedy (a).
TEST(SierpinskiHalves, EqualParityNormalizationWhenHalvesAreExact) {
  for (int depth : {1, 2, 3}) {
    std::mt19937 rng(21 + depth);
    Scene scene = pixel_scene(320, 240);
    add_object(scene, corner_triangles(320, 240, 40, depth, rng));
    ScreenGeometry g;
    build_screen_geometry(scene, {Method::gouraud, false}, g);
    const std::string d = std::to_string(depth);
    const Records exact = frame_records(g, parse_units(("sierpinski:" + d + ":even:seal").c_str()));
    for (const char* grid : {":touch:seal", ":overlap:seal"}) {
      const Records halves = frame_records(g, parse_units(("sierpinski:" + d + grid).c_str()));
      ASSERT_EQ(halves.geometry.size(), exact.geometry.size());
      EXPECT_EQ(0, std::memcmp(halves.geometry.data(), exact.geometry.data(),
                               exact.geometry.size() * sizeof(TriangleGeometry))) << "depth " << depth << grid;
      EXPECT_EQ(0, std::memcmp(halves.planes.data(), exact.planes.data(), exact.planes.size() * sizeof(FixedPlanes)))
          << "depth " << depth << grid;
      EXPECT_EQ(0, std::memcmp(halves.leaves.data(), exact.leaves.data(), exact.leaves.size() * sizeof(SierpinskiLeaf)))
          << "depth " << depth << grid;
    }
  }
}

// On odd increments the halves cannot tile an edge: touching halves leave it a pixel short (holes on
// midlines and along the far edges), overlapping ones reach every vertex and cover the midlines twice.
// The figures are recorded (docs/units.md); the construction's seams must show.
TEST(SierpinskiHalves, OddEdgesShowTheirSeams) {
  for (int depth : {1, 2}) {
    std::mt19937 rng(31 + depth);
    Scene scene = pixel_scene(320, 240);
    add_object(scene, pixel_corner_triangles(320, 240, 40, rng));
    const std::string d = std::to_string(depth);
    const CoverageComparison touch = sub_triangle_coverage(scene, ("sierpinski:" + d + ":touch:seal").c_str());
    const CoverageComparison overlap = sub_triangle_coverage(scene, ("sierpinski:" + d + ":overlap:seal").c_str());
    for (const auto& [name, c] : {std::pair{"touch", touch}, std::pair{"overlap", overlap}}) {
      const std::string key = "depth" + d + "_" + name + "_";
      RecordProperty(key + "covered", std::to_string(c.covered));
      RecordProperty(key + "holes", std::to_string(c.holes));
      RecordProperty(key + "doubled", std::to_string(c.doubled));
      RecordProperty(key + "outside", std::to_string(c.outside));
      std::printf("sierpinski:%d:%s:seal  covered %llu  holes %llu  doubled %llu  outside %llu\n", depth, name,
                  (unsigned long long)c.covered, (unsigned long long)c.holes, (unsigned long long)c.doubled,
                  (unsigned long long)c.outside);
    }
    EXPECT_GT(touch.covered, 3000u);
    EXPECT_GT(touch.holes, 0u) << "depth " << depth;
    EXPECT_GT(overlap.doubled, 0u) << "depth " << depth;
    EXPECT_LT(overlap.holes, touch.holes) << "depth " << depth;
  }
}

}  // namespace
}  // namespace parashade
