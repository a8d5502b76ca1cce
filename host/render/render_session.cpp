// The frames of a resolved render and what they measured (render_step.hpp).
#include "against_frames.hpp"
#include "frame_medians.hpp"
#include "parashade/render_step.hpp"
#include "parashade/output_file.hpp"
#include "parashade/split_renderer.hpp"

namespace parashade {
namespace {

// What was rendered, before any frame: the request as resolved.
RenderResult describe(const ResolvedRender& r) {
  RenderResult out;
  out.scene_name = r.scene.name;
  out.scene_file = r.request.scene_file;
  out.width = r.scene.width;
  out.height = r.scene.height;
  for (const Object& o : r.scene.objects) {
    out.mesh_vertices += o.mesh->positions.size();
    out.mesh_triangles += o.mesh->triangles.size();
  }
  out.options = r.options;
  out.mode = r.mode;
  for (const auto& d : r.devices)
    if (r.mode == DeviceMode::bands || out.devices.empty()) out.devices.push_back(d->info());
  out.tuned = r.tuned;
  out.sources = r.sources;
  out.frames = r.request.frames;
  out.warmup = r.request.warmup;
  return out;
}

// The frames: warm-up, then the timed ones; --against's frames alternate with them a pair at a time.
void run_frames(const ResolvedRender& r, RenderSession& session, RenderResult& out,
                const std::function<void(int, int)>& progress) {
  std::optional<AgainstFrames> against;
  if (r.request.against) against.emplace(*r.devices.front(), r.scene, *r.request.against, r.options.band_record_bytes);
  if (r.against_device) against.emplace(*r.against_device);
  const int total = r.request.warmup + r.request.frames;
  std::string warning;
  const auto frame = [&]() -> const Frame& {
    const Frame& f = session.frame(&warning);
    reclaim_signal_cleanup();  // LLVM takes SIGQUIT and SIGUSR1 when a kernel is first compiled or linked
    if (!warning.empty()) out.warnings.push_back(warning), warning.clear();
    return f;
  };
  for (int i = 0; i < r.request.warmup; ++i) {
    frame();  // builds programs, compiles work-group functions
    if (against) against->warm_up(r.scene);
    if (progress) progress(i + 1, total);
  }
  std::vector<FrameTimings> timings;
  const Frame* last = nullptr;
  for (int i = 0; i < r.request.frames; ++i) {
    if (against && AgainstFrames::first_in_pair(i)) against->frame(r.scene);
    last = &frame();
    if (against && !AgainstFrames::first_in_pair(i)) against->frame(r.scene);
    timings.push_back(last->timings);
    out.frame_ms.push_back(last->timings.total_ms);
    if (progress) progress(r.request.warmup + i + 1, total);
  }
  out.image = last->image;
  out.stats = last->stats;
  out.medians = median_timings(timings);
  if (against) out.against = against->summary(timings);
}

}  // namespace

RenderSession::RenderSession(const ResolvedRender& r) : r_(r) {
  if (r.mode == DeviceMode::bands) {
    std::vector<Device*> devices;
    for (const auto& d : r.devices) devices.push_back(d.get());
    split_ = std::make_unique<SplitRenderer>(devices, r.options, r.request.keep_going);
    return;
  }
  for (std::size_t i = 1; i < r.devices.size(); ++i) unit_devices_.push_back(r.devices[i].get());
  renderer_ = std::make_unique<Renderer>(*r.devices.front(), r.options, unit_devices_);
}

RenderSession::~RenderSession() = default;

const Frame& RenderSession::frame(std::string* warning) {
  return split_ ? split_->render(r_.scene, warning) : renderer_->render(r_.scene);
}

int RenderSession::work_items(int tiles) const { return renderer_ ? renderer_->work_items(tiles) : 0; }

std::optional<int> RenderSession::deferral_threshold() const {
  return renderer_ ? renderer_->deferral_threshold(r_.scene) : std::nullopt;
}

std::string RenderSession::kernel_build() const { return renderer_ ? renderer_->kernel_build() : std::string(); }

std::vector<DeviceShare> RenderSession::shares() const { return split_ ? split_->shares() : std::vector<DeviceShare>{}; }

RenderResult render(const ResolvedRender& r, const std::function<void(int, int)>& progress) {
  RenderSession session(r);
  return render(r, session, progress);
}

RenderResult render(const ResolvedRender& r, RenderSession& session, const std::function<void(int, int)>& progress) {
  RenderResult out = describe(r);
  run_frames(r, session, out, progress);
  out.work_items = session.work_items(out.stats.tiles);
  out.deferral = session.deferral_threshold();
  out.kernel_build = session.kernel_build();
  out.shares = session.shares();
  // A split frame's bands come from several devices: no error figures in that mode.
  if (r.request.error_figures && r.mode != DeviceMode::bands)
    out.errors = error_figures(r.scene, r.options, out.image, r.request.keep_reference, r.request.flip);
  // Fixed point: the registers' wraps and saturations, from the golden models (the kernels count none).
  if (r.options.arith.fixed && r.mode != DeviceMode::bands) out.registers = count_register_events(r.scene, r.options);
  return out;
}

}  // namespace parashade
