// load_scene on JSON written for the test: values, defaults, sharing, paths, and every kind of refusal.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "framing.hpp"
#include "parashade/errors.hpp"
#include "parashade/scene.hpp"
#include "temp_dir.hpp"

namespace parashade {
namespace {

using namespace testing_support;

std::string with_objects(const std::string& objects, const std::string& extra = "") {
  return "{" + extra + (extra.empty() ? "" : ", ") + "\"objects\": " + objects + "}";
}

TEST(SceneLoader, MinimalSceneTakesTheDefaults) {
  TempDir dir;
  const Scene s = load_scene(dir.write("min.json", with_objects(R"([{"shape": "sphere"}])")));
  EXPECT_EQ(s.name, "min");
  EXPECT_EQ(s.width, 1920);
  EXPECT_EQ(s.height, 1080);
  EXPECT_FALSE(s.cull_backfaces);
  EXPECT_TRUE(s.local_viewer);
  EXPECT_TRUE(s.lights.empty());
  ASSERT_EQ(s.materials.size(), 1u);  // the default material, added for the object without one
  EXPECT_EQ(s.materials[0].name, "default");
  EXPECT_EQ(s.objects[0].mesh->triangles.size(), 2u * 32u * 16u);
  EXPECT_EQ(s.objects[0].model, glm::mat4(1.0f));
}

// Found by fuzzing (docs/robustness.md F9, F10): directions of extreme magnitude normalized to NaN in
// single precision and were accepted; a camera spanning more than float range gave a NaN view.
TEST(SceneLoader, DirectionsOfExtremeMagnitudeAreUnitVectors) {
  TempDir dir;
  const Scene s = load_scene(dir.write(
      "tiny.json", with_objects(R"([{"shape": "sphere"}])",
                                R"("lights": [{"type": "directional", "direction": [1e-30, 0, 0]}],
                                   "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1e-30, 0]})")));
  EXPECT_EQ(s.lights[0].direction, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_NEAR(glm::length(s.camera.up), 1.0f, 1e-6f);
  const Scene big = load_scene(dir.write(
      "big.json", with_objects(R"([{"shape": "sphere"}])",
                               R"("lights": [{"type": "directional", "direction": [3e38, 3e38, 0]}])")));
  EXPECT_NEAR(big.lights[0].direction.x, 0.70710678f, 1e-6f);
  EXPECT_THROW(load_scene(dir.write("far.json", with_objects(R"([{"shape": "sphere"}])",
                                                             R"("camera": {"position": [3e38, 0, 0], "target": [-3e38, 0, 0]})"))),
               InputError);
}

// Fuzzing finding F8: a bare mesh with coordinates near 1e20 got a NaN camera and rendered NaN. Up to
// 1e18 it is framed with a finite camera; beyond, it is refused.
TEST(SceneLoader, BareMeshesOfHugeCoordinatesAreFramedOrRefused) {
  TempDir dir;
  const Scene s = load_scene(dir.write("large.obj", "v 0 0 0\nv 1e17 0 0\nv 0 1e17 0\nf 1 2 3\n"));
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(std::isfinite(s.camera.position[k]));
    EXPECT_TRUE(std::isfinite(s.camera.target[k]));
  }
  EXPECT_TRUE(std::isfinite(s.camera.far_plane));
  EXPECT_GT(s.camera.near_plane, 0.0f);
  EXPECT_THROW(load_scene(dir.write("huge.obj", "v 0 0 0\nv 1e20 0 0\nv 0 1e20 0\nf 1 2 3\n")), InputError);
}

TEST(SceneLoader, ReadsEverySetting) {
  TempDir dir;
  const std::string json = R"({
    "name": "all", "resolution": [640, 480], "background": [0.1, 0.2, 0.3], "ambient": [0.5, 0.5, 0.5],
    "camera": {"type": "orthographic", "position": [0, 0, 10], "target": [0, 0, 0], "up": [0, 1, 0],
               "height": 4, "near": 1, "far": 20},
    "lights": [{"type": "directional", "direction": [0, 0, -2], "color": [1, 0.5, 0.25], "intensity": 2},
               {"type": "point", "position": [1, 2, 3]}],
    "materials": {"mat": {"color": [1, 0.5, 0], "ka": 0.2, "kd": 0.6, "ks": 0.4, "specular_color": [0, 0, 1], "n": 12},
                  "over": {"color": [1, 1, 1], "ambient": [0.3, 0.3, 0.3], "diffuse": [0, 1, 0], "specular": [0.9, 0.9, 0.9]}},
    "objects": [{"name": "b", "shape": {"type": "box", "size": [1, 2, 3]}, "material": "over"}],
    "cull_backfaces": true, "viewer": "infinite"})";
  const Scene s = load_scene(dir.write("all.json", json));
  EXPECT_EQ(s.name, "all");
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  EXPECT_EQ(s.background, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(s.ambient_light, glm::vec3(0.5f));
  EXPECT_EQ(s.camera.projection, Projection::orthographic);
  EXPECT_EQ(s.camera.ortho_height, 4.0f);
  EXPECT_EQ(s.camera.far_plane, 20.0f);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].direction, glm::vec3(0, 0, -1));          // normalized
  EXPECT_EQ(s.lights[0].color, glm::vec3(2.0f, 1.0f, 0.5f));      // colour x intensity
  EXPECT_EQ(s.lights[1].type, LightType::point);
  EXPECT_EQ(s.lights[1].position, glm::vec3(1, 2, 3));
  EXPECT_EQ(s.lights[1].color, glm::vec3(1.0f));
  ASSERT_EQ(s.materials.size(), 2u);  // by name: "mat", "over"
  const Material& mat = s.materials[0];
  EXPECT_EQ(mat.name, "mat");
  EXPECT_EQ(mat.ambient, 0.2f * glm::vec3(1, 0.5f, 0));
  EXPECT_EQ(mat.diffuse, 0.6f * glm::vec3(1, 0.5f, 0));
  EXPECT_EQ(mat.specular, 0.4f * glm::vec3(0, 0, 1));
  EXPECT_EQ(mat.shininess, 12.0f);
  const Material& over = s.materials[1];
  EXPECT_EQ(over.ambient, glm::vec3(0.3f));
  EXPECT_EQ(over.diffuse, glm::vec3(0, 1, 0));
  EXPECT_EQ(over.specular, glm::vec3(0.9f));
  EXPECT_EQ(s.objects[0].name, "b");
  EXPECT_EQ(s.objects[0].material, 1u);
  EXPECT_TRUE(s.cull_backfaces);
  EXPECT_FALSE(s.local_viewer);
}

