#pragma once
// One render in the library: a request in, a result out (docs/pipeline.md, "The render step"). Every way
// parashade renders a scene for a figure goes through it: `render` on one device, a frame split across
// devices, the units of a plan on sub-devices, `tune`'s candidates, `scaling`'s configurations and the
// MPI ranks of `render --distribute` (distributed.hpp). The request is resolved and checked once, at the
// size and on the devices that will render it, into a ResolvedRender that nothing changes afterwards; a
// RenderSession renders its frames; the result holds the image, the frame medians and stages, the error
// figures and every count the report and the summary print (render_report.hpp).
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "parashade/choice_pixels.hpp"
#include "parashade/combinations.hpp"
#include "parashade/command_files.hpp"
#include "parashade/device.hpp"
#include "parashade/device_layout.hpp"
#include "parashade/image.hpp"
#include "parashade/metrics.hpp"
#include "parashade/reference.hpp"
#include "parashade/register_events.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"
#include "parashade/split_renderer.hpp"

namespace parashade {


// A device selector the request named that cannot be read ("A,A" names a device twice, "sub:X:0"): a
// usage error a front end can prefix with its own option's name.
struct DeviceSelectorError : UsageError {
  using UsageError::UsageError;
};

// What a caller asks for. Values are checked by resolve_render, not here.
// render --flip / --flip-map: LDR-FLIP (flip.hpp) of the frame against one of its references, whose
// ErrorMetrics then carries its mean. About 0.8 s of host time per 1920x1080 frame, so only when asked.
struct FlipRequest {
  bool enabled = false;
  bool against_exact = false;  // exact Phong (ErrorFigures::method), else the method's ideal (implementation)
  bool keep_map = false;       // ErrorFigures::flip_map
};

struct RenderRequest {
  std::filesystem::path scene_file;
  std::optional<std::pair<int, int>> size;  // replaces the scene's resolution (check_resolution'd by the caller)
  RenderOptions options;                    // tile_size 0: chosen for the scene (default_tile_size) or tuned
  // A device selector (device.hpp: index, name substring, "all", "A,B", "sub:NAME:N"); empty: the
  // PARASHADE_DEVICE variable's, else the default device (device.hpp's default_device). A list or sub-devices without a plan split the
  // frame into bands; sub-devices with a plan run the units' depth pass.
  std::string device;
  bool keep_going = false;  // a device list: drop a failing device and go on
  int frames = 5, warmup = 1;
  bool error_figures = true;   // the exact reference and the error against it
  bool keep_reference = false;  // the reference's values and visible triangles in the result (pictures)
  FlipRequest flip;             // LDR-FLIP against a reference (render --flip, --flip-map)
  // The pictures asked for, by option name ("--reference-image", "--error-map", "--triangle-map"): each
  // holds a frame of its own, budgeted with --float against the host memory limit before rendering.
  std::vector<std::string> pictures;
  bool use_tuned = true;       // the best entry of the tune cache for this device, build and problem
  // The kernel shape from the device (device_layout.hpp) instead of options.kernel_shape, where no tuned entry
  // gives one, the frame is on one device and the table of combinations allows it (render, tune).
  bool device_kernel_shape = false;
  std::filesystem::path tune_cache;  // empty: default_tune_cache()
  std::optional<Method> against;     // a plain method whose frames alternate with these (render --against)
  // A device selector naming one device that renders this same request, resolved there as if alone (its
  // tuned entry, kernel shape and layout), its frames alternating with these (render --against-device).
  std::string against_device;
  bool quiet = false;                // no notes in ResolvedRender::notes
};

// The request resolved: the scene at its rendered size, the devices opened, the tuned entry and the
// default tile applied, the plan's units resolved to the device's compute units, the whole configuration
// checked once against the table of combinations (check_frame_config) on these devices.
struct ResolvedRender {
  RenderRequest request;
  Scene scene;
  RenderOptions options;  // final: what the renderer, the pipeline and the kernel variant read
  DeviceMode mode = DeviceMode::one;
  // One; or the list (bands); or the parent and its sub-devices. Shared by the variants of with_options.
  std::vector<std::shared_ptr<Device>> devices;
  nlohmann::json tuned;                          // {cache, params, objective_ms}, or null
  LayoutSources sources;                         // where the shape, work-group, work-items and tile came from
  std::vector<std::string> notes;     // notes for stderr before the work (print_note): the tuned entry taken, stale entries
  std::vector<std::string> warnings;  // the scene's warnings and a tune cache that could not be read
  std::shared_ptr<const ResolvedRender> against_device;  // request.against_device resolved on its device
};

// Devices kept open between requests, by device mode and selector, for a caller that resolves many requests
// in one process (the Python module, docs/python.md): a later request with the same selector takes the same
// devices, and with them the programs they built (device.hpp's program cache, keyed by the kernel variant).
class DeviceCache {
 public:
  struct Entry {
    std::vector<std::shared_ptr<Device>> devices;
    std::vector<std::string> left_out;  // what "all" left out, for its note
  };
  const Entry* find(DeviceMode mode, const std::string& selector) const;
  void keep(DeviceMode mode, const std::string& selector, Entry entry);

