// Links the scene library alone (find_package(parashade COMPONENTS scene)): a procedural sphere's size.
#include <cstdio>

#include <parashade/shapes.hpp>

int main() {
  const parashade::Mesh sphere = parashade::make_sphere(8, 5);
  std::printf("scene library ok: a sphere of %zu triangles\n", sphere.triangles.size());
  return sphere.triangles.size() > 0 ? 0 : 1;
}
