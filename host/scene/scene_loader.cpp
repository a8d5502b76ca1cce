// Scene files: the JSON format of scenes/README.md, or a bare mesh file.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <tuple>
#include <memory>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "json_reader.hpp"
#include "parashade/errors.hpp"
#include "parashade/memory_budget.hpp"
#include "parashade/scene.hpp"
#include "parashade/scene_files.hpp"
#include "parashade/shapes.hpp"
#include "short_number.hpp"

namespace parashade {

namespace {

using detail::JsonObject;
using detail::JsonValue;

// Upper bounds that keep a typo from allocating gigabytes; generous for any real scene.
constexpr int kMaxSegments = 4096;                     // slices, stacks, segments
constexpr int kMaxTeapotLevel = 256;                   // 4.2M triangles
constexpr long long kMaxShapeTriangles = 1ll << 24;    // 16.8M per procedural shape

double positive(const JsonValue& v) {
  const double x = v.number();
  if (!(x > 0.0)) v.fail("must be > 0 (got " + v.dump() + ")");
  return x;
}

double non_negative(const JsonValue& v) {
  const double x = v.number();
  if (x < 0.0) v.fail("must be >= 0 (got " + v.dump() + ")");
  return x;
}

// The brightest light (colour x intensity), material coefficient or ambient light taken, per channel. The
// kernels shade in single precision with 255 x each: a light of 3e38 made inf, then NaN (inf x 0), and an
// all-black image where the reference is white (issue 46, item 17). With every factor at most 1e6 (a million
// times white), a pixel's sum over lights and a plane's values across 4096 pixels stay far below 3.4e38.
constexpr double kBrightest = 1e6;

// `value` (the product of `factor` and `colour`, in double: it may pass float's range) within kBrightest,
// else `where` fails naming `what`.
void check_brightness(const JsonValue& where, double factor, const glm::vec3& colour, const std::string& what) {
  const double largest = factor * double(std::max({colour.x, colour.y, colour.z}));
  if (!(largest <= kBrightest))
    where.fail(what + " reaches " + short_number(largest) + ", beyond the " + short_number(kBrightest) +
               " that single-precision shading can take (255 times it must stay finite through every sum)");
}

// A direction, normalized in double precision: any non-zero float vector has a unit direction (in float a
// component of 1e-30 squares to 0 and one of 1e30 to inf, and normalize() gave NaN).
glm::vec3 unit_vec3(const JsonValue& v) {
  const glm::vec3 x = v.vec3();
  if (x == glm::vec3(0.0f)) v.fail("must not be the zero vector");
  return glm::vec3(glm::normalize(glm::dvec3(x)));
}

// ${NAME} and $NAME from the environment; an unset variable is an error that names it.
std::string expand_variables(const JsonValue& where, const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] != '$') {
      out += text[i++];
      continue;
    }
    std::string name;
    std::size_t next;
    if (i + 1 < text.size() && text[i + 1] == '{') {
      const std::size_t close = text.find('}', i + 2);
      if (close == std::string::npos) where.fail("unterminated '${' in \"" + text + "\"");
      name = text.substr(i + 2, close - i - 2);
      next = close + 1;
    } else {
      next = i + 1;
      while (next < text.size() && (std::isalnum(static_cast<unsigned char>(text[next])) || text[next] == '_')) ++next;
      name = text.substr(i + 1, next - i - 1);
    }
    if (name.empty()) where.fail("'$' without a variable name in \"" + text + "\"");
    const char* value = std::getenv(name.c_str());
    if (!value) where.fail("environment variable " + name + " is not set (used in \"" + text + "\")");
    out += value;
    i = next;
  }
  return out;
}

// Shapes and meshes already built for this scene, so equal specifications share one Mesh.
class MeshCache {
 public:
  std::vector<std::string> warnings;  // of the meshes loaded, once per file
  std::vector<std::filesystem::path>* files = nullptr;  // the mesh files read, when asked for

  std::shared_ptr<const Mesh> get(const std::string& key, const std::function<Mesh()>& build) {
    auto& slot = meshes_[key];
    if (!slot) slot = std::make_shared<const Mesh>(build());
    return slot;
  }

 private:
  std::map<std::string, std::shared_ptr<const Mesh>> meshes_;
};

