// The combined method's per-triangle choice (triangle_choice.hpp): a triangle given to Gouraud must stay
// within the shading budget of Phong (screen-linear normals and positions, as the kernel interpolates),
// checked by dense sampling in double precision; the sources' listing as printed and as intended.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "parashade/geometry_stage.hpp"
#include "parashade/light_bounds_lanes.hpp"
#include "parashade/lighting.hpp"
#include "parashade/shapes.hpp"
#include "parashade/triangle_choice.hpp"
#include "test_support.hpp"

namespace parashade {
namespace {

// A tessellated sphere and a teapot in perspective with a local viewer, a directional and a nearby
// point light; `jitter` perturbs the vertex normals so that some triangles shade unevenly.
Scene lit_scene(std::uint32_t seed, float jitter, float shininess) {
  Scene s;
  s.name = "choice";
  s.width = 480;
  s.height = 360;
  testing_support::set_perspective(s.camera, {0.0f, 1.0f, 6.0f}, {0.0f, 0.2f, 0.0f}, 40.0f, 0.5f, 30.0f);
  s.local_viewer = true;
  Light sun;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.6f));
  sun.color = {0.9f, 0.9f, 0.85f};
  Light lamp;
  lamp.type = LightType::point;
  lamp.position = {-2.5f, 1.5f, 2.5f};
  lamp.color = {0.4f, 0.45f, 0.6f};
  s.lights = {sun, lamp};
  Material m;
  m.ambient = {0.1f, 0.1f, 0.1f};
  m.diffuse = {0.7f, 0.6f, 0.5f};
  m.specular = {0.5f, 0.5f, 0.5f};
  m.shininess = shininess;
  s.materials = {m};
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, jitter);
  auto sphere = std::make_shared<Mesh>(make_sphere(48, 24));
  auto teapot = std::make_shared<Mesh>(make_teapot(6));
  for (auto* mesh : {sphere.get(), teapot.get()})
    for (glm::vec3& n : mesh->normals) n = glm::normalize(n + glm::vec3(noise(rng), noise(rng), noise(rng)));
  Object a, b;
  a.name = "sphere";
  a.mesh = sphere;
  a.model = glm::translate(glm::mat4(1.0f), glm::vec3(-1.2f, 0.0f, 0.0f));
  b.name = "teapot";
  b.mesh = teapot;
  b.model = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.2f, -0.5f, 0.0f)), glm::vec3(0.5f));
  s.objects = {a, b};
  return s;
}

// Largest |Gouraud - Phong| over the triangle (largest channel, clamped to the 8-bit range as the image
// is), sampled on a barycentric grid in screen space.
double sampled_error(const Scene& s, const ScreenGeometry& g, std::size_t t) {
  const glm::uvec3 idx = g.triangles[t];
  const std::uint32_t v[3] = {idx.x, idx.y, idx.z};
  const Material& m = s.materials[g.material[t]];
  glm::dvec3 vertex[3], n[3], w[3];
  for (int k = 0; k < 3; ++k) {
    n[k] = glm::dvec3(g.normal[v[k]]);
    w[k] = glm::dvec3(g.world[v[k]]);
    vertex[k] = blinn_phong(s, m, w[k], glm::normalize(n[k]));
  }
  const auto clamp8 = [](glm::dvec3 c) { return glm::clamp(c, glm::dvec3(0.0), glm::dvec3(255.0)); };
  double worst = 0.0;
  const int steps = 24;
  for (int a = 0; a <= steps; ++a)
    for (int b = 0; a + b <= steps; ++b) {
      const double b0 = double(a) / steps, b1 = double(b) / steps, b2 = 1.0 - b0 - b1;
      const glm::dvec3 gouraud = b0 * vertex[0] + b1 * vertex[1] + b2 * vertex[2];
      const glm::dvec3 normal = glm::normalize(b0 * n[0] + b1 * n[1] + b2 * n[2]);
      const glm::dvec3 phong = blinn_phong(s, m, b0 * w[0] + b1 * w[1] + b2 * w[2], normal);
      const glm::dvec3 d = glm::abs(clamp8(gouraud) - clamp8(phong));
      worst = std::max({worst, d.x, d.y, d.z});
    }
  return worst;
}