TEST(SceneLoader, TransformIsTranslateRotateZYXScale) {
  TempDir dir;
  const Scene s = load_scene(dir.write(
      "t.json", with_objects(R"([{"shape": "box", "transform": {"translate": [10, 0, 0], "rotate": [90, 90, 90], "scale": [1, 3, 1]}}])")));
  const glm::mat4& m = s.objects[0].model;
  // (0,1,0) scaled to (0,3,0); X turns it to (0,0,3), then Y to (3,0,0), then Z to (0,3,0); then moved.
  const glm::vec3 p = glm::vec3(m * glm::vec4(0, 1, 0, 1));
  EXPECT_NEAR(glm::distance(p, glm::vec3(10, 3, 0)), 0.0f, 1e-5f) << p.x << " " << p.y << " " << p.z;
}

TEST(SceneLoader, EqualShapesShareOneMesh) {
  TempDir dir;
  const Scene s = load_scene(dir.write("share.json", with_objects(R"([
      {"shape": {"type": "sphere", "slices": 12, "stacks": 7}},
      {"shape": {"type": "sphere", "stacks": 7, "slices": 12}, "transform": {"translate": [1, 0, 0]}},
      {"shape": {"type": "sphere", "slices": 12, "stacks": 8}},
      {"shape": "box"}, {"shape": {"type": "box", "size": 1}}, {"shape": {"type": "box", "size": [1, 1, 2]}}])")));
  ASSERT_EQ(s.objects.size(), 6u);
  EXPECT_EQ(s.objects[0].mesh, s.objects[1].mesh);
  EXPECT_NE(s.objects[0].mesh, s.objects[2].mesh);
  EXPECT_EQ(s.objects[3].mesh, s.objects[4].mesh);
  EXPECT_NE(s.objects[3].mesh, s.objects[5].mesh);
}

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST(SceneLoader, MeshPathsAreRelativeToTheSceneAndExpandVariables) {
  TempDir dir;
  dir.write("models/tri.obj", kTriangleObj);
  ::setenv("PARASHADE_TEST_MODELS", (dir.path() / "models").c_str(), 1);
  const Scene s = load_scene(dir.write("scenes/m.json", with_objects(R"([
      {"mesh": "../models/tri.obj"}, {"mesh": "${PARASHADE_TEST_MODELS}/tri.obj"}, {"mesh": "$PARASHADE_TEST_MODELS/tri.obj"}])")));
  ::unsetenv("PARASHADE_TEST_MODELS");
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[0].mesh->triangles.size(), 1u);
  EXPECT_EQ(s.objects[0].mesh, s.objects[1].mesh);  // one file, loaded once
  EXPECT_EQ(s.objects[1].mesh, s.objects[2].mesh);
}

TEST(SceneLoader, BareMeshFileGetsAFramingCamera) {
  TempDir dir;
  const std::string tetra = "v 10 10 10\nv 12 10 10\nv 10 13 10\nv 10 10 11\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const Scene s = load_scene(dir.write("tetra.obj", tetra));
  EXPECT_EQ(s.name, "tetra");
  EXPECT_EQ(s.width, 1920);
  EXPECT_EQ(s.height, 1080);
  EXPECT_EQ(s.camera.fov_y_degrees, 40.0f);
  EXPECT_FALSE(s.cull_backfaces);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LightType::directional);
  EXPECT_GT(s.camera.position.z, 10.0f);  // from the +z side...
  EXPECT_GT(s.camera.position.y, s.camera.target.y);  // ...slightly above
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].shininess, 32.0f);
  const Framing f = framing(s);
  EXPECT_EQ(f.outside, 0u);
  EXPECT_GT(f.height_fraction(), 0.4f);
}

