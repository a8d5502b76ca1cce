#pragma once
// A render's result (render_step.hpp) as its JSON report and as the summary printed on the terminal: the
// one place each report key and each printed figure is made, for one device, a frame split across devices
// and MPI ranks alike (docs/reports.md; schemas/render*.schema.json).
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parashade/render_step.hpp"

namespace parashade {

struct RenderReport {
  std::string kind;     // "render", "render-split" or "render-distributed" (the schema's name)
  nlohmann::json body;  // unstamped (report_header.hpp's stamp_report adds the header)
};

// `image` is where the frame was written (the report's "image").
RenderReport render_report(const RenderResult& r, const std::filesystem::path& image);

// The figures on stdout: scene, device, frame and stages, the unit's clocks, the plan, the error lines,
// `lines` (what the outputs hold: render_outputs.hpp), then "wrote ..." with `written` (the image and the
// report). `per_unit`: the plan's per-unit table too.
void print_render_summary(const RenderResult& r, const std::vector<std::string>& lines,
                          const std::vector<std::string>& written, bool per_unit, std::FILE* out = stdout);

// What the user should hear on stderr after the frames: the result's warnings (dropped devices), objects
// that vanished, fixed-point register wraps and saturations.
void print_render_warnings(const RenderResult& r, std::ostream& err);

}  // namespace parashade