void check_triangles(const JsonValue& where, long long triangles) {
  if (triangles > kMaxShapeTriangles)
    where.fail("would make " + std::to_string(triangles) + " triangles, more than the limit " +
               std::to_string(kMaxShapeTriangles));
}

// A shape's parameters, all keys checked, before anything is built.
struct ShapeSpec {
  std::string key;  // equal keys, equal meshes
  std::function<Mesh()> build;
  std::string type;
  std::uint64_t triangles = 0, vertices = 0;  // what build() makes, for the memory budget (about)
};

ShapeSpec read_shape(const JsonValue& v) {
  // "sphere" alone takes the defaults; {"type": "sphere", ...} sets parameters.
  static const nlohmann::json kNoParameters = nlohmann::json::object();
  const std::vector<std::string> types = {"sphere", "torus", "box", "cylinder", "teapot"};
  const bool bare = v.is_string();
  JsonObject spec = bare ? JsonObject(v, kNoParameters) : v.object();
  const std::string type = bare ? v.choice(types) : spec.required("type").choice(types);
  auto integer = [&](const char* key, int fallback, int lo, int hi) {
    const auto x = spec.optional(key);
    return x ? x->integer(lo, hi) : fallback;
  };
  auto length = [&](const char* key, double fallback) {
    const auto x = spec.optional(key);
    return float(x ? positive(*x) : fallback);
  };
  std::ostringstream key;
  key.precision(9);
  key << type;
  ShapeSpec shape;
  if (type == "sphere") {
    const int slices = integer("slices", 32, 3, kMaxSegments), stacks = integer("stacks", 17, 2, kMaxSegments);
    check_triangles(v, 2ll * slices * (stacks - 1));
    shape.triangles = 2ull * slices * (stacks - 1);
    shape.vertices = std::uint64_t(slices + 1) * (stacks + 1);
    key << ' ' << slices << ' ' << stacks;
    shape.build = [=] { return make_sphere(slices, stacks); };
  } else if (type == "torus") {
    const float major = length("major_radius", 1.0), minor = length("minor_radius", 0.25);
    if (!(minor < major)) {
      const auto minor_v = spec.optional("minor_radius");
      (minor_v ? *minor_v : v).fail("minor_radius must be smaller than major_radius");
    }
    const int major_n = integer("major_segments", 48, 3, kMaxSegments);
    const int minor_n = integer("minor_segments", 24, 3, kMaxSegments);
    check_triangles(v, 2ll * major_n * minor_n);
    shape.triangles = 2ull * major_n * minor_n;
    shape.vertices = std::uint64_t(major_n + 1) * (minor_n + 1);
    key << ' ' << major << ' ' << minor << ' ' << major_n << ' ' << minor_n;
    shape.build = [=] { return make_torus(major, minor, major_n, minor_n); };
  } else if (type == "box") {
    glm::vec3 size(1.0f);
    if (const auto s = spec.optional("size")) {
      size = s->is_number() ? glm::vec3(float(positive(*s))) : s->vec3();
      if (!(size.x > 0.0f && size.y > 0.0f && size.z > 0.0f)) s->fail("every size must be > 0 (got " + s->dump() + ")");
    }
    shape.triangles = 12;
    shape.vertices = 24;
    key << ' ' << size.x << ' ' << size.y << ' ' << size.z;
    shape.build = [=] { return make_box(size); };
  } else if (type == "cylinder") {
    const float radius = length("radius", 0.5), height = length("height", 1.0);
    const int segments = integer("segments", 32, 3, kMaxSegments);
    const auto caps_v = spec.optional("caps");
    const bool caps = caps_v ? caps_v->boolean() : true;
    shape.triangles = 4ull * segments;
    shape.vertices = 4ull * (segments + 1) + 2;
    key << ' ' << radius << ' ' << height << ' ' << segments << ' ' << caps;
    shape.build = [=] { return make_cylinder(radius, height, segments, caps); };
  } else {
    const int level = integer("level", 8, 2, kMaxTeapotLevel);
    shape.triangles = 64ull * level * level;  // 32 patches of level x level quads
    shape.vertices = 32ull * (level + 1) * (level + 1);
    key << ' ' << level;
    shape.build = [=] { return make_teapot(level); };
  }
  spec.finish();
  shape.type = type;
  shape.key = key.str();
  return shape;
}

