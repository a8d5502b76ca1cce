#pragma once
// One frame on an OpenCL device: the host stages ("software", frame_pipeline.hpp) write into the device's
// mapped buffers, then the shading kernel (the modeled hardware units) runs, then read-back.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parashade/device.hpp"
#include "parashade/frame_config.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/frame_stats.hpp"
#include "parashade/host_clock.hpp"
#include "parashade/image.hpp"
#include "parashade/scene.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {

// The largest RenderOptions::defer_min_triangles (render --defer-min-triangles): above any tile's list on a
// real frame, so it means "never defer".
constexpr int kMaxDeferMinTriangles = 1 << 24;

// A frame's configuration (frame_config.hpp) and how the device runs it.
struct RenderOptions : FrameConfig {
  bool float_output = false;  // also read back unclamped float RGB (for EXR and exact error figures)
  int work_items = 0;  // kernel work-items, each rendering every G-th tile; 0: the device's (device_layout.hpp)
  // Work-items per work-group, the kernel's local size (--work-group-size; 0: the shape's default). The vector
  // shape's each walk tiles of their own (default 1, work_items rounded up to a multiple); the lanes shape's are one
  // tile's pixel lanes, each owning tile x tile / N of its pixels (default LANES_WORK_GROUP_DEFAULT, at most the
  // tile's pixels). A power of two, at most the device's largest work-group. The image is the same.
  int work_group_size = 0;
  // work_group_size with its default resolved for the shape and tile.
  int group_size() const { return work_group_size > 0 ? work_group_size : shape_work_group_size(kernel_shape, tile_size); }
  // The kernel's pixel layout where the frame allows a choice (docs/pipeline.md): 4x4 stamps (true) or
  // 1x16 row segments. The image is the same either way.
  bool stamps = true;
  // Phong and combined:0 on stamps: a tile holding at least this many triangles is shaded after its walk, each
  // pixel once by the triangle that won its depth test (docs/pipeline.md); -1: the default (every tile for
  // Phong, TILE * TILE / 16 for the combined method, whose Gouraud and segment triangles shade in the walk),
  // 0: every tile.
  // Same image.
  int defer_min_triangles = -1;  // at most kMaxDeferMinTriangles
  // defer_min_triangles with its default resolved for this method and tile size.
  int deferral_threshold() const {
    if (defer_min_triangles >= 0) return defer_min_triangles;
    return method == Method::phong ? 0 : tile_size * tile_size / 16;
  }
  // A frame whose triangle records would take more bytes than this is prepared and shaded in bands of
  // tile rows (FramePipeline::begin_frame), which bounds the frame's peak memory (bench/README.md);
  // kBandBytesByFrame: by the frame's size (default_band_mib, kDefaultBandBytes); SIZE_MAX: never.
  std::size_t band_record_bytes = kBandBytesByFrame;
  // Build options appended to the frame kernel's own ("-D NAME=VALUE ..."): two builds of the same kernel
  // source told apart by a macro, for bench_kernel_ab's frame-by-frame comparison. Empty in normal use.
  std::string kernel_defines;
};

// The work-group size (RenderOptions::group_size) a frame can run with: a power of two up to MAX_WORK_GROUP_SIZE, in
// the lanes shape within the tile's pixels (each work-item owns a share; not checked while the tile is 0, still
// to be chosen), and within `device`'s largest work-group when given. UsageError naming --work-group-size.
void check_work_group_size(const RenderOptions& o, const DeviceInfo* device = nullptr);

struct Frame {
  RenderedImage image;
  FrameTimings timings;
  FrameStats stats;
};

// Renders frames on one device: the host stages through a FramePipeline writing into the device's
// mapped buffers, then the tile kernel (the modeled units), then read-back. Its OpenCL side (buffers,
// kernels, events) lives in Renderer::Impl (host/cl/renderer_impl.hpp), out of this header.
class Renderer {
 public:
  // unit_devices (with a plan only): sub-devices of `device`, in its context (sub_devices.hpp), over
  // which the units' depth pass is spread; empty: the units run as work-items of `device`.
  Renderer(Device& device, RenderOptions options, std::vector<Device*> unit_devices = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  // Renders one frame. The result stays valid until the next render() (its memory is reused).
  const Frame& render(const Scene& scene);
  // Per pixel (row-major, width x height), how many triangles cover its centre, ignoring depth:
  // the same geometry, tiles and span computation as render(). For watertightness tests.
  std::vector<std::uint32_t> coverage_counts(const Scene& scene);
  // The screen geometry of the last render() or coverage_counts().
  const ScreenGeometry& geometry() const;
  // The options as given, with the plan's units resolved to the device's compute units.
  const RenderOptions& options() const;
  // Shade only tile rows [first, first + rows) from the next render() on (the rest is background), as if
  // constructed with band_first / band_rows: a moved band keeps the programs, buffers and mapped memory.
  void set_band(int first, int rows);
  // Work-items the kernel runs with for a frame of `tiles` tiles.
  int work_items(int tiles) const;
  // The deferral threshold the scene's kernel uses (RenderOptions::deferral_threshold), or none where its
  // kernel never defers (Gouraud, flat, the unit paths, span normalization, segments).
  std::optional<int> deferral_threshold(const Scene& scene) const;
  // A planned frame's depth keys after render() (kernels/plan_key.h: per pixel, row-major, the least
  // (depth, record index) key, PLAN_NO_KEY where nothing covers it): what sort-last ranks composite.
  std::vector<std::uint64_t> plan_keys(const Scene& scene);
  // The -D options the last frame's kernel was built with (its variant: every knob that reached the
  // kernel), or "" before the first frame.
  std::string kernel_build() const;

  class Impl;  // host/cl/renderer_impl.hpp

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace parashade
