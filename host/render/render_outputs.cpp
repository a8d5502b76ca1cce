// A render's files, staged and committed together (render_outputs.hpp).
#include "parashade/render_outputs.hpp"

#include <optional>

#include "error_pictures.hpp"
#include "parashade/errors.hpp"
#include "parashade/metrics.hpp"
#include "parashade/output_file.hpp"
#include "parashade/render_report.hpp"
#include "parashade/report_header.hpp"

namespace parashade {
namespace {

// --reference-image, --error-map and --flip-map against the chosen reference, and --triangle-map, staged. The
// result holds the reference only when a picture drawn from it is asked for (RenderOutputs::needs_reference).
std::vector<StagedFile> stage_pictures(const RenderOutputs& o, const RenderResult& r, std::vector<std::string>& lines) {
  std::vector<StagedFile> files;
  if (!o.pictures()) return files;
  if (!r.errors || (o.needs_reference() && !r.errors->reference))
    throw std::logic_error("render outputs: pictures asked for without the reference (RenderRequest::keep_reference)");
  const ReferenceImage* ref = r.errors->reference ? &*r.errors->reference : nullptr;
  const std::vector<glm::dvec3>* values = ref ? (o.against_exact ? &ref->exact : &ref->ideal) : nullptr;
  const std::string name = o.against_exact ? "exact phong" : ideal_name(r.options.method);
  if (!o.reference_image.empty()) {
    files.push_back(stage_image(o.reference_image, levels_image(*values, ref->width, ref->height)));
    lines.push_back("reference image " + o.reference_image.string() + ": " + name);
  }
  if (!o.error_map.empty()) {
    const std::vector<double> errors = pixel_errors(r.image, ref->covered, *values, front_surface_flips(r.image, *ref));
    const std::size_t first = lines.size();
    for (StagedFile& f : stage_error_pictures({o.error_map, o.error_legend, o.error_scale}, errors, ref->width,
                                              ref->height, lines))
      files.push_back(std::move(f));
    for (std::size_t i = first; i < lines.size(); ++i) lines[i] += ", against " + name;
  }
  if (!o.flip_map.empty()) {
    files.push_back(stage_flip_map(o.flip_map, r.errors->flip_map, r.image.width, r.image.height, lines));
    lines.back() += ", against " + name;
  }
  if (!o.triangle_map.empty()) {
    files.push_back(stage_image(o.triangle_map, triangle_map_image(ref->triangle, ref->width, ref->height)));
    lines.push_back("triangle map " + o.triangle_map.string() +
                    ": the reference's visible triangle + 1 per pixel (R high byte)");
  }
  return files;
}

}  // namespace

std::vector<std::string> RenderOutputs::picture_options() const {
  std::vector<std::string> given;
  if (!reference_image.empty()) given.push_back("--reference-image");
  if (!error_map.empty()) given.push_back("--error-map");
  if (!triangle_map.empty()) given.push_back("--triangle-map");
  if (!flip_map.empty()) given.push_back("--flip-map");
  return given;
}

void RenderOutputs::declare(CommandFiles& files) const {
  files.output("-o", image, OutputKind::image);
  files.output("--report", report);
  files.output("--reference-image", reference_image, OutputKind::image);
  files.output("--error-map", error_map, OutputKind::image);
  files.output("--error-legend", error_legend, OutputKind::image);
  files.output("--triangle-map", triangle_map, OutputKind::triangle_map);
  files.output("--flip-map", flip_map, OutputKind::image);
}

std::vector<std::string> RenderOutputs::write(const RenderResult& r) const {
  std::vector<std::string> lines;
  StagedFile staged_image = stage_image(image, r.image);
  std::vector<StagedFile> pictures = stage_pictures(*this, r, lines);
  std::optional<StagedFile> staged_report;
  if (!report.empty()) {
    const RenderReport rr = render_report(r, image);
    staged_report.emplace(stage_text(report, report_text(rr.body, rr.kind)));
  }
  staged_image.commit();
  for (StagedFile& f : pictures) f.commit();
  if (staged_report) staged_report->commit();
  return lines;
}

}  // namespace parashade
