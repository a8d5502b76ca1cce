// parashade.load_scene (docs/python.md): the scene file read by the library's loader, as render reads it.
#include "../../host/cli/cli_args.hpp"
#include "bindings.hpp"

namespace parashade::python {

pybind11::dict scene_info(const std::string& path, const std::string& size) {
  Scene scene;
  {
    pybind11::gil_scoped_release unlocked;
    scene = cli::load_scene_at(path, cli::checked_size(size));
  }
  pybind11::dict out;
  out["scene"] = scene.name;
  out["width"] = scene.width;
  out["height"] = scene.height;
  out["triangles"] = scene.triangle_count();
  return out;
}

}  // namespace parashade::python