std::shared_ptr<const Mesh> read_mesh_path(const JsonValue& v, const std::filesystem::path& folder, MeshCache& cache) {
  std::filesystem::path path = expand_variables(v, v.string());
  if (path.is_relative()) path = folder / path;
  path = path.lexically_normal();
  return cache.get("mesh " + path.string(), [&] {
    try {
      MeshLoadStats stats;
      if (cache.files) cache.files->push_back(path);
      Mesh mesh = load_mesh(path, &stats);
      if (std::string w = mesh_load_warning(path.string(), stats); !w.empty()) cache.warnings.push_back(std::move(w));
      return mesh;
    } catch (const InputError& e) {
      v.fail(e.what());
    }
  });
}

// model = T * Rz * Ry * Rx * S: scale, then rotate about X, Y, Z (degrees), then translate.
glm::mat4 read_transform(const JsonValue& v) {
  JsonObject t = v.object();
  glm::vec3 translate(0.0f), rotate(0.0f), scale(1.0f);
  if (const auto x = t.optional("translate")) translate = x->vec3();
  if (const auto x = t.optional("rotate")) rotate = x->vec3();
  if (const auto x = t.optional("scale")) {
    scale = x->is_number() ? glm::vec3(float(x->number())) : x->vec3();
    // A negative factor mirrors the object, turning its front faces into back faces.
    if (!(scale.x > 0.0f && scale.y > 0.0f && scale.z > 0.0f))
      x->fail("every scale factor must be > 0 (got " + x->dump() + ")");
  }
  t.finish();
  glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
  m = glm::rotate(m, glm::radians(rotate.z), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotate.y), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotate.x), glm::vec3(1, 0, 0));
  return glm::scale(m, scale);
}

Camera read_camera(const JsonValue& v) {
  JsonObject c = v.object();
  Camera cam;
  const auto type = c.optional("type");
  cam.projection = (type && type->choice({"perspective", "orthographic"}) == "orthographic") ? Projection::orthographic
                                                                                           : Projection::perspective;
  if (const auto x = c.optional("position")) cam.position = x->vec3();
  if (const auto x = c.optional("target")) cam.target = x->vec3();
  const auto up = c.optional("up");
  if (up) cam.up = unit_vec3(*up);
  if (cam.position == cam.target) v.fail("position and target are the same point");
  const glm::vec3 view = cam.target - cam.position;
  if (!std::isfinite(view.x) || !std::isfinite(view.y) || !std::isfinite(view.z))
    v.fail("position and target are too far apart for single precision");
  const glm::dvec3 forward = glm::normalize(glm::dvec3(view));
  if (!(glm::length(glm::cross(forward, glm::normalize(glm::dvec3(cam.up)))) >= 1e-4))
    (up ? *up : v).fail("up is parallel to the view direction");
  // Only the parameters of the chosen projection are accepted, so a forgotten "type" is noticed.
  if (cam.projection == Projection::perspective) {
    if (const auto x = c.optional("fov")) {
      const double fov = x->number();
      cam.fov_y_degrees = float(fov);
      if (!(fov > 0.0 && fov < 180.0)) x->fail("must be in (0, 180) degrees (got " + x->dump() + ")");
      // A field this narrow has no usable projection in single precision (tan(fov/2) underflows or the
      // scale overflows): say so instead of claiming the value is out of (0, 180).
      constexpr double kMinFovDegrees = 1e-3;
      if (!(fov >= kMinFovDegrees))
        x->fail("too narrow: at least 0.001 degrees (got " + x->dump() +
                "); the single-precision projection cannot take a narrower field");
    }
  } else if (const auto x = c.optional("height")) {
    cam.ortho_height = float(positive(*x));
  }
  if (const auto x = c.optional("near")) cam.near_plane = float(positive(*x));
  const auto far = c.optional("far");
  if (far) cam.far_plane = float(far->number());
  if (!(cam.far_plane > cam.near_plane))
    (far ? *far : v).fail("far (" + std::to_string(cam.far_plane) + ") must be greater than near (" +
                         std::to_string(cam.near_plane) + ")");
  c.finish();
  return cam;
}

Light read_light(const JsonValue& v) {
  JsonObject l = v.object();
  Light light;
  light.type = l.required("type").choice({"directional", "point"}) == "point" ? LightType::point : LightType::directional;
  if (light.type == LightType::directional)
    light.direction = unit_vec3(l.required("direction"));
  else
    light.position = l.required("position").vec3();
  glm::vec3 color(1.0f);
  if (const auto x = l.optional("color")) color = x->color();
  double intensity = 1.0;
  if (const auto x = l.optional("intensity")) intensity = non_negative(*x);
  l.finish();
  check_brightness(v, intensity, color, "the light's colour x intensity");
  light.color = color * float(intensity);
  return light;
}

