// A scene for a bare mesh file: the mesh framed by a default camera, light and material.
#include <algorithm>
#include <cmath>
#include <memory>

#include "parashade/scene.hpp"

namespace parashade {

Scene scene_for_mesh(const std::filesystem::path& mesh_path) {
  auto mesh = std::make_shared<const Mesh>(load_mesh(mesh_path));

  // Bounding sphere: the box centre and the farthest vertex from it.
  glm::vec3 lo = mesh->positions.front(), hi = lo;
  for (const glm::vec3& p : mesh->positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec3 centre = 0.5f * (lo + hi);
  float radius = 0.0f;
  for (const glm::vec3& p : mesh->positions) radius = std::max(radius, glm::distance(p, centre));
  if (!(radius > 0.0f)) radius = 1.0f;  // a single point: any distance will do

  Scene scene;
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
  const float distance = 1.15f * radius / std::sin(glm::radians(0.5f * cam.fov_y_degrees));
  cam.target = centre;
  cam.position = centre + distance * glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
  cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
  cam.near_plane = 0.5f * (distance - radius);
  cam.far_plane = 2.0f * (distance + radius);

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
