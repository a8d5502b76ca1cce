#pragma once
// Renderer's implementation (parashade/renderer.hpp): its OpenCL buffers, kernels and events, and the
// frame's steps, kept out of the public header so a program that renders needs no OpenCL header.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "parashade/device.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/host_clock.hpp"
#include "parashade/renderer.hpp"

namespace parashade {

struct KernelVariant;   // kernel_variant.hpp
struct TileKernelArgs;  // tile_kernel_args.hpp

// One frame on an OpenCL device: the host stages write into the device's mapped buffers (FrameStorage),
// then the shading kernel runs, then read-back.
class Renderer::Impl : private FrameStorage {
 public:
  // unit_devices (with a plan only): sub-devices of `device`, in its context (sub_devices.hpp), over
  // which the units' depth pass is spread; empty: the units run as work-items of `device`.
  Impl(Device& device, RenderOptions options, std::vector<Device*> unit_devices);
  ~Impl() override;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // Renders one frame. The result stays valid until the next render() (its memory is reused).
  const Frame& render(const Scene& scene);
  // Per pixel (row-major, width x height), how many triangles cover its centre, ignoring depth:
  // the same geometry, tiles and span computation as render(). For watertightness tests.
  std::vector<std::uint32_t> coverage_counts(const Scene& scene);
  // The screen geometry of the last render() or coverage_counts().
  const ScreenGeometry& geometry() const { return pipeline_.geometry(); }
  const RenderOptions& options() const { return options_; }
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

 private:
  // FrameStorage: the record buffers and the tile list, mapped for the host stages (one round trip).
  FrameRecords records(std::size_t n, std::size_t attribute_floats, bool fixed, bool leaves) override;
  // Maps the triangle records, their attributes and the tile list at their capacity now, without waiting,
  // so the map's round trip to the device's threads overlaps the host stages; records() then waits for
  // it, or maps again in the rare frame that needs more room.
  void premap_records();
  void unmap_premapped();
  // The records (tri_bytes), attributes (attr_bytes) and the whole tile list mapped for writing, not waited for.
  void enqueue_record_maps(std::size_t tri_bytes, std::size_t attr_bytes, std::vector<cl::Event>& events);
  std::uint32_t* tile_list(std::size_t entries) override;
  // The host stages into the mapped buffers, then their unmaps and the bins' and row table's uploads
  // (these last take `upload_ms`).
  const PreparedFrame& prepare(const Scene& scene, double* upload_ms = nullptr);
  // The same for band `band` of a frame begun with pipeline_.begin_frame.
  const PreparedFrame& prepare_band(const Scene& scene, int band, double* upload_ms);
  void release_frame();  // unmaps the last frame's image
  // render(), step by step (renderer.cpp).
  void upload_tables(const Scene& scene);
  void prepare_outputs(const Scene& scene, std::size_t counter_bytes);
  cl::Kernel& frame_kernel(const Scene& scene);
  bool counts_per_tile() const;
  void add_tile_counters(const cl_ulong* counters, FrameStats& stats) const;
  double launch_bands(const Scene& scene, int bands, const PreparedFrame* band, const TileKernelArgs& args,
                      cl::Event& done, std::vector<cl::Event>& band_done, Clock::time_point& last);
  struct MappedFrame {
    void* rgba = nullptr;
    const float* planar = nullptr;
    cl::Event mapped, float_mapped;
  };
  MappedFrame map_frame(std::size_t pixels, std::size_t counter_bytes);
  void copy_out(MappedFrame& m, std::size_t pixels, const cl::Event& done);
  // The arguments every pass of render_tiles shares (the frame's buffers), with these tile lists.
  TileKernelArgs tile_args(const cl::Buffer& tile_start, const cl::Buffer& tile_list, cl_float4 viewer,
                           cl_float4 background, const Scene& scene, const PreparedFrame& f) const;
  // planned_frame.cpp: the units' pass before the resolve kernel.
  struct UnitPassEvents {
    std::vector<cl::Event> share;  // per FrameStats::unit_pass entry (none for a share without units)
    std::vector<cl::Event> merge;  // sub-devices: the key merges
  };
  std::vector<UnitPassShare> unit_pass_shares(const Plan& plan) const;
  void enqueue_unit_pass(cl::Kernel& resolve, const KernelVariant& variant, const TileKernelArgs& frame_args,
                         const Plan& plan, const std::vector<UnitPassShare>& shares, std::size_t pixels,
                         UnitPassEvents& events);
  void unit_pass_times(const UnitPassEvents& events, FrameTimings& t) const;
  cl::Buffer& ensure(cl::Buffer& buffer, std::size_t& capacity, std::size_t bytes, cl_mem_flags flags);

  Device& device_;
  RenderOptions options_;  // as given, with the plan's units resolved to the device's compute units
  std::vector<Device*> unit_devices_;
  FramePipeline pipeline_;
  std::unique_ptr<KernelVariant> variant_;  // built once; set_scene adds the scene's lights and viewer
  cl::Kernel kernel_;      // the frame kernel of variant_, rebuilt when the scene's part changes
  std::vector<cl_float4> light_values_, material_values_;  // upload_tables' sources, alive while written
  Frame frame_;
  // The host stages' view of the mapped buffers (FrameStorage), unmapped after prepare.
  FrameRecords mapped_;
  std::uint32_t* mapped_list_ = nullptr;
  std::size_t list_mapped_bytes_ = 0;
  std::vector<cl::Event> premapped_;  // premap_records()'s maps, until records() takes them
  cl::Buffer tris_, attrs_, tile_start_, tile_tris_, lights_, materials_, out_rgba_, out_float_, counts_, fixed_,
      tile_counters_, leaves_, dda_first_, dda_rows_;
  cl::Buffer keys_, plan_packets_, plan_vtiles_, plan_starts_, plan_list_, plan_counter_;
  std::vector<cl::Buffer> share_keys_, share_counters_;  // sub-devices: each one's keys and batch counter
  std::vector<std::size_t> share_keys_cap_, share_counters_cap_;
  std::size_t keys_cap_ = 0, plan_packets_cap_ = 0, plan_vtiles_cap_ = 0, plan_starts_cap_ = 0, plan_list_cap_ = 0,
              plan_counter_cap_ = 0;
  void* mapped_rgba_ = nullptr;   // the last frame's image, mapped for the host until the next render
  void* rgba_host_ = nullptr;     // the memory out_rgba_ was created on (frame_.image.rgba)
  std::size_t tris_cap_ = 0, attrs_cap_ = 0, start_cap_ = 0, list_cap_ = 0, lights_cap_ = 0, materials_cap_ = 0,
              float_cap_ = 0, counts_cap_ = 0, fixed_cap_ = 0, tile_counters_cap_ = 0, leaves_cap_ = 0,
              dda_first_cap_ = 0, dda_rows_cap_ = 0;
};

}  // namespace parashade
