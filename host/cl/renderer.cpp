#include "renderer_impl.hpp"

#include <chrono>
#include <cstring>
#include <utility>

#include <glm/glm.hpp>

#include "kernel_variant.hpp"
#include "parashade/device_layout.hpp"
#include "parashade/errors.hpp"
#include "parashade/host_clock.hpp"
#include "shading_tables.hpp"
#include "tile_kernel_args.hpp"

namespace parashade {
namespace {

double event_ms(const cl::Event& e) {
  const auto start = e.getProfilingInfo<CL_PROFILING_COMMAND_START>();
  const auto end = e.getProfilingInfo<CL_PROFILING_COMMAND_END>();
  return double(end - start) * 1e-6;
}

// A streamed frame's band after the first: its setup, binning with the bins' upload, and counts.
void add_band(const PreparedFrame& band, double upload_ms, FrameTimings& t, FrameStats& s) {
  t.setup_ms += band.timings.setup_ms;
  t.binning_ms += band.timings.binning_ms + upload_ms;
  s.triangles_without_pixels += band.stats.triangles_without_pixels;
  s.bin_entries += band.stats.bin_entries;
}

}  // namespace

namespace {

// The options with the plan's units resolved (0: the device's compute units).
RenderOptions resolved_units(RenderOptions o, const Device& device) {
  if (o.plan && o.plan->units == 0) o.plan->units = std::max(1, device.info().compute_units);
  return o;
}

}  // namespace

Renderer::Impl::Impl(Device& device, RenderOptions options, std::vector<Device*> unit_devices)
    : device_(device),
      options_(resolved_units(options, device)),
      unit_devices_(std::move(unit_devices)),
      pipeline_(options_),  // checks the configuration against the table, once
      variant_(std::make_unique<KernelVariant>(kernel_variant(options_))) {
  check_work_group_size(options_, &device_.info());
  if (!unit_devices_.empty() && !options_.plan)
    throw UsageError("sub-devices run a plan's units; without a plan, sub-devices take bands of the frame");
  for (Device* d : unit_devices_)
    if (d->context()() != device_.context()())
      throw DeviceError("'" + d->info().name + "' does not share the context of '" + device_.info().name +
                        "': open the units' sub-devices with a shared context (sub_devices.hpp)");
  // The units' depth pass keeps each pixel's least key by a 64-bit atomic minimum (plan_key.h): without
  // the extension its build would fail on an undeclared atom_min; say what is missing instead.
  if (options_.plan) {
    std::vector<Device*> pass_devices = unit_devices_;
    if (pass_devices.empty()) pass_devices.push_back(&device_);
    for (Device* d : pass_devices)
      if (d->device().getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_int64_extended_atomics") == std::string::npos)
        throw DeviceError("a plan's units need 64-bit atomics (cl_khr_int64_extended_atomics) for their depth pass; '" +
                          d->info().name + "' does not have them");
  }
}

void Renderer::Impl::set_band(int first, int rows) {
  if (options_.plan && rows >= 0)
    throw UsageError("planned units run on one device, or on the sub-devices of one, not in bands");
  pipeline_.set_band(first, rows);
  options_.band_first = first;
  options_.band_rows = rows;
}

cl::Buffer& Renderer::Impl::ensure(cl::Buffer& buffer, std::size_t& capacity, std::size_t bytes, cl_mem_flags flags) {
  bytes = std::max<std::size_t>(bytes, 64);
  if (bytes > capacity) {
    if (bytes > device_.info().max_allocation)
      throw DeviceError("a buffer of " + std::to_string(bytes) + " bytes exceeds the device's largest allocation (" +
                        std::to_string(device_.info().max_allocation) + " bytes) on '" + device_.info().name + "'");
    // Grow by half to spare reallocations, but never past what the device can allocate in one buffer.
    const std::size_t grown = std::min<std::size_t>(std::max(bytes, capacity + capacity / 2), device_.info().max_allocation);
    buffer = cl::Buffer(device_.context(), flags | CL_MEM_ALLOC_HOST_PTR, grown);
    capacity = grown;
  }
  return buffer;
}

// Every blocking OpenCL call costs a round trip to the device's threads (~60 us on PoCL here), so the
// input buffers are mapped together: the tile list at its current capacity, since binning's size is
// known only later (it is mapped again in the rare frame it must grow).
void Renderer::Impl::enqueue_record_maps(std::size_t tri_bytes, std::size_t attr_bytes, std::vector<cl::Event>& events) {
  cl::CommandQueue& q = device_.queue();
  events.resize(3);
  mapped_ = FrameRecords{};
  mapped_.triangles = static_cast<TriangleGeometry*>(
      q.enqueueMapBuffer(tris_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, tri_bytes, nullptr, &events[0]));
  mapped_.attributes = static_cast<float*>(
      q.enqueueMapBuffer(attrs_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, attr_bytes, nullptr, &events[1]));
  list_mapped_bytes_ = list_cap_;
  mapped_list_ = static_cast<std::uint32_t*>(
      q.enqueueMapBuffer(tile_tris_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, list_mapped_bytes_, nullptr, &events[2]));
}

void Renderer::Impl::premap_records() {
  if (!premapped_.empty() || tris_cap_ == 0) return;  // mapped already, or no frame yet to size them
  enqueue_record_maps(tris_cap_, attrs_cap_, premapped_);
}

void Renderer::Impl::unmap_premapped() {
  if (premapped_.empty()) return;
  cl::CommandQueue& q = device_.queue();
  q.enqueueUnmapMemObject(tris_, mapped_.triangles);
  q.enqueueUnmapMemObject(attrs_, mapped_.attributes);
  q.enqueueUnmapMemObject(tile_tris_, mapped_list_);
  mapped_ = FrameRecords{};
  mapped_list_ = nullptr;
  premapped_.clear();
}

FrameRecords Renderer::Impl::records(std::size_t n, std::size_t attribute_floats, bool fixed, bool leaves) {
  cl::CommandQueue& q = device_.queue();
  const std::size_t tri_bytes = std::max<std::size_t>(64, n * sizeof(TriangleGeometry));
  const std::size_t attr_bytes = std::max<std::size_t>(64, n * attribute_floats * sizeof(float));
  const std::size_t list_bytes = std::max<std::size_t>(64, 2 * n * sizeof(std::uint32_t));
  if (!premapped_.empty() && (tri_bytes > tris_cap_ || attr_bytes > attrs_cap_ || list_bytes > list_cap_))
    unmap_premapped();  // too small for this frame: grown and mapped below
  std::vector<cl::Event> mapped;
  if (!premapped_.empty()) {
    mapped.swap(premapped_);
  } else {
    ensure(tris_, tris_cap_, tri_bytes, CL_MEM_READ_ONLY);
    ensure(attrs_, attrs_cap_, attr_bytes, CL_MEM_READ_ONLY);
    ensure(tile_tris_, list_cap_, list_bytes, CL_MEM_READ_ONLY);
    enqueue_record_maps(tri_bytes, attr_bytes, mapped);
  }
  if (fixed) {
    const std::size_t fixed_bytes = std::max<std::size_t>(64, n * sizeof(FixedPlanes));
    ensure(fixed_, fixed_cap_, fixed_bytes, CL_MEM_READ_ONLY);
    mapped_.fixed = static_cast<FixedPlanes*>(
        q.enqueueMapBuffer(fixed_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, fixed_bytes, nullptr, &mapped.emplace_back()));
  }
  const std::size_t leaf_bytes = std::max<std::size_t>(64, (leaves ? n : 0) * sizeof(SierpinskiLeaf));
  ensure(leaves_, leaves_cap_, leaf_bytes, CL_MEM_READ_ONLY);
  if (leaves)
    mapped_.leaves = static_cast<SierpinskiLeaf*>(
        q.enqueueMapBuffer(leaves_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, leaf_bytes, nullptr, &mapped.emplace_back()));
  cl::Event::waitForEvents(mapped);
  return mapped_;
}

std::uint32_t* Renderer::Impl::tile_list(std::size_t entries) {
  const std::size_t list_bytes = entries * sizeof(std::uint32_t);
  if (list_bytes > list_mapped_bytes_) {
    cl::CommandQueue& q = device_.queue();
    q.enqueueUnmapMemObject(tile_tris_, mapped_list_);
    ensure(tile_tris_, list_cap_, list_bytes, CL_MEM_READ_ONLY);
    mapped_list_ = static_cast<std::uint32_t*>(
        q.enqueueMapBuffer(tile_tris_, CL_TRUE, CL_MAP_WRITE_INVALIDATE_REGION, 0, list_bytes));
    list_mapped_bytes_ = list_bytes;
  }
  return mapped_list_;
}

const PreparedFrame& Renderer::Impl::prepare(const Scene& scene, double* upload_ms) {
  pipeline_.begin_frame(scene, SIZE_MAX);
  return prepare_band(scene, 0, upload_ms);
}

const PreparedFrame& Renderer::Impl::prepare_band(const Scene& scene, int band, double* upload_ms) {
  cl::CommandQueue& q = device_.queue();
  if (options_.dda_coverage) q.finish();  // the previous frame's row table may still be in flight
  const PreparedFrame& f = pipeline_.prepare_band(scene, *this, band);
  const auto t0 = Clock::now();
  if (mapped_.leaves) q.enqueueUnmapMemObject(leaves_, mapped_.leaves);
  if (mapped_.fixed) q.enqueueUnmapMemObject(fixed_, mapped_.fixed);
  q.enqueueUnmapMemObject(attrs_, mapped_.attributes);
  if (f.dda) {
    const std::size_t first_bytes = f.dda->first.size() * sizeof(std::uint32_t);
    const std::size_t rows_bytes = f.dda->rows.size() * sizeof(std::int32_t);
    ensure(dda_first_, dda_first_cap_, first_bytes, CL_MEM_READ_ONLY);
    ensure(dda_rows_, dda_rows_cap_, rows_bytes, CL_MEM_READ_ONLY);
    if (first_bytes) q.enqueueWriteBuffer(dda_first_, CL_FALSE, 0, first_bytes, f.dda->first.data());
    if (rows_bytes) q.enqueueWriteBuffer(dda_rows_, CL_FALSE, 0, rows_bytes, f.dda->rows.data());
  }
  const std::size_t start_bytes = std::size_t(f.tiles() + 1) * sizeof(std::uint32_t);
  ensure(tile_start_, start_cap_, start_bytes, CL_MEM_READ_ONLY);
  q.enqueueWriteBuffer(tile_start_, CL_FALSE, 0, start_bytes, f.tile_start);
  q.enqueueUnmapMemObject(tile_tris_, mapped_list_);
  q.enqueueUnmapMemObject(tris_, mapped_.triangles);
  mapped_ = FrameRecords{};
  mapped_list_ = nullptr;
  if (upload_ms) *upload_ms = ms_since(t0);
  return f;
}

TileKernelArgs Renderer::Impl::tile_args(const cl::Buffer& tile_start, const cl::Buffer& tile_list, cl_float4 viewer,
                                   cl_float4 background, const Scene& scene, const PreparedFrame& f) const {
  return {&tris_,  &attrs_,     &tile_start,  &tile_list,    &lights_,  &materials_,   viewer,
          background, cl_int(f.tiles_x), cl_int(f.end_tile), cl_int(scene.width), cl_int(scene.height),
          &out_rgba_, &out_float_, &fixed_, &tile_counters_, &leaves_, &dda_first_, &dda_rows_};
}

std::optional<int> Renderer::Impl::deferral_threshold(const Scene& scene) const {
  if (options_.kernel_shape == KernelShape::lanes) return 0;  // every pixel shaded once after the walk, every tile
  KernelVariant v = *variant_;
  v.plan_pass = 0;  // as the report has always said it (a planned frame's resolve pass never defers)
  if (!v.defers_tiles()) return std::nullopt;
  return options_.deferral_threshold();
}

std::string Renderer::Impl::kernel_build() const {
  return kernel_() ? variant_->build_options() + device_build_options(device_.info()) : std::string();
}

int Renderer::Impl::work_items(int tiles) const {
  const int group = options_.group_size();
  if (options_.kernel_shape == KernelShape::lanes) return std::max(1, tiles) * group;  // a work-group per tile
  const int wanted = options_.work_items > 0 ? options_.work_items : device_work_items(device_.info(), tiles);
  const int n = std::max(1, std::min(tiles, wanted));
  return (n + group - 1) / group * group;  // whole work-groups (the kernel skips the tiles past the last)
}

void check_work_group_size(const RenderOptions& o, const DeviceInfo* device) {
  const int n = o.group_size();  // a default fits any tile
  const std::string what = "work-group size " + std::to_string(o.work_group_size ? o.work_group_size : n) +
                           " (--work-group-size)";
  if (o.work_group_size < 0 || n < 1 || (n & (n - 1)) != 0 || n > MAX_WORK_GROUP_SIZE)
    throw UsageError(what + " must be a power of two from 1 to " + std::to_string(MAX_WORK_GROUP_SIZE));
  if (o.kernel_shape == KernelShape::lanes && o.tile_size > 0 && n > o.tile_size * o.tile_size)
    throw UsageError(what + ": the lanes shape's work-items each own pixels of one " + std::to_string(o.tile_size) +
                     "x" + std::to_string(o.tile_size) + " tile, so at most " + std::to_string(o.tile_size * o.tile_size));
  if (device && device->max_work_group > 0 && std::size_t(n) > device->max_work_group)
    throw UsageError(what + " exceeds the largest work-group of '" + device->name + "', " +
                     std::to_string(device->max_work_group));
}

Renderer::Impl::~Impl() {
  try {
    release_frame();
    unmap_premapped();
    device_.queue().finish();
    for (Device* d : unit_devices_) d->queue().finish();
  } catch (...) {  // nothing sensible to do while tearing down
  }
}

void Renderer::Impl::release_frame() {
  if (mapped_rgba_) {
    device_.queue().enqueueUnmapMemObject(out_rgba_, mapped_rgba_);
    mapped_rgba_ = nullptr;
  }
}

// The scene's lights and materials into constant memory. The tables are members: the writes do not block,
// so the host memory they read must outlive this call (the frame waits for its kernel before it returns).
void Renderer::Impl::upload_tables(const Scene& scene) {
  cl::CommandQueue& q = device_.queue();
  std::vector<cl_float4>& lights = light_values_;
  std::vector<cl_float4>& materials = material_values_;
  lights = light_table(scene);
  materials = material_table(scene, options_.specular);
  if (options_.method == Method::combined) set_combined_limits(scene, options_.combined, materials);
  if ((lights.size() + materials.size()) * sizeof(cl_float4) > device_.info().constant_buffer)
    throw DeviceError("the scene's lights and materials do not fit the constant memory of '" + device_.info().name + "'");
  ensure(lights_, lights_cap_, lights.size() * sizeof(cl_float4), CL_MEM_READ_ONLY);
  ensure(materials_, materials_cap_, materials.size() * sizeof(cl_float4), CL_MEM_READ_ONLY);
  q.enqueueWriteBuffer(lights_, CL_FALSE, 0, lights.size() * sizeof(cl_float4), lights.data());
  q.enqueueWriteBuffer(materials_, CL_FALSE, 0, materials.size() * sizeof(cl_float4), materials.data());
}

// The kernel writes the 8-bit frame straight into the image kept here (no copy on the host); the other
// outputs, and placeholders for the buffers this variant does not read.
void Renderer::Impl::prepare_outputs(const Scene& scene, std::size_t counter_bytes) {
  cl::CommandQueue& q = device_.queue();
  const std::size_t pixels = std::size_t(scene.width) * scene.height;
  RenderedImage& img = frame_.image;
  img.width = scene.width;
  img.height = scene.height;
  if (img.rgba.size() != pixels * 4 || img.rgba.data() != rgba_host_) {
    q.finish();  // the old buffer's pending unmap must not outlive the memory it maps
    img.rgba.assign(pixels * 4, 0);
    rgba_host_ = img.rgba.data();
    out_rgba_ = cl::Buffer(device_.context(), CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR, pixels * 4, rgba_host_);
  }
  ensure(out_float_, float_cap_, options_.float_output ? 3 * pixels * sizeof(float) : 64, CL_MEM_WRITE_ONLY);
  // Unused by the kernel off the unit path (and the planes without fixed point): a small placeholder.
  if (!options_.arith.fixed) ensure(fixed_, fixed_cap_, 64, CL_MEM_READ_ONLY);
  ensure(tile_counters_, tile_counters_cap_, counter_bytes, CL_MEM_WRITE_ONLY);
  if (!options_.dda_coverage) {
    ensure(dda_first_, dda_first_cap_, 64, CL_MEM_READ_ONLY);
    ensure(dda_rows_, dda_rows_cap_, 64, CL_MEM_READ_ONLY);
  }
}

// The frame kernel of this renderer's variant for the scene's lights and viewer: built when they change,
// not every frame (a planned frame's variant is its resolve pass).
cl::Kernel& Renderer::Impl::frame_kernel(const Scene& scene) {
  if (variant_->set_scene(scene) || !kernel_()) {
    variant_->plan_pass = options_.plan ? 2 : 0;
    kernel_ = cl::Kernel(device_.program(kernel_files(*variant_), variant_->build_options()), "render_tiles");
  }
  return kernel_;
}

// Three counters per tile: the unit's spans, pixels and clocks, or the per-span normalization's setups,
// fallbacks and sequential steps (never both: the table refuses per-span normals on a unit).
bool Renderer::Impl::counts_per_tile() const { return options_.unit_path() || options_.span_normalize(); }

void Renderer::Impl::add_tile_counters(const cl_ulong* c, FrameStats& stats) const {
  for (int tile = 0; tile < stats.tiles && options_.span_normalize(); ++tile) {
    stats.normalize_span_setups += c[3 * tile];
    stats.normalize_fallback_spans += c[3 * tile + 1];
    stats.normalize_sequential_steps += c[3 * tile + 2];
  }
  for (int tile = 0; tile < stats.tiles && options_.unit_path(); ++tile) {
    stats.clocks.spans += c[3 * tile];
    stats.clocks.pixels += c[3 * tile + 1];
    stats.clocks.clocks += c[3 * tile + 2];
  }
}

// Every band's kernel (tiles [first_tile, end_tile): the kernel walks from its global id, offset by
// first_tile); a streamed frame's next band is prepared when the band before it is shaded. `done` is the
// last kernel's event, band_done the others'; `last` when the last band was launched. Returns the earlier
// bands' launch time.
double Renderer::Impl::launch_bands(const Scene& scene, int bands, const PreparedFrame* band, const TileKernelArgs& args,
                              cl::Event& done, std::vector<cl::Event>& band_done, Clock::time_point& last) {
  cl::CommandQueue& q = device_.queue();
  last = Clock::now();
  double launch_ms = 0, upload_ms = 0;
  for (int b = 0;; ++b) {
    const int tiles = band->end_tile - band->first_tile;
    // The lanes shape's work-items are a work-group per tile: its band starts a work-group per tile further on.
    const std::size_t group = std::size_t(options_.group_size());
    const std::size_t offset = std::size_t(band->first_tile) * (options_.kernel_shape == KernelShape::lanes ? group : 1);
    q.enqueueNDRangeKernel(kernel_, offset ? cl::NDRange(offset) : cl::NullRange,
                           cl::NDRange(std::size_t(work_items(std::max(1, tiles)))), cl::NDRange(group), nullptr, &done);
    if (b + 1 == bands) break;
    band_done.push_back(done);
    premap_records();  // mapped when this band's kernel ends (the queue is in order)
    done.wait();  // the next band's map would wait for it too; this keeps the wait out of its setup time
    launch_ms += ms_since(last);
    band = &prepare_band(scene, b + 1, &upload_ms);
    add_band(*band, upload_ms, frame_.timings, frame_.stats);
    set_tile_kernel_args(kernel_, tile_args(tile_start_, tile_tris_, args.viewer, args.background, scene, *band));
    last = Clock::now();
  }
  return launch_ms;
}

// The frame mapped (valid in the image's memory: on a CPU device the kernel wrote it there already), with
// the float colour and the tile counters, waited for; the counters added to the stats.
Renderer::Impl::MappedFrame Renderer::Impl::map_frame(std::size_t pixels, std::size_t counter_bytes) {
  cl::CommandQueue& q = device_.queue();
  MappedFrame m;
  m.rgba = q.enqueueMapBuffer(out_rgba_, CL_FALSE, CL_MAP_READ, 0, pixels * 4, nullptr, &m.mapped);
  if (options_.float_output)
    m.planar = static_cast<const float*>(
        q.enqueueMapBuffer(out_float_, CL_FALSE, CL_MAP_READ, 0, 3 * pixels * sizeof(float), nullptr, &m.float_mapped));
  cl::Event counters_mapped;
  const cl_ulong* tile_counters = nullptr;
  if (counts_per_tile())
    tile_counters = static_cast<const cl_ulong*>(
        q.enqueueMapBuffer(tile_counters_, CL_FALSE, CL_MAP_READ, 0, counter_bytes, nullptr, &counters_mapped));
  m.mapped.wait();
  mapped_rgba_ = m.rgba;
  if (tile_counters) {
    counters_mapped.wait();
    add_tile_counters(tile_counters, frame_.stats);
    q.enqueueUnmapMemObject(tile_counters_, const_cast<cl_ulong*>(tile_counters));
  }
  return m;
}

// Read-back: from the kernel's end to the frame in host memory (device clock), plus the host copies.
void Renderer::Impl::copy_out(MappedFrame& m, std::size_t pixels, const cl::Event& done) {
  const auto t0 = Clock::now();
  RenderedImage& img = frame_.image;
  if (m.rgba != rgba_host_) std::memcpy(img.rgba.data(), m.rgba, pixels * 4);  // the spec says it is the host pointer
  img.rgb_float.clear();
  if (options_.float_output) {
    m.float_mapped.wait();
    img.rgb_float.resize(pixels * 3);
    for (std::size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) img.rgb_float[p * 3 + c] = m.planar[c * pixels + p];
    device_.queue().enqueueUnmapMemObject(out_float_, const_cast<float*>(m.planar));
  }
  const auto kernel_end = done.getProfilingInfo<CL_PROFILING_COMMAND_END>();
  const auto map_end = m.mapped.getProfilingInfo<CL_PROFILING_COMMAND_END>();
  frame_.timings.readback_ms = double(map_end > kernel_end ? map_end - kernel_end : 0) * 1e-6 + ms_since(t0);
}

const Frame& Renderer::Impl::render(const Scene& scene) {
  Frame& frame = frame_;
  FrameTimings& t = frame.timings;
  t = FrameTimings{};
  frame.stats = FrameStats{};
  try {
    release_frame();  // the previous frame's image stays mapped until now
    const auto frame_start = Clock::now();
    premap_records();
    double upload_ms = 0;
    // A large frame streams: band after band, its records are set up, binned and shaded (the next band's
    // map waits for the kernel that reads the records it overwrites).
    const int bands = pipeline_.begin_frame(scene, options_.band_record_bytes);
    const PreparedFrame& f = prepare_band(scene, 0, &upload_ms);
    t = f.timings;
    t.binning_ms += upload_ms;  // the bins' upload belongs to binning
    frame.stats = f.stats;
    frame.stats.bands = bands;
    const std::size_t pixels = std::size_t(scene.width) * scene.height;
    const std::size_t counter_bytes = counts_per_tile() ? 3 * std::size_t(frame.stats.tiles) * sizeof(cl_ulong) : 64;
    upload_tables(scene);
    prepare_outputs(scene, counter_bytes);
    cl::Kernel& kernel = frame_kernel(scene);
    const glm::vec3 bg = 255.0f * scene.background;
    const cl_float4 viewer4 = viewer_value(scene, variant_->local_viewer), background{{bg.x, bg.y, bg.z, 0.0f}};
    const TileKernelArgs args = tile_args(tile_start_, tile_tris_, viewer4, background, scene, f);
    set_tile_kernel_args(kernel, args);
    UnitPassEvents unit_pass;
    if (f.plan) {
      frame.stats.unit_pass = unit_pass_shares(*f.plan);
      frame.stats.unit_pass_on_sub_devices = !unit_devices_.empty();
      enqueue_unit_pass(kernel, *variant_, args, *f.plan, frame.stats.unit_pass, pixels, unit_pass);
    }
    // The kernels, then the map that makes the frame valid in the image's memory: one wait for both. The
    // frame stays mapped until the next render.
    cl::Event done;
    std::vector<cl::Event> band_done;  // the bands before the last
    Clock::time_point last;
    const double earlier_bands_ms = launch_bands(scene, bands, &f, args, done, band_done, last);
    MappedFrame mapped = map_frame(pixels, counter_bytes);
    t.launch_ms = earlier_bands_ms + ms_since(last);
    t.kernel_ms = event_ms(done);
    for (const cl::Event& e : band_done) t.kernel_ms += event_ms(e);
    if (f.plan) unit_pass_times(unit_pass, t);
    copy_out(mapped, pixels, done);
    t.total_ms = ms_since(frame_start);
  } catch (const cl::Error&) {
    rethrow_cl_error("rendering on '" + device_.info().name + "'");
  }
  return frame;
}

std::vector<std::uint32_t> Renderer::Impl::coverage_counts(const Scene& scene) {
  try {
    const PreparedFrame& f = prepare(scene);
    cl::CommandQueue& q = device_.queue();
    const int tile = f.tile_size;
    const std::size_t pitch = std::size_t(f.tiles_x) * tile, rows = std::size_t(f.tiles_y) * tile;
    ensure(counts_, counts_cap_, pitch * rows * sizeof(std::uint32_t), CL_MEM_WRITE_ONLY);
    cl::Program& program =
        device_.program({"coverage_count.cl"}, "-D TILE=" + std::to_string(tile));
    cl::Kernel kernel(program, "coverage_count");
    kernel.setArg(0, tris_);
    kernel.setArg(1, tile_start_);
    kernel.setArg(2, tile_tris_);
    kernel.setArg(3, cl_int(f.tiles_x));
    kernel.setArg(4, counts_);
    const std::size_t group = 1;  // one work-item per tile
    q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(std::size_t(f.tiles()) * group), cl::NDRange(group));
    std::vector<std::uint32_t> padded(pitch * rows);
    q.enqueueReadBuffer(counts_, CL_TRUE, 0, padded.size() * sizeof(std::uint32_t), padded.data());
    std::vector<std::uint32_t> out(std::size_t(scene.width) * scene.height);
    for (int y = 0; y < scene.height; ++y)
      std::memcpy(&out[std::size_t(y) * scene.width], &padded[std::size_t(y) * pitch], std::size_t(scene.width) * 4);
    return out;
  } catch (const cl::Error&) {
    rethrow_cl_error("counting coverage on '" + device_.info().name + "'");
  }
}

// Renderer: the public face, each call passed to its Impl.
Renderer::Renderer(Device& device, RenderOptions options, std::vector<Device*> unit_devices)
    : impl_(std::make_unique<Impl>(device, std::move(options), std::move(unit_devices))) {}
Renderer::~Renderer() = default;
const Frame& Renderer::render(const Scene& scene) { return impl_->render(scene); }
std::vector<std::uint32_t> Renderer::coverage_counts(const Scene& scene) { return impl_->coverage_counts(scene); }
const ScreenGeometry& Renderer::geometry() const { return impl_->geometry(); }
const RenderOptions& Renderer::options() const { return impl_->options(); }
void Renderer::set_band(int first, int rows) { impl_->set_band(first, rows); }
int Renderer::work_items(int tiles) const { return impl_->work_items(tiles); }
std::optional<int> Renderer::deferral_threshold(const Scene& scene) const { return impl_->deferral_threshold(scene); }
std::vector<std::uint64_t> Renderer::plan_keys(const Scene& scene) { return impl_->plan_keys(scene); }
std::string Renderer::kernel_build() const { return impl_->kernel_build(); }

}  // namespace parashade