 private:
  std::map<std::pair<int, std::string>, Entry> entries_;
};

// Resolves `request`. The scene's files are declared to `files` as inputs (with request.tune_cache) and
// files.check() runs before any device is opened. Throws UsageError, InputError, DeviceError, and
// ConfigError (combinations.hpp) for a refused combination, which names the axes at fault. `devices`, when
// given, supplies devices opened before for the same selector and keeps those opened now.
ResolvedRender resolve_render(RenderRequest request, CommandFiles& files, DeviceCache* devices = nullptr);

// The same scene on the same devices with other options (tune's candidates, scaling's configurations):
// `options` checked against the table and resolved as resolve_render resolves them (tile 0: the scene's
// default; the plan's units 0: the device's compute units; the work-group 0: the device's); no tuned entry is
// looked up, and the shape is `options`'.
ResolvedRender with_options(const ResolvedRender& base, const RenderOptions& options);

// The kernel shape `device` takes for `options` on `mode` when the request leaves it to the device: its own
// (device_layout.hpp's device_kernel_shape) where the table of combinations allows it, else options'.
struct DeviceShape {
  KernelShape shape = KernelShape::vector;
  // Where it came from (LayoutSources::kernel_shape): kFromDevice, or "option (the device's lanes refused:
  // WHY)" when the device's own was not taken.
  std::string source;
  std::string refused;  // empty, or one sentence saying why the device's own was not taken (a note)
};
DeviceShape device_shape_for(const DeviceInfo& device, const RenderOptions& options, DeviceMode mode);

// Options checked against the table of combinations on `mode` (check_frame_config; tile 0 counts as valid,
// it is chosen later): the one check of a configuration, made by resolve_render and with_options, and by
// the commands that check a list of configurations before any file is read (scaling, plan).
void check_render_options(const RenderOptions& options, DeviceMode mode);

// The error of a frame against the exact reference.
struct ErrorFigures {
  ErrorMetrics implementation;  // against the method's own ideal
  ErrorMetrics method;          // against exact Phong
  std::optional<ChoicePixels> choice_pixels;  // a per-triangle choice: visible pixels per method
  std::optional<ReferenceImage> reference;    // when asked for (pictures)
  std::vector<float> flip_map;                // FlipRequest::keep_map: LDR-FLIP per pixel
};

// The exact reference of `scene` for `options`' method and the image's error against it (and its FLIP when
// `flip` asks).
ErrorFigures error_figures(const Scene& scene, const RenderOptions& options, const RenderedImage& image,
                           bool keep_reference, const FlipRequest& flip = {});
// The exact reference of `scene` shaded by `method` (its ideal and exact Phong), for callers that compare
// many frames of one scene against it (tune, scaling), and a frame's error against it.
ReferenceImage exact_reference(const Scene& scene, Method method);
ErrorFigures error_against(const ReferenceImage& ref, Method method, const RenderedImage& image);
// "ideal gouraud", ...; the combined method's ideal is Phong's (its segment ends are exact Phong).
std::string ideal_name(Method method);

// One device's band of a split frame.
using DeviceShare = SplitRenderer::Share;

// --against's frames: the other method's stage medians and the pairs' ratios (other / this).
struct AgainstSummary {
  std::string method;
  std::string device;  // --against-device: the other device's name (method is then this render's); else empty
  FrameTimings medians;
  std::vector<double> samples_ms, frame_ratios, kernel_ratios;
};

struct RankFigures;  // distributed.hpp
struct DistributedFigures;

struct RenderResult {
  std::string scene_name;
  std::filesystem::path scene_file;
  int width = 0, height = 0;
  std::uint64_t mesh_vertices = 0, mesh_triangles = 0;  // the scene's meshes as the memory budget counts them
  RenderOptions options;
  DeviceMode mode = DeviceMode::one;
  std::vector<DeviceInfo> devices;  // the device (first) and, split, the others
  nlohmann::json tuned;
  LayoutSources sources;
  int frames = 0, warmup = 0;
  RenderedImage image;
  FrameStats stats;                 // the last timed frame's
  FrameTimings medians;             // per stage over the timed frames
  std::vector<double> frame_ms;     // the timed frames, whole
  int work_items = 0;
  std::optional<int> deferral;      // the kernel's deferral threshold, where it defers
  std::string kernel_build;         // the frame kernel's -D options: every knob that reached it
  std::vector<DeviceShare> shares;  // a split frame
  std::optional<AgainstSummary> against;
  std::optional<ErrorFigures> errors;
  std::optional<RegisterEvents> registers;  // fixed point: wraps and saturations (golden models)
  std::shared_ptr<const DistributedFigures> distributed;  // render --distribute (rank 0)
  std::vector<std::string> warnings;  // a split frame's dropped devices
};


// The renderer(s) of a resolved render kept between frames, for callers that interleave frames of
// several configurations (scaling, tune's confirmation, --against).
class RenderSession {
 public:
  explicit RenderSession(const ResolvedRender& r);
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;
  // One frame; `warning` receives a split renderer's dropped device, when any.
  const Frame& frame(std::string* warning = nullptr);
  int work_items(int tiles) const;
  std::optional<int> deferral_threshold() const;
  std::string kernel_build() const;
  std::vector<DeviceShare> shares() const;

 private:
  const ResolvedRender& r_;
  std::vector<Device*> unit_devices_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<SplitRenderer> split_;
};

// Renders a resolved request: warm-up, the timed frames (`progress(done, total)` after each, when given),
// then the error figures and the register events.
RenderResult render(const ResolvedRender& r, const std::function<void(int, int)>& progress = {});
// The same with a session kept by the caller (made from `r`, which it reads at each frame): a caller that
// renders the same resolved request again (the Python module) keeps its renderer, buffers and kernels.
RenderResult render(const ResolvedRender& r, RenderSession& session, const std::function<void(int, int)>& progress = {});

}  // namespace parashade
