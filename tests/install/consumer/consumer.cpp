// Renders a lit sphere with Phong shading on the default OpenCL device and writes it to argv[1].
#include <cstdio>
#include <memory>

#include <parashade/parashade.hpp>

int main(int argc, char** argv) try {
  using namespace parashade;
  if (argc != 2) return std::fprintf(stderr, "usage: consumer IMAGE\n"), 2;
  Scene scene;  // camera at +z looking at the origin
  scene.width = 160, scene.height = 120;
  scene.lights.push_back({LightType::directional, {-0.4f, -0.5f, -1.0f}});
  scene.materials.push_back({"grey"});
  scene.objects.push_back({"sphere", std::make_shared<Mesh>(make_sphere(32, 17))});
  std::unique_ptr<Device> device = open_device("");  // "": the default device
  RenderOptions options;
  options.method = Method::phong;
  Renderer renderer(*device, options);
  write_image(argv[1], renderer.render(scene).image);
  std::printf("parashade %s (git %s) on %s\n", version, git_hash, device->info().name.c_str());
} catch (const parashade::Error& e) {
  std::fprintf(stderr, "consumer: %s\n", e.what());
  return int(e.code());
}
