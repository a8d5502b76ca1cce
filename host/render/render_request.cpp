// A render request resolved once (render_step.hpp): the options checked against the table, the scene at
// its rendered size, the files checked, the devices opened, the tuned entry and the default tile applied.
#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "parashade/combined.hpp"
#include "parashade/device_layout.hpp"
#include "parashade/errors.hpp"
#include "parashade/render_step.hpp"
#include "parashade/scene_files.hpp"
#include "parashade/split_renderer.hpp"
#include "parashade/sub_devices.hpp"
#include "parashade/tile_choice.hpp"
#include "frame_memory.hpp"
#include "tune_cache.hpp"

namespace parashade {
namespace {

// Where the devices come from: the request's selector, else PARASHADE_DEVICE (docs/environment.md), else
// the default device (device.hpp's default_device, said in a note). Errors of a selector from the variable name it, since no command line shows it.
struct Selector {
  std::string text, origin;
};

Selector selector_of(const std::string& given) {
  if (!given.empty()) return {given, ""};
  const char* value = std::getenv("PARASHADE_DEVICE");
  if (!value || !*value) return {"", ""};
  return {value, "PARASHADE_DEVICE='" + std::string(value) + "' (the device when none is given)"};
}

template <typename Open>
auto opened(const Selector& s, Open&& open) {
  try {
    return open();
  } catch (const UsageError& e) {
    if (s.origin.empty()) throw DeviceSelectorError(e.what());
    throw UsageError(s.origin + ": " + e.what());
  } catch (const Error& e) {
    if (s.origin.empty()) throw;
    throw Error(e.code(), s.origin + ": " + e.what());
  }
}

DeviceMode mode_of(const std::string& selector, const RenderOptions& o) {
  if (o.plan && is_sub_device_selector(selector)) return DeviceMode::unit_sub_devices;
  return is_device_list(selector) ? DeviceMode::bands : DeviceMode::one;
}

// The devices `s` names for `mode`, opened; `left_out`: what "all" leaves out.
std::vector<std::shared_ptr<Device>> open_selected(DeviceMode mode, const Selector& s, std::vector<std::string>& left_out) {
  std::vector<std::shared_ptr<Device>> devices;
  if (mode == DeviceMode::bands) {
    for (auto& d : opened(s, [&] { return open_devices(s.text, &left_out); })) devices.push_back(std::move(d));
  } else if (mode == DeviceMode::unit_sub_devices) {
    SubDevices sub = opened(s, [&] { return open_sub_devices(s.text, SubDeviceContext::shared); });
    devices.push_back(std::move(sub.parent));
    for (auto& d : sub.subs) devices.push_back(std::move(d));
  } else {
    devices.push_back(opened(s, [&] { return open_device(s.text); }));
  }
  return devices;
}

void open_devices_for(ResolvedRender& r, const Selector& s, DeviceCache* cache) {
  std::vector<std::string> left_out;
  const DeviceCache::Entry* kept = cache ? cache->find(r.mode, s.text) : nullptr;
  if (kept) {
    r.devices = kept->devices;
    left_out = kept->left_out;
  } else {
    r.devices = open_selected(r.mode, s, left_out);
    if (cache) cache->keep(r.mode, s.text, {r.devices, left_out});
  }
  std::string names;
  for (const std::string& n : left_out) names += (names.empty() ? "" : ", ") + n;
  if (!names.empty() && !r.request.quiet)
    r.notes.push_back("device list 'all' leaves out " + names +
                      "; name the devices to split across them (A,B)");
  if (r.mode == DeviceMode::one && takes_default_device(s.text) && !r.request.quiet)
    r.notes.push_back(default_device_note(r.devices.front()->info()));
}

// The tune cache's best entry for this device, build and problem, applied to r.options; a refused or
// unreadable entry is not used (a warning says why).
void apply_tuned(ResolvedRender& r) {
  const std::optional<TuneProblem> problem = tune_problem(r.scene, r.options);
  if (!r.request.use_tuned || !problem) return;
  const std::filesystem::path path = r.request.tune_cache.empty() ? default_tune_cache() : r.request.tune_cache;
  const DeviceInfo& dev = r.devices.front()->info();
  try {
    const TuneCache cache(path);
    if (const std::string aside = cache.set_aside(); !aside.empty()) r.warnings.push_back(aside);
    if (const std::string stale = cache.stale_entries(dev, &*problem); !stale.empty() && !r.request.quiet)
      r.notes.push_back(stale);
    const auto best = cache.best(dev, *problem);
    if (!best) return;
    RenderOptions tuned = r.options;
    apply_tuned_params(best->at("params"), tuned);
    check_render_options(tuned, r.mode);
    r.options = tuned;
    r.tuned = {{"cache", path.string()}, {"params", best->at("params")}, {"objective_ms", best->at("objective")}};
    r.notes.push_back("using the tuned configuration " + best->at("params").dump() + " from " + path.string() +
                      " (--no-tuned to disable)");
  } catch (const InputError& e) {
    r.warnings.push_back(std::string("tune cache not used: ") + e.what());
  } catch (const UsageError& e) {
    r.warnings.push_back(std::string("tune cache entry not used: ") + e.what());
  }
}

// The layout values left to the device and the scene: the tile (0: the scene's default; a split frame's
// bands keep TILE_DEFAULT) and the plan's units (0: the device's compute units).
void resolve_layout(ResolvedRender& r) {
  if (r.options.tile_size == 0)
    r.options.tile_size = r.mode == DeviceMode::bands ? TILE_DEFAULT
                                                      : default_tile_size(r.scene, r.options, r.options.band_record_bytes);
  if (r.options.plan && r.options.plan->units == 0)
    r.options.plan->units = std::max(1, r.devices.front()->info().compute_units);
}

// The shape from the device where the request leaves it to the device, no tuned entry gave one and the frame
// is on one device (device_shape_for), and where it came from; a shape the frame cannot take is said in a note.
void take_device_shape(ResolvedRender& r) {
  const bool tuned = !r.tuned.is_null();
  r.sources.kernel_shape = tuned ? kFromTuneCache : kFromOption;
  if (!r.request.device_kernel_shape || tuned || r.mode != DeviceMode::one) return;
  const DeviceShape taken = device_shape_for(r.devices.front()->info(), r.options, r.mode);
  r.options.kernel_shape = taken.shape;
  r.sources.kernel_shape = taken.source;
  if (!taken.refused.empty() && !r.request.quiet) r.notes.push_back(taken.refused);
}

// The work-group the device allows where neither the request nor a tuned entry gave one (after the tile is
// known: the lanes shape's work-group is within its pixels), and where the other layout settings came from
// (the shape's: take_device_shape).
// `asked`: the request's options, before the tuned entry.
void take_device_layout(ResolvedRender& r, const RenderOptions& asked) {
  const bool tuned = !r.tuned.is_null();
  const std::string chosen = tuned ? kFromTuneCache : kFromDevice;
  LayoutSources& s = r.sources;
  s.tile = asked.tile_size ? kFromOption : tuned ? kFromTuneCache : kFromFrame;
  s.work_items = asked.work_items ? kFromOption : chosen;
  s.work_group_size = asked.work_group_size ? kFromOption : chosen;
  // An entry tuned at the default work-group (0) gets the device's, as an untuned run does: the lanes
  // default (256) may be over the device's largest work-group.
  if (r.options.work_group_size != 0) return;
  const int n = device_work_group_size(r.devices.front()->info(), r.options.kernel_shape, r.options.tile_size);
  if (n != r.options.group_size()) r.options.work_group_size = n;
}

// A budget below its floor (issue 46, item 18) is said, not refused: the 8-bit rounding plus float Phong's
// own error, which no choice of methods can remove.
void note_error_floor(ResolvedRender& r) {
  const CombinedConfig& c = r.options.combined;
  if (r.request.quiet || r.options.method != Method::combined || !(c.automatic || c.rule == TriangleRule::bound)) return;
  const double phong = phong_float_error_bound(r.scene), floor = 0.5 + phong;
  if (!(c.max_error < floor)) return;
  char text[480];
  std::snprintf(text, sizeof text,
                "--max-error %.3g is below its floor on this scene, %.3g levels: the 8-bit rounding "
                "(0.5) plus float Phong's own error (at most %.3g levels here, docs/error-bounds.md). The budget "
                "bounds the distance to Phong's float image; against ideal Phong the image may be off by that much "
                "more, as --method phong's is",
                c.max_error, floor, phong);
  r.notes.push_back(text);
}

// Every layout step after the devices are opened, in order: the tuned entry, the device's shape, the tile
// and units, the device's work-group.
void resolve_on_devices(ResolvedRender& r) {
  if (r.mode == DeviceMode::one || r.mode == DeviceMode::unit_sub_devices) apply_tuned(r);
  take_device_shape(r);
  resolve_layout(r);
  take_device_layout(r, r.request.options);
}

// render --against-device: this request on one other device, resolved there as it would be alone; its notes
// and warnings are said with the option's name. Both sides are one device each: a pair compares two devices.
void resolve_against_device(ResolvedRender& r, DeviceCache* cache) {
  const std::string& selector = r.request.against_device;
  if (selector.empty()) return;
  if (r.request.against)
    throw UsageError("--against and --against-device: one renderer to pair with at a time");
  if (r.mode != DeviceMode::one || is_device_list(selector) || is_sub_device_selector(selector))
    throw UsageError("--against-device pairs frames of one device with another's; not with a device list, "
                     "sub-devices or a plan on them ('" + (r.mode == DeviceMode::one ? selector : r.request.device) + "')");
  auto a = std::make_shared<ResolvedRender>();
  a->request = r.request;
  a->request.device = selector;
  a->request.against_device.clear();
  a->scene = r.scene;
  a->options = a->request.options;
  a->mode = DeviceMode::one;
  open_devices_for(*a, {selector, "--against-device '" + selector + "'"}, cache);
  resolve_on_devices(*a);
  for (const std::string& n : a->notes) r.notes.push_back("--against-device: " + n);
  for (const std::string& w : a->warnings) r.warnings.push_back("--against-device: " + w);
  r.against_device = std::move(a);
}

}  // namespace

const DeviceCache::Entry* DeviceCache::find(DeviceMode mode, const std::string& selector) const {
  const auto it = entries_.find({int(mode), selector});
  return it == entries_.end() ? nullptr : &it->second;
}

void DeviceCache::keep(DeviceMode mode, const std::string& selector, Entry entry) {
  entries_[{int(mode), selector}] = std::move(entry);
}

void check_render_options(const RenderOptions& options, DeviceMode mode) {
  check_work_group_size(options);
  if (options.kernel_shape == KernelShape::lanes && options.defer_min_triangles > 0)
    throw UsageError("--defer-min-triangles " + std::to_string(options.defer_min_triangles) +
                     ": the lanes shape shades every tile's pixels once after its depth test (0); the threshold is the "
                     "vector shape's");
  RenderOptions o = options;
  if (o.tile_size == 0) o.tile_size = TILE_DEFAULT;  // chosen later from the valid sizes
  check_frame_config(o, mode);
}

DeviceShape device_shape_for(const DeviceInfo& device, const RenderOptions& options, DeviceMode mode) {
  RenderOptions o = options;
  o.kernel_shape = device_kernel_shape(device);
  if (o.kernel_shape == options.kernel_shape) return {o.kernel_shape, kFromDevice, ""};
  try {
    check_render_options(o, mode);
    return {o.kernel_shape, kFromDevice, ""};
  } catch (const Error& e) {  // ConfigError or UsageError: what the device's shape does not run
    const std::string own = kernel_shape_name(o.kernel_shape);
    return {options.kernel_shape, std::string(kFromOption) + " (the device's " + own + " refused: " + e.what() + ")",
            std::string("the ") + kernel_shape_name(options.kernel_shape) + " kernel shape on " + device.name +
                ", whose own is " + own + " (docs/pipeline.md), which this frame cannot take: " + e.what()};
  }
}

ResolvedRender resolve_render(RenderRequest request, CommandFiles& files, DeviceCache* devices) {
  ResolvedRender r;
  const Selector selector = selector_of(request.device);
  r.mode = mode_of(selector.text, request.options);
  check_render_options(request.options, r.mode);
  files.check_folders();  // before the scene, whose loading may take many seconds
  std::vector<std::filesystem::path> inputs;
  r.scene = load_scene(request.scene_file, inputs, request.size);
  check_frame_memory(r.scene, request);
  files.scene(inputs);
  files.input("--triangle-choice list:", request.options.combined.list_file);
  if (request.use_tuned || !request.tune_cache.empty())
    files.input("--tune-cache", request.tune_cache.empty() ? default_tune_cache() : request.tune_cache);
  files.check();
  r.warnings = r.scene.warnings;
  r.options = request.options;
  r.request = std::move(request);
  open_devices_for(r, selector, devices);
  resolve_on_devices(r);
  note_error_floor(r);
  resolve_against_device(r, devices);
  return r;
}

ResolvedRender with_options(const ResolvedRender& base, const RenderOptions& options) {
  check_render_options(options, base.mode);
  ResolvedRender r;
  r.request = base.request;
  r.request.options = options;
  r.request.device_kernel_shape = false;  // the shape is the caller's
  r.scene = base.scene;
  r.options = options;
  r.mode = base.mode;
  r.devices = base.devices;
  resolve_layout(r);
  take_device_layout(r, options);
  return r;
}

}  // namespace parashade
