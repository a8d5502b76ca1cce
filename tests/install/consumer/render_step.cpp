// The render step from another program (README, "Using parashade from another program"): a scene file
// (argv[1]) resolved, rendered with its error figures, and its report built, all from the installed package.
#include <cstdio>

#include <parashade/parashade.hpp>

int main(int argc, char** argv) try {
  using namespace parashade;
  if (argc != 2) return std::fprintf(stderr, "usage: render_step SCENE\n"), 2;
  RenderRequest request;
  request.scene_file = argv[1];
  request.size = std::make_pair(64, 48);
  request.options.method = Method::phong;
  request.frames = 2;
  request.use_tuned = false;
  CommandFiles files;
  const ResolvedRender r = resolve_render(request, files);
  const RenderResult result = render(r);
  const RenderReport report = render_report(result, "unwritten.png");
  if (report.kind != "render" || !result.errors || report.body.at("width") != 64)
    return std::fprintf(stderr, "render_step: unexpected result\n"), 1;
  std::printf("render step ok: %s, %.3f ms, NMSE %.3g against exact Phong\n", result.scene_name.c_str(),
              result.medians.total_ms, result.errors->method.nmse);
} catch (const parashade::Error& e) {
  std::fprintf(stderr, "render_step: %s\n", e.what());
  return int(e.code());
}
