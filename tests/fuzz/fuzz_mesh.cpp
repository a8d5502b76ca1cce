// libFuzzer target: the bytes are a mesh file of one format (PARASHADE_FUZZ_MESH_EXT, one binary per
// format), read by load_mesh (host/scene/mesh_loader.cpp, mesh_file_scan.cpp, OpenMesh's reader) and,
// when that succeeds, framed by scene_for_mesh (host/scene/mesh_scene.cpp) as a bare mesh scene.
#include <cstdint>

#include "fuzz_support.hpp"
#include "parashade/mesh.hpp"
#include "parashade/scene.hpp"

#ifndef PARASHADE_FUZZ_MESH_EXT
#error "PARASHADE_FUZZ_MESH_EXT must name the format, e.g. \".obj\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = parashade::fuzz::write_input(std::string("mesh") + PARASHADE_FUZZ_MESH_EXT, data, size);
  bool loaded = false;
  parashade::fuzz::expect_input_errors_only("load_mesh", [&] {
    parashade::MeshLoadStats stats;
    const parashade::Mesh mesh = parashade::load_mesh(path, &stats);
    loaded = true;
    if (parashade::fuzz::check_output()) {
      parashade::fuzz::check_mesh(mesh, "load_mesh");
      parashade::fuzz::check_mesh_stats(mesh, stats);
    }
  });
  if (loaded)  // the same file as a bare mesh scene: the mesh loads, so framing it must succeed
    parashade::fuzz::expect_input_errors_only("load_scene (bare mesh)", [&] {
      const parashade::Scene scene = parashade::load_scene(path);
      if (parashade::fuzz::check_output()) parashade::fuzz::check_scene(scene);
    });
  return 0;
}
