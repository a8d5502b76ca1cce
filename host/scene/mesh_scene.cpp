// A scene for a bare mesh file: the mesh framed by a default camera, light and material.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "parashade/errors.hpp"
#include "parashade/scene.hpp"
#include "short_number.hpp"

namespace parashade {

Scene scene_for_mesh(const std::filesystem::path& mesh_path) {
  MeshLoadStats stats;
  auto mesh = std::make_shared<const Mesh>(load_mesh(mesh_path, &stats));

  // Bounding sphere: the box centre and the farthest vertex from it, in double (squared float distances
  // overflow from ~1.8e19 on: fuzzing finding F8).
  glm::dvec3 lo = mesh->positions.front(), hi = lo;
  for (const glm::vec3& p : mesh->positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  const glm::dvec3 centre = 0.5 * (lo + hi);
  double radius = 0.0;
  for (const glm::vec3& p : mesh->positions) radius = std::max(radius, glm::distance(glm::dvec3(p), centre));
  // Every vertex at one point: no triangle has an area, nothing can be drawn (it rendered an empty image
  // without a word, while a merely tiny mesh is refused below: issue 46, item 17).
  if (!(radius > 0.0))
    throw InputError("'" + mesh_path.string() + "': every vertex of the mesh lies at one point (" + short_number(centre.x) +
                     ", " + short_number(centre.y) + ", " + short_number(centre.z) + "): nothing to frame or draw");

  Scene scene;
  if (std::string w = mesh_load_warning(mesh_path.string(), stats); !w.empty()) scene.warnings.push_back(std::move(w));
  scene.name = mesh_path.stem().string();
  scene.source = mesh_path;
  scene.width = 1920;
  scene.height = 1080;
  scene.background = glm::vec3(0.1f, 0.1f, 0.12f);
  scene.ambient_light = glm::vec3(1.0f);
  scene.cull_backfaces = false;  // an arbitrary mesh may be open

  // From +z, slightly above, far enough that the sphere fits the 40 degree field with a margin; the
  // frame is wider than tall, so the vertical field is the one that limits.
  Camera& cam = scene.camera;
  cam.projection = Projection::perspective;
  cam.fov_y_degrees = 40.0f;
  // Shading squares distances in single precision (lengths, normalization): beyond ~1.8e19 they overflow
  // and the image would be NaN, so such a mesh is refused rather than rendered wrong.
  constexpr double kLargest = 1e18;
  if (!(radius < kLargest && glm::length(centre) < kLargest))
    throw InputError("'" + mesh_path.string() + "': coordinates reach " + short_number(glm::length(centre) + radius) +
                     ", beyond the 1e18 that single-precision shading can take");
  // Too small to frame: the camera's offset from the target would underflow or vanish next to the
  // target's own coordinates in single precision (fuzzing finding F12: a view direction of 1e-40).
  const double magnitude = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
  constexpr double kSmallest = 1e-18, kRelative = 1e-5;
  if (!(radius >= kSmallest && radius >= kRelative * magnitude))
    throw InputError("'" + mesh_path.string() + "': the mesh spans only " + short_number(2 * radius) + " at " +
                     short_number(magnitude) + " from the origin, too small to frame in single precision (it must span at least 1e-18 "
                     "and 1e-5 of its distance from the origin)");
  const double distance = 1.15 * radius / std::sin(glm::radians(0.5 * double(cam.fov_y_degrees)));
  const glm::dvec3 position = centre + distance * glm::normalize(glm::dvec3(0.0, 0.25, 1.0));
  const double far_plane = 2.0 * (distance + radius);
  cam.target = glm::vec3(centre);
  cam.position = glm::vec3(position);
  cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
  cam.near_plane = float(0.5 * (distance - radius));
  cam.far_plane = float(far_plane);

  // White, from the upper left behind the camera.
  Light light;
  light.type = LightType::directional;
  light.direction = glm::normalize(glm::vec3(1.0f, -1.0f, -1.0f));
  light.color = glm::vec3(1.0f);
  scene.lights.push_back(light);

  Material grey;
  grey.name = "grey";
  grey.ambient = glm::vec3(0.1f);
  grey.diffuse = glm::vec3(0.6f);
  grey.specular = glm::vec3(0.4f);
  grey.shininess = 32.0f;
  scene.materials.push_back(grey);

  Object object;
  object.name = scene.name;
  object.mesh = std::move(mesh);
  scene.objects.push_back(object);
  return scene;
}

}  // namespace parashade