// Every refusal is an InputError whose message names the file and the culprit.
struct BadScene {
  const char* label;
  std::string json;
  const char* says;
};

void PrintTo(const BadScene& b, std::ostream* os) { *os << b.label; }

class RefusedScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(RefusedScene, ThrowsInputErrorNamingTheCulprit) {
  TempDir dir;
  const std::filesystem::path p = dir.write("bad.json", GetParam().json);
  try {
    load_scene(p);
    ADD_FAILURE() << "loaded";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(p.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(GetParam().says), std::string::npos) << message;
  }
}

const std::string kSphere = R"([{"shape": "sphere"}])";

std::string one(const std::string& object) { return with_objects("[" + object + "]"); }

INSTANTIATE_TEST_SUITE_P(
    Cases, RefusedScene,
    ::testing::Values(
        BadScene{"malformed", "{\"objects\": [\n  {\"shape\": \"sphere\",}\n]}", "invalid JSON: parse error at line 2"},
        BadScene{"not_an_object", "[1, 2]", "expected an object"},
        BadScene{"unknown_top_key", with_objects(kSphere, R"("cull_backface": true)"), "cull_backface: unknown key"},
        BadScene{"unknown_nested_key",
                 with_objects(R"([{"shape": "box"}, {"shape": "box"}, {"shape": "box", "transfrom": {}}])"),
                 "objects[2].transfrom: unknown key (expected one of: "},
        BadScene{"duplicate_key", R"({"objects": [{"shape": "box"}], "name": "a", "name": "b"})", "key 'name' appears twice"},
        BadScene{"wrong_type", with_objects(kSphere, R"("resolution": "big")"), "resolution: expected an array"},
        BadScene{"fractional_resolution", with_objects(kSphere, R"("resolution": [640.5, 480])"), "resolution[0]: expected an integer"},
        BadScene{"resolution_5000", with_objects(kSphere, R"("resolution": [5000, 1000])"),
                 "resolution: width 5000 is larger than the 12-bit screen address limit 4096"},
        BadScene{"resolution_0", with_objects(kSphere, R"("resolution": [640, 0])"), "resolution: height 0 must be at least 1"},
        BadScene{"shininess_0", with_objects(R"([{"shape": "box", "material": "m"}])", R"("materials": {"m": {"n": 0}})"),
                 "materials.m.n: must be > 0"},
        BadScene{"negative_colour", with_objects(kSphere, R"("background": [0, -1, 0])"), "background[1]: a colour channel must be >= 0"},
        BadScene{"nan_colour_as_string", with_objects(kSphere, R"("ambient": [0, "x", 0])"), "ambient[1]: expected a number"},
        BadScene{"fov_180", with_objects(kSphere, R"("camera": {"fov": 180})"), "camera.fov: must be in (0, 180)"},
        BadScene{"fov_on_orthographic", with_objects(kSphere, R"("camera": {"type": "orthographic", "fov": 30})"),
                 "camera.fov: unknown key"},
        BadScene{"near_0", with_objects(kSphere, R"("camera": {"near": 0})"), "camera.near: must be > 0"},
        BadScene{"far_before_near", with_objects(kSphere, R"("camera": {"near": 5, "far": 2})"), "camera.far: far"},
        BadScene{"camera_on_target", with_objects(kSphere, R"("camera": {"position": [1, 1, 1], "target": [1, 1, 1]})"),
                 "camera: position and target are the same point"},
        BadScene{"up_along_view", with_objects(kSphere, R"("camera": {"position": [0, 5, 0], "up": [0, 1, 0]})"),
                 "camera.up: up is parallel"},
        BadScene{"light_type", with_objects(kSphere, R"("lights": [{"type": "spot", "direction": [0, 0, -1]}])"),
                 "lights[0].type: 'spot' is not one of: directional, point"},
        BadScene{"zero_direction", with_objects(kSphere, R"("lights": [{"type": "directional", "direction": [0, 0, 0]}])"),
                 "lights[0].direction: must not be the zero vector"},
        BadScene{"point_with_direction",
                 with_objects(kSphere, R"("lights": [{"type": "point", "position": [0, 0, 0], "direction": [0, 0, 1]}])"),
                 "lights[0].direction: unknown key"},
        BadScene{"negative_intensity",
                 with_objects(kSphere, R"("lights": [{"type": "point", "position": [0, 0, 0], "intensity": -1}])"),
                 "lights[0].intensity: must be >= 0"},
        BadScene{"unknown_material", with_objects(R"([{"shape": "box", "material": "stel"}])", R"("materials": {"steel": {}})"),
                 "objects[0].material: unknown material 'stel' (defined: steel)"},
        BadScene{"unknown_shape", one(R"({"shape": "cone"})"), "objects[0].shape: 'cone' is not one of"},
        BadScene{"slices_typo", one(R"({"shape": {"type": "sphere", "slices": 100000}})"), "objects[0].shape.slices: must be in 3..4096"},
        BadScene{"too_many_triangles", one(R"({"shape": {"type": "sphere", "slices": 4096, "stacks": 4096}})"),
                 "would make 33546240 triangles, more than the limit"},
        BadScene{"teapot_level", one(R"({"shape": {"type": "teapot", "level": 1000}})"), "objects[0].shape.level: must be in 2..256"},
        BadScene{"torus_inside_out", one(R"({"shape": {"type": "torus", "major_radius": 1, "minor_radius": 1}})"),
                 "objects[0].shape.minor_radius: minor_radius must be smaller"},
        BadScene{"box_size", one(R"({"shape": {"type": "box", "size": [1, 0, 1]}})"), "objects[0].shape.size: every size must be > 0"},
        BadScene{"shape_parameter_of_other_shape", one(R"({"shape": {"type": "box", "radius": 1}})"),
                 "objects[0].shape.radius: unknown key"},
        BadScene{"mirror_scale", one(R"({"shape": "box", "transform": {"scale": [1, -1, 1]}})"),
                 "objects[0].transform.scale: every scale factor must be > 0"},
        BadScene{"shape_and_mesh", one(R"({"shape": "box", "mesh": "a.obj"})"), "objects[0]: has both 'shape' and 'mesh'"},
        BadScene{"no_geometry", one(R"({"name": "x"})"), "objects[0]: needs 'shape' or 'mesh'"},
        BadScene{"missing_mesh", one(R"({"mesh": "nowhere.obj"})"), "objects[0].mesh: "},
        BadScene{"unset_variable", one(R"({"mesh": "${PARASHADE_SURELY_UNSET}/a.obj"})"),
                 "objects[0].mesh: environment variable PARASHADE_SURELY_UNSET is not set"},
        BadScene{"no_objects", R"({"objects": []})", "objects: needs at least 1 element"},
        BadScene{"objects_missing", R"({"name": "x"})", "missing key 'objects'"},
        BadScene{"viewer", with_objects(kSphere, R"("viewer": "near")"), "viewer: 'near' is not one of: local, infinite"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(SceneLoader, MissingMeshIsNamed) {
  TempDir dir;
  const std::filesystem::path p = dir.write("m.json", one(R"({"mesh": "nowhere.obj"})"));
  try {
    load_scene(p);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find((dir.path() / "nowhere.obj").string() + ": no such file"), std::string::npos) << e.what();
  }
}

TEST(SceneLoader, MissingOrUnknownFilesAreRefused) {
  TempDir dir;
  try {
    load_scene(dir.path() / "none.json");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("none.json: no such file"), std::string::npos) << e.what();
  }
  try {
    load_scene(dir.write("scene.yaml", "objects: []\n"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.yaml: unknown scene format '.yaml'"), std::string::npos) << e.what();
  }
}

TEST(CheckResolution, LimitsAreInclusive) {
  EXPECT_NO_THROW(check_resolution(1, 1, "r"));
  EXPECT_NO_THROW(check_resolution(kMaxResolution, kMaxResolution, "r"));
  EXPECT_THROW(check_resolution(kMaxResolution + 1, 1, "r"), InputError);
  EXPECT_THROW(check_resolution(1, 0, "r"), InputError);
}

TEST(SceneTriangleCount, SumsOverObjects) {
  TempDir dir;
  const Scene s = load_scene(dir.write("c.json", with_objects(R"([{"shape": "box"}, {"shape": "box"}, {"shape": {"type": "sphere", "slices": 3, "stacks": 2}}])")));
  EXPECT_EQ(s.triangle_count(), 12u + 12u + 6u);
}

}  // namespace
}  // namespace parashade