struct Case {
  std::uint32_t seed;
  float jitter, shininess;
  double budget;
};

// The case's scene, its screen geometry and the bound rule of combined:auto.
class TriangleChoiceBound : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    k = GetParam();
    s = lit_scene(k.seed, k.jitter, k.shininess);
    build_screen_geometry(s, {Method::combined, true, true}, g);
    c.automatic = true;
    c.rule = TriangleRule::bound;
  }
  Case k;
  Scene s;
  ScreenGeometry g;
  CombinedConfig c;
};

// Both ways of computing the bounds: the float lanes the renderer uses and the double reference.
TEST_P(TriangleChoiceBound, GouraudOnlyWhereTheSampledErrorFits) {
  std::vector<double> sampled(g.triangles.size());
  for (std::size_t t = 0; t < g.triangles.size(); ++t) sampled[t] = sampled_error(s, g, t);
  for (const ChoiceArithmetic arithmetic : {ChoiceArithmetic::float_lanes, ChoiceArithmetic::double_reference}) {
    const bool lanes = arithmetic == ChoiceArithmetic::float_lanes;
    SCOPED_TRACE(lanes ? "float lanes" : "double reference");
    std::vector<TriangleShading> out;
    const TriangleChoiceStats st = choose_triangle_methods(s, g, c, k.budget, out, arithmetic);
    ASSERT_EQ(out.size(), g.triangles.size());
    std::size_t gouraud = 0, refused_but_fitting = 0;
    double worst = 0.0;
    for (std::size_t t = 0; t < g.triangles.size(); ++t) {
      if (out[t].method == TriangleMethod::gouraud) {
        ++gouraud;
        worst = std::max(worst, sampled[t]);
      } else {
        refused_but_fitting += sampled[t] <= 0.5 * k.budget;
      }
    }
    const double worst_over_expected = st.largest_expected_levels > 0 ? worst / st.largest_expected_levels : 0.0;
    const std::string tag = lanes ? "_lanes" : "_reference";
    RecordProperty("gouraud" + tag, std::to_string(gouraud));
    RecordProperty("worst_sampled_levels" + tag, std::to_string(worst));
    RecordProperty("refused_with_half_the_budget" + tag, std::to_string(refused_but_fitting));
    EXPECT_EQ(st.gouraud, gouraud);
    EXPECT_GT(gouraud, g.triangles.size() / 20) << "the scene has smooth triangles: some must go to Gouraud";
    EXPECT_LE(worst, k.budget + 1e-6) << "a Gouraud triangle exceeded the budget";
    EXPECT_LE(worst_over_expected, 1.0 + 1e-6);
  }
}

// The float lanes decide as the double reference does, except for triangles whose expected error lies
// within float rounding and the tables' grid of the budget: few triangles may differ, and no mask.
TEST_P(TriangleChoiceBound, FloatLanesAgreeWithTheDoubleReference) {
  std::vector<TriangleShading> lanes, reference;
  const TriangleChoiceStats a = choose_triangle_methods(s, g, c, k.budget, lanes, ChoiceArithmetic::float_lanes);
  const TriangleChoiceStats b = choose_triangle_methods(s, g, c, k.budget, reference, ChoiceArithmetic::double_reference);
  std::size_t method_differs = 0, mask_differs = 0;
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    method_differs += lanes[t].method != reference[t].method;
    mask_differs += lanes[t].specular_mask != reference[t].specular_mask;
  }
  RecordProperty("method_differs", std::to_string(method_differs));
  RecordProperty("mask_differs", std::to_string(mask_differs));
  EXPECT_LE(method_differs, g.triangles.size() / 500 + 2) << "of " << g.triangles.size() << " triangles";
  EXPECT_LE(mask_differs, g.triangles.size() / 200 + 2);
  EXPECT_NEAR(a.largest_expected_levels, b.largest_expected_levels, 0.05 * k.budget);
}