// ambient = ka*color, diffuse = kd*color, specular = ks*specular_color, unless given explicitly.
Material read_material(const std::string& name, const JsonValue& v) {
  JsonObject m = v.object();
  Material mat;
  mat.name = name;
  glm::vec3 color(1.0f), specular_color(1.0f);
  if (const auto x = m.optional("color")) color = x->color();
  if (const auto x = m.optional("specular_color")) specular_color = x->color();
  auto coefficient = [&](const char* key, double fallback) {
    const auto x = m.optional(key);
    return x ? non_negative(*x) : fallback;
  };
  const double ka = coefficient("ka", 0.1f), kd = coefficient("kd", 0.7f), ks = coefficient("ks", 0.5f);
  // Each product checked in double first: in float it may already be inf.
  const auto product = [&](const char* key, double k, const glm::vec3& c) {
    if (const auto x = m.optional(key)) {
      const glm::vec3 given = x->color();
      check_brightness(v, 1.0, given, std::string("the ") + key + " colour");
      return given;
    }
    check_brightness(v, k, c, std::string("the ") + key + " colour");
    return float(k) * c;
  };
  mat.ambient = product("ambient", ka, color);
  mat.diffuse = product("diffuse", kd, color);
  mat.specular = product("specular", ks, specular_color);
  if (const auto x = m.optional("n")) mat.shininess = float(positive(*x));
  m.finish();
  return mat;
}

// A shape is built only after the whole scene is read and its memory budget checked: its ShapeSpec
// waits in `shapes` (by object index) and the object's mesh stays empty until then.
Object read_object(const JsonValue& v, std::size_t index, std::map<std::string, std::uint32_t>& materials,
                   Scene& scene, const std::filesystem::path& folder, MeshCache& cache,
                   std::map<std::size_t, ShapeSpec>& shapes) {
  JsonObject o = v.object();
  Object obj;
  const auto shape = o.optional("shape");
  const auto mesh = o.optional("mesh");
  if (shape && mesh) v.fail("has both 'shape' and 'mesh' (one object, one geometry)");
  if (!shape && !mesh) v.fail("needs 'shape' or 'mesh'");
  if (shape) {
    shapes[index] = read_shape(*shape);
  } else {
    obj.mesh = read_mesh_path(*mesh, folder, cache);
  }
  if (const auto x = o.optional("name")) {
    obj.name = x->string();
  } else {
    obj.name = "object " + std::to_string(index);
  }
  std::string material = "default";
  const auto material_v = o.optional("material");
  if (material_v) material = material_v->string();
  auto found = materials.find(material);
  if (found == materials.end()) {
    if (material_v) {
      std::string defined;
      for (const auto& [name, i] : materials) defined += (defined.empty() ? "" : ", ") + name;
      material_v->fail("unknown material '" + material + "' (defined: " + (defined.empty() ? "none" : defined) + ")");
    }
    // Objects without a material share a default one, added once.
    Material fallback;
    fallback.name = "default";
    scene.materials.push_back(fallback);
    found = materials.emplace("default", std::uint32_t(scene.materials.size() - 1)).first;
  }
  obj.material = found->second;
  if (const auto x = o.optional("transform")) obj.model = read_transform(*x);
  o.finish();
  return obj;
}

