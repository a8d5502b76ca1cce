// libFuzzer target: the bytes are a JSON scene file, read by load_scene (host/scene/scene_loader.cpp,
// json_reader.cpp, and through "mesh" the mesh loaders and through "shape" the procedural shapes).
// The scene's folder holds one small valid mesh per format (tetra.obj .off .ply .stl), so that seeds and
// mutations that name them reach the mesh path of the scene reader.
#include <cmath>
#include <cstdint>
#include <fstream>

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "parashade/scene.hpp"

namespace {

using parashade::fuzz::work_dir;

// Valid scenes may ask for up to 16.8M triangles per shape, by design. That is tested elsewhere; here it
// would make one input take seconds and gigabytes, so inputs whose shapes would build more than this many
// triangles in total are skipped. Shapes over the loader's limits are rejected before building and are
// not skipped, so the limit checks are still fuzzed.
constexpr double kTriangleBudget = 1 << 17;

// Triangles the shape objects in `v` would build, estimated from the integer members of each object (the
// product of slices/stacks/segments; 64 level^2 for a teapot), counting 0 for parameters the loader
// refuses before building (outside 0..4096, or over its 2^24 triangle limit).
double estimated_triangles(const nlohmann::json& v) {
  double total = 0.0;
  if (v.is_object()) {
    double product = 2.0;
    bool any = false, refused = false;
    for (const auto& item : v.items()) {
      const nlohmann::json& x = item.value();
      if (x.is_number_integer()) {
        const double n = x.get<double>();
        if (n < 0.0 || n > 4096.0) refused = true;
        product *= item.key() == "level" ? 32.0 * n * n : std::max(n, 1.0);
        any = true;
      }
      total += estimated_triangles(x);
    }
    if (any && !refused && product <= double(1 << 24)) total += product;
  } else if (v.is_array()) {
    for (const auto& x : v) total += estimated_triangles(x);
  }
  return total;
}

void write_meshes() {
  const auto put = [](const char* name, const std::string& bytes) {
    std::ofstream(work_dir() / name, std::ios::binary) << bytes;
  };
  put("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  put("tetra.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  put("tetra.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  put("tetra.stl",
      "solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
      "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
      "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
      "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  write_meshes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The JSON library's own parse (no exceptions) only decides whether to skip the input.
  const nlohmann::json doc = nlohmann::json::parse(data, data + size, nullptr, false);
  if (!doc.is_discarded() && estimated_triangles(doc) > kTriangleBudget) return -1;  // -1: not added to the corpus

  const auto path = parashade::fuzz::write_input("scene.json", data, size);
  parashade::fuzz::expect_input_errors_only("load_scene", [&] {
    const parashade::Scene scene = parashade::load_scene(path);
    if (parashade::fuzz::check_output()) parashade::fuzz::check_scene(scene);
  });
  return 0;
}