// Choices that differ in method, mask or segment limit.
std::size_t differing_choices(const std::vector<TriangleShading>& a, const std::vector<TriangleShading>& b) {
  std::size_t differs = a.size() == b.size() ? 0 : std::max(a.size(), b.size());
  for (std::size_t t = 0; t < std::min(a.size(), b.size()); ++t)
    differs += a[t].method != b[t].method || a[t].specular_mask != b[t].specular_mask || a[t].psi_limit != b[t].psi_limit;
  return differs;
}

void expect_same_counts(const TriangleChoiceStats& a, const TriangleChoiceStats& b) {
  EXPECT_EQ(b.triangles, a.triangles);
  EXPECT_EQ(b.gouraud, a.gouraud);
  EXPECT_EQ(b.segments, a.segments);
  EXPECT_EQ(b.without_highlight, a.without_highlight);
  EXPECT_EQ(b.terminator, a.terminator);
  EXPECT_EQ(b.light_terms_skipped, a.light_terms_skipped);
  EXPECT_EQ(b.largest_expected_levels, a.largest_expected_levels);
}

// The lanes run on eight-float vectors where the CPU has AVX2 and on four elsewhere (lane_vectors.hpp): the
// same operations lane by lane, so the same bits, per light and for the whole choice. (On a CPU without AVX2
// both runs take four lanes.)
TEST_P(TriangleChoiceBound, FourAndEightFloatLanesGiveTheSameBits) {
  std::vector<TriangleShading> native, four;
  const TriangleChoiceStats a = choose_triangle_methods(s, g, c, k.budget, native);
  four_float_lanes_only(true);
  const TriangleChoiceStats b = choose_triangle_methods(s, g, c, k.budget, four);
  std::size_t lights_differ = 0;
  for (std::size_t first = 0; first < g.triangles.size(); first += kLanes) {
    FrameLanes f;
    frame_lanes(s, g, first, int(std::min<std::size_t>(kLanes, g.triangles.size() - first)), f);
    for (const Light& l : s.lights) {
      LightLanes x, y;
      four_float_lanes_only(false);
      light_lanes(f, l, x);
      four_float_lanes_only(true);
      light_lanes(f, l, y);
      lights_differ += std::memcmp(&x, &y, sizeof x) != 0;
    }
  }
  four_float_lanes_only(false);
  EXPECT_EQ(lights_differ, 0u);
  EXPECT_EQ(differing_choices(native, four), 0u) << "of " << native.size() << " triangles";
  expect_same_counts(a, b);
}

