#include "fuzz_support.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>
#include <typeinfo>

#include <cxxabi.h>
#include <unistd.h>

#include "parashade/errors.hpp"

namespace parashade::fuzz {

namespace {

std::filesystem::path g_dir;

void remove_work_dir() {
  std::error_code ec;
  if (!g_dir.empty()) std::filesystem::remove_all(g_dir, ec);
}

std::string type_name(const std::type_info& type) {
  int status = 0;
  char* name = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
  std::string out = status == 0 && name ? name : type.name();
  std::free(name);
  return out;
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite_non_negative(glm::vec3 v) { return finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; }
bool unit(glm::vec3 v) { return finite(v) && std::abs(glm::length(v) - 1.0f) < 1e-3f; }
std::string str(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}
std::string str(glm::vec3 v) { return "(" + str(v.x) + ", " + str(v.y) + ", " + str(v.z) + ")"; }

}  // namespace

const std::filesystem::path& work_dir() {
  if (g_dir.empty()) {
    std::string pattern = (std::filesystem::temp_directory_path() / "parashade-fuzz-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) {
      std::perror("parashade fuzz: mkdtemp");
      std::abort();
    }
    g_dir = pattern;
    std::atexit(remove_work_dir);
  }
  return g_dir;
}

std::filesystem::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = work_dir() / name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || (size && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
    std::perror("parashade fuzz: writing the input file");
    std::abort();
  }
  return path;
}

void finding(const std::string& what) {
  std::fprintf(stderr, "\nparashade fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

void expect_input_errors_only(const char* what, const std::function<void()>& load) {
  try {
    load();
  } catch (const InputError&) {
    // The documented outcome for bad input.
  } catch (const Error& e) {
    finding(std::string(what) + " threw " + type_name(typeid(e)) + " (not InputError): " + e.what());
  } catch (const std::bad_alloc& e) {
    finding(std::string(what) + " threw " + type_name(typeid(e)) + " (an allocation the input asked for failed): " +
            e.what());
  } catch (const std::exception& e) {
    finding(std::string(what) + " threw " + type_name(typeid(e)) + ": " + e.what());
  } catch (...) {
    finding(std::string(what) + " threw a non-standard exception");
  }
}

bool check_output() {
  static const bool on = [] {
    const char* v = std::getenv("PARASHADE_FUZZ_CHECK_OUTPUT");
    return !(v && std::strcmp(v, "0") == 0);
  }();
  return on;
}

void check_mesh(const Mesh& mesh, const std::string& what) {
  if (mesh.triangles.empty()) finding(what + ": returned a mesh without triangles");
  if (mesh.normals.size() != mesh.positions.size())
    finding(what + ": " + std::to_string(mesh.positions.size()) + " positions, " + std::to_string(mesh.normals.size()) +
            " normals");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!finite(mesh.positions[i])) finding(what + ": position " + std::to_string(i) + " not finite " + str(mesh.positions[i]));
    if (!unit(mesh.normals[i]))
      finding(what + ": normal " + std::to_string(i) + " not of unit length " + str(mesh.normals[i]));
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[i][k] >= mesh.positions.size())
        finding(what + ": triangle " + std::to_string(i) + " refers to vertex " + std::to_string(mesh.triangles[i][k]) +
                " of " + std::to_string(mesh.positions.size()));
}

void check_mesh_stats(const Mesh& mesh, const MeshLoadStats& s) {
  if (s.faces_dropped > s.faces_read) finding("stats: more faces dropped than read");
  if (s.polygons_triangulated > s.faces_read) finding("stats: more polygons triangulated than faces read");
  if (s.degenerate_faces > mesh.triangles.size()) finding("stats: more degenerate faces than triangles");
  if (s.faces_read - s.faces_dropped > mesh.triangles.size()) finding("stats: more faces kept than triangles");
}

void check_scene(const Scene& scene) {
  if (scene.width < 1 || scene.width > kMaxResolution || scene.height < 1 || scene.height > kMaxResolution)
    finding("scene: resolution " + std::to_string(scene.width) + "x" + std::to_string(scene.height));
  if (!finite_non_negative(scene.background)) finding("scene: background " + str(scene.background));
  if (!finite_non_negative(scene.ambient_light)) finding("scene: ambient " + str(scene.ambient_light));

  const Camera& c = scene.camera;
  if (!finite(c.position) || !finite(c.target) || !finite(c.up))
    finding("camera: position " + str(c.position) + " target " + str(c.target) + " up " + str(c.up));
  const glm::vec3 view = c.target - c.position;
  // The renderer normalizes the view direction and crosses it with up: both must give finite unit vectors.
  if (!unit(glm::normalize(view))) finding("camera: view direction " + str(view) + " does not normalize");
  if (!unit(glm::normalize(c.up))) finding("camera: up " + str(c.up) + " does not normalize");
  if (!unit(glm::normalize(glm::cross(glm::normalize(view), glm::normalize(c.up)))))
    finding("camera: up " + str(c.up) + " is (nearly) parallel to the view direction " + str(view));
  if (!(c.near_plane > 0.0f) || !(c.far_plane > c.near_plane) || !std::isfinite(c.far_plane))
    finding("camera: near " + str(c.near_plane) + " far " + str(c.far_plane));
  if (c.projection == Projection::perspective && !(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 180.0f))
    finding("camera: fov " + str(c.fov_y_degrees));
  if (c.projection == Projection::orthographic && !(c.ortho_height > 0.0f && std::isfinite(c.ortho_height)))
    finding("camera: height " + str(c.ortho_height));

  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    if (!finite_non_negative(l.color)) finding("light " + std::to_string(i) + ": colour " + str(l.color));
    if (l.type == LightType::directional && !unit(l.direction))
      finding("light " + std::to_string(i) + ": direction " + str(l.direction) + " is not a unit vector");
    if (l.type == LightType::point && !finite(l.position))
      finding("light " + std::to_string(i) + ": position " + str(l.position));
  }
  for (const Material& m : scene.materials)
    if (!finite_non_negative(m.ambient) || !finite_non_negative(m.diffuse) || !finite_non_negative(m.specular) ||
        !(m.shininess > 0.0f) || !std::isfinite(m.shininess))
      finding("material '" + m.name + "': a coefficient is negative or not finite");

  if (scene.objects.empty()) finding("scene: no objects");
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    const std::string what = "object " + std::to_string(i);
    if (!o.mesh) finding(what + ": no mesh");
    if (o.material >= scene.materials.size()) finding(what + ": material index out of range");
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row)
        if (!std::isfinite(o.model[col][row])) finding(what + ": model matrix not finite");
    check_mesh(*o.mesh, what);
  }
}

}  // namespace parashade::fuzz