Scene read_scene(const nlohmann::json& doc, const std::filesystem::path& path,
                 std::vector<std::filesystem::path>& files, const std::optional<std::pair<int, int>>& size) {
  const std::string file = path.string();
  const JsonValue root(doc, "", file);
  JsonObject top = root.object();
  Scene scene;
  scene.source = path;
  scene.name = path.stem().string();
  if (const auto x = top.optional("name")) scene.name = x->string();
  if (const auto x = top.optional("resolution")) {
    const std::vector<JsonValue> wh = x->array();
    if (wh.size() != 2) x->fail("expected [width, height]");
    // Integers of any size, then the limit with its reason (check_resolution's words for those beyond int).
    const long long w = wh[0].any_integer(), h = wh[1].any_integer();
    for (const auto& [v, axis] : {std::pair{w, "width"}, std::pair{h, "height"}})
      if (v < -1000000000 || v > 1000000000)
        throw InputError(file + ": " + x->path() + ": " + axis + " " + std::to_string(v) +
                         (v < 1 ? " must be at least 1"
                                : " is larger than the 12-bit screen address limit " + std::to_string(kMaxResolution)));
    check_resolution(int(w), int(h), file + ": " + x->path());
    scene.width = int(w);
    scene.height = int(h);
  }
  if (size) std::tie(scene.width, scene.height) = *size;  // budgeted below at the size it will be rendered
  if (const auto x = top.optional("background")) scene.background = x->color();
  if (const auto x = top.optional("ambient")) {
    scene.ambient_light = x->color();
    check_brightness(*x, 1.0, scene.ambient_light, "the ambient light");
  }
  if (const auto x = top.optional("camera")) scene.camera = read_camera(*x);
  if (const auto x = top.optional("lights"))
    for (const JsonValue& l : x->array()) scene.lights.push_back(read_light(l));
  std::map<std::string, std::uint32_t> materials;
  if (const auto x = top.optional("materials")) {
    JsonObject all = x->object();
    for (const auto& [name, m] : all.members()) {
      scene.materials.push_back(read_material(name, m));
      materials[name] = std::uint32_t(scene.materials.size() - 1);
    }
  }
  const std::filesystem::path folder = path.parent_path();
  MeshCache cache;
  cache.files = &files;
  const std::vector<JsonValue> objects = top.required("objects").array(1);
  std::map<std::size_t, ShapeSpec> shapes;
  for (std::size_t i = 0; i < objects.size(); ++i)
    scene.objects.push_back(read_object(objects[i], i, materials, scene, folder, cache, shapes));
  std::vector<MemoryItem> budget;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    if (const auto s = shapes.find(i); s != shapes.end())
      budget.push_back({"'" + o.name + "' (" + s->second.type + ")", s->second.triangles, s->second.vertices});
    else
      budget.push_back({"'" + o.name + "' (mesh)", o.mesh->triangles.size(), o.mesh->positions.size()});
  }
  const std::string at = size ? file + " at " + std::to_string(scene.width) + "x" + std::to_string(scene.height) : file;
  check_host_memory(at, budget, scene.width, scene.height);
  for (const auto& [i, spec] : shapes) scene.objects[i].mesh = cache.get(spec.key, spec.build);
  scene.warnings = cache.warnings;
  if (const auto x = top.optional("cull_backfaces")) scene.cull_backfaces = x->boolean();
  if (const auto x = top.optional("viewer")) scene.local_viewer = x->choice({"local", "infinite"}) == "local";
  top.finish();
  return scene;
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

Scene load_scene(const std::filesystem::path& path) {
  std::vector<std::filesystem::path> files;
  return load_scene(path, files);
}

Scene load_scene(const std::filesystem::path& path, std::vector<std::filesystem::path>& files) {
  return load_scene(path, files, std::nullopt);
}

Scene load_scene(const std::filesystem::path& path, std::vector<std::filesystem::path>& files,
                 const std::optional<std::pair<int, int>>& size) {
  files.push_back(path);
  const std::string ext = lower_extension(path);
  std::error_code ec;
  // The system's reason when it cannot be reached: "no such file", a loop of symbolic links, permission.
  if (!std::filesystem::exists(path, ec))
    throw InputError(path.string() + ": " + (ec && ec != std::errc::no_such_file_or_directory ? ec.message() : "no such file"));
  // A directory opens as an empty stream, which would read as "invalid JSON".
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string() + ": is a directory, not a scene file");
  if (ext == ".json") return read_scene(detail::parse_json_file(path), path, files, size);
  if (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl") {
    Scene scene = scene_for_mesh(path);
    if (size) {  // the mesh at the size it will be rendered
      std::tie(scene.width, scene.height) = *size;
      check_host_memory(path.string() + " at " + std::to_string(scene.width) + "x" + std::to_string(scene.height),
                        {{"'" + scene.objects.front().name + "' (mesh)", scene.objects.front().mesh->triangles.size(),
                          scene.objects.front().mesh->positions.size()}},
                        scene.width, scene.height);
    }
    return scene;
  }
  throw InputError(path.string() + ": unknown scene format '" + ext + "' (expected .json, or a mesh: .obj .off .ply .stl)");
}

}  // namespace parashade