// The frame's setup chooses range by range (TriangleChooser), in ranges of its own chunks: any ranges, in any
// order, must give every triangle the choice and the counts of the whole at once, in both arithmetics (the
// lanes gather kLanes triangles from each range's start, so uneven ranges move triangles between lanes).
TEST_P(TriangleChoiceBound, RangesInAnyOrderChooseAsTheWhole) {
  for (const ChoiceArithmetic arithmetic : {ChoiceArithmetic::float_lanes, ChoiceArithmetic::double_reference}) {
    SCOPED_TRACE(arithmetic == ChoiceArithmetic::float_lanes ? "float lanes" : "double reference");
    std::vector<TriangleShading> whole, ranged;
    const TriangleChoiceStats a = choose_triangle_methods(s, g, c, k.budget, whole, arithmetic);
    TriangleChooser chooser(s, g, c, k.budget, ranged, arithmetic);
    std::vector<std::size_t> cuts = {0};  // ranges of 1 to 41 triangles, chosen last to first
    for (std::size_t at = 0, step = 1; at < g.triangles.size(); step = step % 37 + 5) {
      at = std::min(g.triangles.size(), at + step);
      cuts.push_back(at);
    }
    for (std::size_t r = cuts.size() - 1; r > 0; --r) chooser.choose(cuts[r - 1], cuts[r]);
    const TriangleChoiceStats b = chooser.stats();
    EXPECT_EQ(differing_choices(whole, ranged), 0u) << "of " << whole.size() << " triangles";
    expect_same_counts(a, b);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, TriangleChoiceBound,
                         ::testing::Values(Case{1, 0.0f, 40.0f, 0.5}, Case{2, 0.0f, 40.0f, 2.0},
                                           Case{3, 0.02f, 10.0f, 1.0}, Case{4, 0.05f, 200.0f, 1.0},
                                           Case{5, 0.0f, 1000.0f, 0.25}));

// The listing as printed returns Phong when two vertex normals are close (|n_i.n_j| > 0.9): a flat
// triangle goes to Phong and a triangle whose normals lie on a cone around L = V (equal N.L, N.h) to
// Gouraud. As intended (close normals -> Gouraud candidates), the other way round.
TEST(TriangleChoiceSources, TheListingsFirstTestIsInverted) {
  Scene s;
  s.width = s.height = 64;
  s.camera.projection = Projection::orthographic;
  s.camera.position = {0.0f, 0.0f, 10.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.ortho_height = 64.0f;
  s.local_viewer = false;
  Light l;
  l.direction = {0.0f, 0.0f, -1.0f};  // L = V = +z: h = L + V = (0, 0, 2)
  s.lights = {l};
  s.materials = {Material{}};
  ScreenGeometry g;
  g.width = g.height = 64;
  const float a = 0.6981317f;  // 40 degrees: pairwise n_i.n_j = 0.38 on the cone
  const glm::vec3 cone[3] = {{std::sin(a), 0.0f, std::cos(a)},
                             {std::sin(a) * -0.5f, std::sin(a) * 0.8660254f, std::cos(a)},
                             {std::sin(a) * -0.5f, std::sin(a) * -0.8660254f, std::cos(a)}};
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k) {
      g.xy.push_back(glm::ivec2(256 * (10 + 20 * t + 10 * k), 256 * (10 + 15 * (k == 2))));
      g.world.push_back(glm::vec3(float(t), float(k), 0.0f));
      g.normal.push_back(t == 0 ? glm::vec3(0.0f, 0.0f, 1.0f) : cone[k]);
      g.depth.push_back(0.5f);
      g.outcode.push_back(0);
    }
  g.triangles = {{0, 1, 2}, {3, 4, 5}};
  g.material = {0, 0};
  std::vector<TriangleShading> out;
  CombinedConfig c;
  c.rule = TriangleRule::sources_literal;
  choose_triangle_methods(s, g, c, 0.5, out);
  EXPECT_NE(out[0].method, TriangleMethod::gouraud) << "flat triangle, literal listing";
  EXPECT_EQ(out[1].method, TriangleMethod::gouraud) << "normals 40 degrees from L, literal listing";
  c.rule = TriangleRule::sources;
  choose_triangle_methods(s, g, c, 0.5, out);
  EXPECT_EQ(out[0].method, TriangleMethod::gouraud) << "flat triangle, intended rule";
  EXPECT_NE(out[1].method, TriangleMethod::gouraud) << "normals 40 degrees apart, intended rule";
}

// Triangles the bounds cannot cover: a zero, a NaN or an infinite vertex normal. Both arithmetics must
// send them to Phong with every light's specular term on, whatever lane of the lanes they fall in, and
// still choose Gouraud for the flat triangles around them.
TEST(TriangleChoiceBound, DegenerateNormalsGoToPhongInEveryLane) {
  Scene s;
  s.name = "degenerate";
  s.width = s.height = 256;
  s.camera.projection = Projection::orthographic;
  s.camera.position = {0.0f, 0.0f, 10.0f};
  s.camera.target = {0.0f, 0.0f, 0.0f};
  s.camera.ortho_height = 256.0f;
  Light sun;
  sun.direction = glm::normalize(glm::vec3(0.2f, -0.3f, -1.0f));
  Light lamp;
  lamp.type = LightType::point;
  lamp.position = {4000.0f, 3000.0f, 5000.0f};  // far: its L hardly turns over a triangle
  s.lights = {sun, lamp};
  s.materials = {Material{}};
  ScreenGeometry g;
  g.width = g.height = 256;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const glm::vec3 bad[3] = {{0.0f, 0.0f, 0.0f}, {nan, 0.0f, 1.0f}, {0.0f, inf, 0.0f}};
  const int count = 19;  // more than two lanes' worth, not a multiple of them
  for (int t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k) {
      g.xy.push_back(glm::ivec2(256 * (4 + 12 * (t % 16) + 8 * (k == 1)), 256 * (4 + 40 * (t / 16) + 8 * (k == 2))));
      g.world.push_back(glm::vec3(float(t), float(k), 0.0f));
      g.normal.push_back(t % 4 == 3 && k == t % 3 ? bad[(t / 4) % 3] : glm::vec3(0.0f, 0.0f, 1.0f));
      g.depth.push_back(0.5f);
      g.outcode.push_back(0);
    }
  for (int t = 0; t < count; ++t) {
    g.triangles.push_back(glm::uvec3(3 * t, 3 * t + 1, 3 * t + 2));
    g.material.push_back(0);
  }
  CombinedConfig c;
  c.automatic = true;
  c.rule = TriangleRule::bound;
  for (const ChoiceArithmetic arithmetic : {ChoiceArithmetic::float_lanes, ChoiceArithmetic::double_reference}) {
    SCOPED_TRACE(arithmetic == ChoiceArithmetic::float_lanes ? "float lanes" : "double reference");
    std::vector<TriangleShading> out;
    const TriangleChoiceStats st = choose_triangle_methods(s, g, c, 1.0, out, arithmetic);
    ASSERT_EQ(out.size(), std::size_t(count));
    for (int t = 0; t < count; ++t) {
      if (t % 4 == 3) {
        EXPECT_EQ(out[t].method, TriangleMethod::phong) << "triangle " << t;
        EXPECT_EQ(out[t].specular_mask, 3u) << "triangle " << t;
      } else {
        EXPECT_EQ(out[t].method, TriangleMethod::gouraud) << "flat triangle " << t;
      }
    }
    EXPECT_TRUE(std::isfinite(st.largest_expected_levels));
  }
}

TEST(TriangleChoiceBound, ChordBoundHoldsOverSampledTriangles) {
  // gouraud_term_bound(phi, n) against the sampled Gouraud error of max(0, N.d)^n on random triangles of
  // unit normals within phi of each other and a fixed direction d, with no zero crossing inside.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double tightest = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double n_exp = i % 4 == 0 ? 1.0 : std::pow(10.0, 0.3 + 2.5 * (0.5 + 0.5 * u(rng)));
    const glm::dvec3 centre = glm::normalize(glm::dvec3(u(rng), u(rng), 1.5 + u(rng)));
    const double size = 0.02 + 0.3 * (0.5 + 0.5 * u(rng));
    glm::dvec3 n[3];
    for (auto& v : n) v = glm::normalize(centre + size * glm::dvec3(u(rng), u(rng), u(rng)));
    const glm::dvec3 d = i % 2 ? glm::normalize(centre + 0.2 * glm::dvec3(u(rng), u(rng), u(rng))) : glm::dvec3(0, 0, 1);
    double phi = 0.0;
    for (int a = 0; a < 3; ++a) phi = std::max(phi, std::acos(std::clamp(glm::dot(n[a], n[(a + 1) % 3]), -1.0, 1.0)));
    const auto term = [&](const glm::dvec3& m) { return std::pow(std::max(0.0, glm::dot(m, d)), n_exp); };
    double worst = 0.0, lowest = 1.0;
    const int steps = 30;
    for (int a = 0; a <= steps; ++a)
      for (int b = 0; a + b <= steps; ++b) {
        const double b0 = double(a) / steps, b1 = double(b) / steps, b2 = 1.0 - b0 - b1;
        const glm::dvec3 m = glm::normalize(b0 * n[0] + b1 * n[1] + b2 * n[2]);
        lowest = std::min(lowest, glm::dot(m, d));
        worst = std::max(worst, std::abs(b0 * term(n[0]) + b1 * term(n[1]) + b2 * term(n[2]) - term(m)));
      }
    const double bound = gouraud_term_bound(phi, n_exp, !(lowest > 0.0));
    ASSERT_LE(worst, bound + 1e-12) << "n " << n_exp << " phi " << phi;
    if (bound > 1e-4) tightest = std::max(tightest, worst / bound);
  }
  RecordProperty("largest_sampled_over_bound", std::to_string(tightest));
  EXPECT_GT(tightest, 0.2) << "the bound should not be uselessly loose";
}

}  // namespace
}  // namespace parashade
