#include "parashade/renderer.hpp"

#include <chrono>
#include <cstring>
#include <sstream>
#include <utility>

#include "parashade/combined_kernel.hpp"
#include "parashade/errors.hpp"
#include "parashade/geometry_stage.hpp"
#include "parashade/parallel.hpp"
#include "parashade/setup.hpp"
#include "parashade/sierpinski.hpp"

namespace parashade {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

const char* method_header(Method m) {
  switch (m) {
    case Method::flat: return "method_flat.h";
    case Method::gouraud: return "method_gouraud.h";
    case Method::phong: return "method_phong.h";
    case Method::combined: return "method_combined.h";
  }
  return "";
}

bool needs_local_viewer(const Scene& s) {
  return s.local_viewer && s.camera.projection == Projection::perspective;
}

// Lights and materials as the kernels read them (blinn_phong.h).
std::vector<cl_float4> light_table(const Scene& s) {
  std::vector<cl_float4> out;
  for (const Light& l : s.lights) {
    const bool point = l.type == LightType::point;
    const glm::vec3 v = point ? l.position : -glm::normalize(l.direction);
    out.push_back({{v.x, v.y, v.z, point ? 1.0f : 0.0f}});
    out.push_back({{255.0f * l.color.r, 255.0f * l.color.g, 255.0f * l.color.b, 0.0f}});
  }
  if (out.empty()) out.push_back({{0, 0, 0, 0}});
  return out;
}

std::vector<cl_float4> material_table(const Scene& s, const SpecularModel& spec) {
  std::vector<cl_float4> out;
  for (const Material& m : s.materials) {
    const glm::vec3 a = 255.0f * m.ambient * s.ambient_light;
    out.push_back({{a.x, a.y, a.z, m.shininess}});
    // .w: the scale a of a cos^k(a alpha) specular model (specular_models.h), per material exponent.
    const double scale = spec.kind == SpecularKind::cosk_taylor ? taylor_scale(m.shininess, spec.k)
                         : spec.kind == SpecularKind::cosk_lobe ? lobe_scale(m.shininess, spec.k)
                                                                : 0.0;
    out.push_back({{m.diffuse.r, m.diffuse.g, m.diffuse.b, float(scale)}});
    out.push_back({{m.specular.r, m.specular.g, m.specular.b, 0.0f}});
  }
  if (out.empty()) out.push_back({{0, 0, 0, 1}});
  return out;
}

std::string kernel_options(const Scene& s, const RenderOptions& o) {
  unsigned point_mask = 0;
  for (std::size_t i = 0; i < s.lights.size(); ++i)
    if (s.lights[i].type == LightType::point) point_mask |= 1u << i;
  const bool need_position = needs_local_viewer(s) || point_mask != 0;
  std::ostringstream opt;
  opt << "-D TILE=" << o.tile_size << " -D NUM_LIGHTS=" << s.lights.size() << " -D POINT_LIGHTS=" << point_mask
      << " -D LOCAL_VIEWER=" << (needs_local_viewer(s) ? 1 : 0) << " -D NEED_POSITION=" << (need_position ? 1 : 0)
      << " -D OUTPUT_FLOAT=" << (o.float_output ? 1 : 0) << " -D UNIT_PATH=" << (o.unit_path() ? 1 : 0);
  if (o.specular.kind != SpecularKind::exact) {
    const int model = o.specular.kind == SpecularKind::quadratic  ? 3
                      : o.specular.kind == SpecularKind::sevenths ? 4
                                                                  : 1;
    opt << " -D SPECULAR_MODEL=" << model << " -D SPECULAR_K=" << o.specular.k << " -D SPECULAR_P=" << std::to_string(o.specular.p)
        << "f -D SPECULAR_P_IS_2=" << (o.specular.p == 2.0 ? 1 : 0);
  }
  if (o.span_normalize()) {
    const NormalizeMethod& n = o.normalize;
    switch (n.kind) {
      case NormalizeKind::slerp: opt << " -D NORMALIZE_METHOD=1"; break;
      case NormalizeKind::quadratic: opt << " -D NORMALIZE_METHOD=2 -D NORMALIZE_MID=" << int(n.mid); break;
      case NormalizeKind::dichotomy:
        opt << " -D NORMALIZE_METHOD=3 -D NORMALIZE_BISECTOR=" << int(n.bisector) << " -D NORMALIZE_SEGMENT_LOG2="
            << n.segment_log2 << " -D NORMALIZE_EXTRAPOLATE=" << (n.extrapolate_last ? 1 : 0);
        break;
      case NormalizeKind::recurrence:
        opt << " -D NORMALIZE_METHOD=4 -D NORMALIZE_ARCCOS=" << int(n.arccos) << " -D NORMALIZE_REANCHOR=" << n.reanchor
            << " -D NORMALIZE_DIFFERENCE=" << (n.difference_form ? 1 : 0);
        break;
      case NormalizeKind::exact: break;
    }
  }
  if (o.method == Method::combined) opt << combined_kernel_options(o.combined);
  if (o.unit_path()) {
    const UnitConfig u = o.unit();
    opt << " -D UNIT_KIND=" << int(u.kind) << " -D UNIT_LANES=" << u.lanes << " -D UNIT_OWN_STEP=" << (u.own_step ? 1 : 0)
        << " -D FIXED=" << (o.arith.fixed ? 1 : 0) << " -D FRAC_BITS=" << o.arith.frac_bits
        << " -D REG_BITS=" << o.arith.width() << " -D SPAN_DIV=" << o.division.mode << " -D DIV_BITS=" << o.division.bits
        << " -D DIV_NEAREST=" << (o.division.nearest ? 1 : 0) << " -D DDA_COVERAGE=" << (o.dda_coverage ? 1 : 0)
        << " -D UNIT_REGISTER_COLOUR=" << (o.method == Method::gouraud ? 1 : 0);
  }
  return opt.str();
}

double event_ms(const cl::Event& e) {
  const auto start = e.getProfilingInfo<CL_PROFILING_COMMAND_START>();
  const auto end = e.getProfilingInfo<CL_PROFILING_COMMAND_END>();
  return double(end - start) * 1e-6;
}

}  // namespace

Renderer::Renderer(Device& device, RenderOptions options, std::vector<Device*> unit_devices)
    : device_(device), options_(options), unit_devices_(std::move(unit_devices)) {
  if (!unit_devices_.empty() && !options_.plan)
    throw UsageError("sub-devices for the units' depth pass need modeled units (--cu / --partition)");
  for (Device* d : unit_devices_)
    if (d->context()() != device_.context()())
      throw DeviceError("'" + d->info().name + "' does not share the context of '" + device_.info().name +
                        "': open the units' sub-devices with a shared context (sub_devices.hpp)");
  if (options_.tile_size != 16 && options_.tile_size != 32 && options_.tile_size != 64)
    throw InputError("tile size " + std::to_string(options_.tile_size) + " is not supported (16, 32 or 64)");
  if (options_.unit_path() && options_.method == Method::flat)
    throw UsageError("the shading units (--units, --arith fixed) interpolate along spans; method 'flat' has nothing to interpolate");
  if (options_.unit_path() && options_.method == Method::phong && options_.unit().kind == UnitKind::sierpinski)
    throw UsageError("--units " + unit_name(options_.unit()) +
                     " copies Gouraud intensities; Phong shades every pixel of every copy, so it is modeled for Gouraud only");
  if (options_.dda_coverage && options_.unit().kind == UnitKind::sierpinski)
    throw UsageError("--coverage dda does not combine with --units " + unit_name(options_.unit()) +
                     " (its copies need pixel-centre coverage)");
  if (options_.specular.kind != SpecularKind::exact && options_.method != Method::phong)
    throw UsageError("--specular " + specular_name(options_.specular) + " needs --method phong (the other methods light on the host)");
  if (options_.normalize.kind != NormalizeKind::exact && options_.method != Method::phong)
    throw UsageError("--normalize " + normalize_name(options_.normalize) + " needs --method phong");
  // The units' Phong normalizes every pixel (method_phong_units.h) and their counters share tile_clocks
  // with the normalization's: the option would be ignored and its report wrong.
  if (options_.span_normalize() && options_.unit_path())
    throw UsageError("--normalize " + normalize_name(options_.normalize) +
                     " has no shading-unit model (--units, --arith fixed): the units normalize per pixel");
  if (options_.dda_coverage && options_.method != Method::gouraud)
    throw UsageError("--coverage dda is modeled for Gouraud's units only");
  if (options_.method == Method::combined && options_.unit_path())
    throw UsageError("--method combined has no shading-unit model (--units, --arith fixed): gouraud or phong");
  if (options_.method == Method::combined && options_.plan)
    throw UsageError("--cu / --partition do not plan --method combined yet (its span walk has no planned depth pass)");
  if (options_.division.mode != DIV_CONSTANT) {
    const UnitConfig u = options_.unit();
    if (!options_.arith.fixed)
      throw UsageError("--div " + division_name(options_.division) + " divides span registers: it needs --arith fixed:I.F");
    if (u.kind == UnitKind::sierpinski || u.own_step)
      throw UsageError("--div " + division_name(options_.division) + " does not combine with --units " + unit_name(u) +
                       " (its increments come from setup's plane)");
  }
}

cl::Buffer& Renderer::ensure(cl::Buffer& buffer, std::size_t& capacity, std::size_t bytes, cl_mem_flags flags) {
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

void Renderer::prepare(const Scene& scene, FrameTimings& t, FrameStats& s) {
  check_resolution(scene.width, scene.height, "scene '" + scene.name + "'");
  const Method method = options_.method;
  cl::CommandQueue& q = device_.queue();

  auto t0 = Clock::now();
  const bool choose = method == Method::combined && options_.combined.rule != TriangleRule::none;
  build_screen_geometry(scene, {method, false, choose}, geometry_);
  // The extra-triangulation unit needs its midpoints on pixel corners: vertex parity normalization.
  const UnitConfig unit = options_.unit();
  const bool split = options_.unit_path() && unit.kind == UnitKind::sierpinski;
  if (split) s.parity_dropped = snap_sierpinski_vertices(geometry_, unit);
  t.geometry_ms = ms_since(t0);
  s.geometry = geometry_.stats;

  // Every blocking OpenCL call costs a round trip to the device's threads (~60 us on PoCL here), so the
  // three input buffers are mapped together: the tile list at its current capacity, since binning's
  // size is known only later (it is mapped again in the rare frame it must grow).
  t0 = Clock::now();
  const std::size_t triangles = geometry_.triangles.size();
  const std::size_t n = split ? triangles << (2 * unit.depth) : triangles;  // records: sub-triangles when split
  const std::size_t tri_bytes = std::max<std::size_t>(64, n * sizeof(TriangleGeometry));
  const std::size_t attr_bytes = std::max<std::size_t>(64, n * attribute_floats(method) * sizeof(float));
  ensure(tris_, tris_cap_, tri_bytes, CL_MEM_READ_ONLY);
  ensure(attrs_, attrs_cap_, attr_bytes, CL_MEM_READ_ONLY);
  ensure(tile_tris_, list_cap_, std::max<std::size_t>(64, 2 * n * sizeof(std::uint32_t)), CL_MEM_READ_ONLY);
  std::vector<cl::Event> mapped(3);
  auto* tri_ptr = static_cast<TriangleGeometry*>(
      q.enqueueMapBuffer(tris_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, tri_bytes, nullptr, &mapped[0]));
  auto* attr_ptr = static_cast<float*>(
      q.enqueueMapBuffer(attrs_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, attr_bytes, nullptr, &mapped[1]));
  std::size_t list_mapped = list_cap_;
  auto* list_ptr = static_cast<std::uint32_t*>(
      q.enqueueMapBuffer(tile_tris_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, list_mapped, nullptr, &mapped[2]));
  FixedPlanes* fixed_ptr = nullptr;
  const std::size_t fixed_bytes = std::max<std::size_t>(64, n * sizeof(FixedPlanes));
  if (options_.arith.fixed) {
    ensure(fixed_, fixed_cap_, fixed_bytes, CL_MEM_READ_ONLY);
    fixed_ptr = static_cast<FixedPlanes*>(
        q.enqueueMapBuffer(fixed_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, fixed_bytes, nullptr, &mapped.emplace_back()));
  }
  SierpinskiLeaf* leaf_ptr = nullptr;
  const std::size_t leaf_bytes = std::max<std::size_t>(64, (split ? n : 0) * sizeof(SierpinskiLeaf));
  ensure(leaves_, leaves_cap_, leaf_bytes, CL_MEM_READ_ONLY);
  if (split)
    leaf_ptr = static_cast<SierpinskiLeaf*>(
        q.enqueueMapBuffer(leaves_, CL_FALSE, CL_MAP_WRITE_INVALIDATE_REGION, 0, leaf_bytes, nullptr, &mapped.emplace_back()));
  cl::Event::waitForEvents(mapped);
  if (split) {
    // Setup per triangle, then each record split into its sub-triangles' records.
    whole_.resize(triangles);
    whole_attr_.resize(triangles * GOURAUD_ATTR_FLOATS);
    whole_fixed_.resize(fixed_ptr ? triangles : 0);
    FixedPlanes* whole_fixed = fixed_ptr ? whole_fixed_.data() : nullptr;
    s.triangles_without_pixels =
        setup_triangles(geometry_, method, whole_.data(), whole_attr_.data(), whole_fixed).without_pixels;
    s.sierpinski_whole = split_sierpinski(geometry_, unit, whole_.data(), whole_attr_.data(), whole_fixed, tri_ptr,
                                         attr_ptr, fixed_ptr, leaf_ptr);
    q.enqueueUnmapMemObject(leaves_, leaf_ptr);
  } else {
    if (choose) {
      const auto c0 = Clock::now();
      s.choice = choose_triangle_methods(scene, geometry_, options_.combined, combined_shading_budget(options_.combined),
                                         choice_);
      t.choice_ms = ms_since(c0);
    }
    s.triangles_without_pixels =
        setup_triangles(geometry_, method, tri_ptr, attr_ptr, fixed_ptr, choose ? choice_.data() : nullptr).without_pixels;
    if (choose) {
      apply_triangle_choice(choice_, attr_ptr, PHONG_ATTR_FLOATS);
      if (uses_highlight_mask(options_.combined))
        s.highlight = {s.choice->triangles, s.choice->without_highlight, s.choice->light_terms_skipped};
    } else if (method == Method::combined && options_.combined.highlight_test) {
      s.highlight = mark_highlights(scene, geometry_, attr_ptr, PHONG_ATTR_FLOATS, PHONG_HIGHLIGHT_SLOT,
                                    options_.combined.negligible_specular);
    }
    if (options_.dda_coverage) {
      q.finish();  // the previous frame's row table may still be in flight
      dda_ = apply_dda_coverage(geometry_, tri_ptr, attr_ptr, fixed_ptr);
      const std::size_t first_bytes = dda_.first.size() * sizeof(std::uint32_t);
      const std::size_t rows_bytes = dda_.rows.size() * sizeof(std::int32_t);
      ensure(dda_first_, dda_first_cap_, first_bytes, CL_MEM_READ_ONLY);
      ensure(dda_rows_, dda_rows_cap_, rows_bytes, CL_MEM_READ_ONLY);
      if (first_bytes) q.enqueueWriteBuffer(dda_first_, CL_FALSE, 0, first_bytes, dda_.first.data());
      if (rows_bytes) q.enqueueWriteBuffer(dda_rows_, CL_FALSE, 0, rows_bytes, dda_.rows.data());
    }
  }
  if (fixed_ptr) q.enqueueUnmapMemObject(fixed_, fixed_ptr);
  q.enqueueUnmapMemObject(attrs_, attr_ptr);
  t.setup_ms = ms_since(t0);

  t0 = Clock::now();
  binner_.count(tri_ptr, n, scene.width, scene.height, options_.tile_size);
  const std::vector<std::uint32_t>* start_list = &binner_.tile_start();
  if (options_.band_rows >= 0) {  // empty every tile outside the band: tile k holds start[k] .. start[k + 1]
    band_start_ = binner_.tile_start();
    const std::size_t tiles = band_start_.size() - 1, tx = std::size_t(binner_.tiles_x());
    const std::size_t lo = std::min(tiles, tx * std::size_t(options_.band_first));
    const std::size_t hi = std::min(tiles, tx * std::size_t(options_.band_first + options_.band_rows));
    for (std::size_t k = 0; k < lo; ++k) band_start_[k] = band_start_[lo];
    for (std::size_t k = hi + 1; k <= tiles; ++k) band_start_[k] = band_start_[hi];
    start_list = &band_start_;
  }
  const auto& start = *start_list;
  const std::size_t start_bytes = start.size() * sizeof(std::uint32_t);
  const std::size_t list_bytes = binner_.entries() * sizeof(std::uint32_t);
  ensure(tile_start_, start_cap_, start_bytes, CL_MEM_READ_ONLY);
  q.enqueueWriteBuffer(tile_start_, CL_FALSE, 0, start_bytes, start.data());
  if (list_bytes > list_mapped) {
    q.enqueueUnmapMemObject(tile_tris_, list_ptr);
    ensure(tile_tris_, list_cap_, list_bytes, CL_MEM_READ_ONLY);
    list_ptr = static_cast<std::uint32_t*>(
        q.enqueueMapBuffer(tile_tris_, CL_TRUE, CL_MAP_WRITE_INVALIDATE_REGION, 0, list_bytes));
  }
  binner_.fill(list_ptr);
  if (options_.plan) plan_frame(tri_ptr, n, list_ptr, t, s);
  q.enqueueUnmapMemObject(tile_tris_, list_ptr);
  q.enqueueUnmapMemObject(tris_, tri_ptr);
  t.binning_ms = ms_since(t0);
  s.bin_entries = binner_.entries();
  s.tiles = binner_.tiles_x() * binner_.tiles_y();
}

void Renderer::set_tile_kernel_args(cl::Kernel& k, const cl::Buffer& tile_start, const cl::Buffer& tile_list,
                                    cl_float4 viewer, cl_float4 background, const Scene& scene) {
  k.setArg(0, tris_);
  k.setArg(1, attrs_);
  k.setArg(2, tile_start);
  k.setArg(3, tile_list);
  k.setArg(4, lights_);
  k.setArg(5, materials_);
  k.setArg(6, viewer);
  k.setArg(7, background);
  k.setArg(8, cl_int(binner_.tiles_x()));
  k.setArg(9, cl_int(binner_.tiles_x() * binner_.tiles_y()));
  k.setArg(10, cl_int(scene.width));
  k.setArg(11, cl_int(scene.height));
  k.setArg(12, out_rgba_);
  k.setArg(13, out_float_);
  k.setArg(14, fixed_);
  k.setArg(15, tile_clocks_);
  k.setArg(16, leaves_);
  k.setArg(17, dda_first_);
  k.setArg(18, dda_rows_);
}

int Renderer::work_items(int tiles) const {
  const int wanted = options_.work_items > 0 ? options_.work_items : WORK_ITEMS_PER_COMPUTE_UNIT * std::max(1, device_.info().compute_units);
  return std::max(1, std::min(tiles, wanted));
}

Renderer::~Renderer() {
  try {
    release_frame();
    device_.queue().finish();
    for (Device* d : unit_devices_) d->queue().finish();
  } catch (...) {  // nothing sensible to do while tearing down
  }
}

void Renderer::release_frame() {
  if (mapped_rgba_) {
    device_.queue().enqueueUnmapMemObject(out_rgba_, mapped_rgba_);
    mapped_rgba_ = nullptr;
  }
}

const Frame& Renderer::render(const Scene& scene) {
  Frame& frame = frame_;
  FrameTimings& t = frame.timings;
  t = FrameTimings{};
  frame.stats = FrameStats{};
  try {
    release_frame();  // the previous frame's image stays mapped until now
    const auto frame_start = Clock::now();
    prepare(scene, t, frame.stats);
    cl::CommandQueue& q = device_.queue();
    const std::size_t pixels = std::size_t(scene.width) * scene.height;

    const auto lights = light_table(scene);
    auto materials = material_table(scene, options_.specular);
    if (options_.method == Method::combined) set_combined_limits(scene, options_.combined, materials);
    if ((lights.size() + materials.size()) * sizeof(cl_float4) > device_.info().constant_buffer)
      throw DeviceError("the scene's lights and materials do not fit the constant memory of '" + device_.info().name + "'");
    ensure(lights_, lights_cap_, lights.size() * sizeof(cl_float4), CL_MEM_READ_ONLY);
    ensure(materials_, materials_cap_, materials.size() * sizeof(cl_float4), CL_MEM_READ_ONLY);
    q.enqueueWriteBuffer(lights_, CL_FALSE, 0, lights.size() * sizeof(cl_float4), lights.data());
    q.enqueueWriteBuffer(materials_, CL_FALSE, 0, materials.size() * sizeof(cl_float4), materials.data());
    // The kernel writes the 8-bit frame straight into the image kept here (no copy on the host).
    RenderedImage& img = frame.image;
    img.width = scene.width;
    img.height = scene.height;
    if (img.rgba.size() != pixels * 4 || img.rgba.data() != rgba_host_) {
      q.finish();  // the old buffer's pending unmap must not outlive the memory it maps
      img.rgba.assign(pixels * 4, 0);
      rgba_host_ = img.rgba.data();
      out_rgba_ = cl::Buffer(device_.context(), CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR, pixels * 4, rgba_host_);
    }
    if (options_.float_output) ensure(out_float_, float_cap_, 3 * pixels * sizeof(float), CL_MEM_WRITE_ONLY);
    else ensure(out_float_, float_cap_, 64, CL_MEM_WRITE_ONLY);

    const std::string options = kernel_options(scene, options_);
    const std::vector<std::string> files{"common.h", "triangle_record.h", method_header(options_.method), "render_tiles.cl"};
    cl::Program& program = device_.program(files, options + (options_.plan ? " -D PLAN_PASS=2" : ""));
    cl::Kernel kernel(program, "render_tiles");
    const glm::vec3 viewer = needs_local_viewer(scene)
                                 ? scene.camera.position
                                 : glm::normalize(scene.camera.position - scene.camera.target);
    const glm::vec3 bg = 255.0f * scene.background;
    // Unused by the kernel off the unit path (and the planes without fixed point): a small placeholder.
    if (!options_.arith.fixed) ensure(fixed_, fixed_cap_, 64, CL_MEM_READ_ONLY);
    const bool counts = options_.unit_path() || options_.span_normalize();
    const std::size_t clock_bytes = counts ? 3 * std::size_t(frame.stats.tiles) * sizeof(cl_ulong) : 64;
    ensure(tile_clocks_, tile_clocks_cap_, clock_bytes, CL_MEM_WRITE_ONLY);
    if (!options_.dda_coverage) {
      ensure(dda_first_, dda_first_cap_, 64, CL_MEM_READ_ONLY);
      ensure(dda_rows_, dda_rows_cap_, 64, CL_MEM_READ_ONLY);
    }
    const cl_float4 viewer4{{viewer.x, viewer.y, viewer.z, 0.0f}}, background{{bg.x, bg.y, bg.z, 0.0f}};
    set_tile_kernel_args(kernel, tile_start_, tile_tris_, viewer4, background, scene);
    UnitPassEvents unit_pass;
    if (options_.plan)
      enqueue_unit_pass(kernel, files, options, viewer4, background, scene, frame.stats.unit_pass, unit_pass);
    // The kernel, then the map that makes the frame valid in the image's memory (on a CPU device the
    // kernel wrote it there already): one wait for both. The frame stays mapped until the next render.
    auto t0 = Clock::now();
    cl::Event done, mapped;
    q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(std::size_t(work_items(frame.stats.tiles))),
                           cl::NDRange(1), nullptr, &done);
    void* rgba = q.enqueueMapBuffer(out_rgba_, CL_FALSE, CL_MAP_READ, 0, pixels * 4, nullptr, &mapped);
    const float* planar = nullptr;
    cl::Event float_mapped;
    if (options_.float_output)
      planar = static_cast<const float*>(
          q.enqueueMapBuffer(out_float_, CL_FALSE, CL_MAP_READ, 0, 3 * pixels * sizeof(float), nullptr, &float_mapped));
    cl::Event clocks_mapped;
    const cl_ulong* tile_clocks = nullptr;
    if (counts)
      tile_clocks = static_cast<const cl_ulong*>(
          q.enqueueMapBuffer(tile_clocks_, CL_FALSE, CL_MAP_READ, 0, clock_bytes, nullptr, &clocks_mapped));
    mapped.wait();
    mapped_rgba_ = rgba;
    if (tile_clocks) {
      clocks_mapped.wait();
      ModeledClocks& c = frame.stats.clocks;
      for (int tile = 0; tile < frame.stats.tiles && options_.span_normalize(); ++tile) {
        frame.stats.normalize_span_setups += tile_clocks[3 * tile];
        frame.stats.normalize_fallback_spans += tile_clocks[3 * tile + 1];
        frame.stats.normalize_sequential_steps += tile_clocks[3 * tile + 2];
      }
      for (int tile = 0; tile < frame.stats.tiles && options_.unit_path(); ++tile) {
        c.spans += tile_clocks[3 * tile];
        c.pixels += tile_clocks[3 * tile + 1];
        c.clocks += tile_clocks[3 * tile + 2];
      }
      q.enqueueUnmapMemObject(tile_clocks_, const_cast<cl_ulong*>(tile_clocks));
    }
    t.launch_ms = ms_since(t0);
    t.kernel_ms = event_ms(done);
    if (options_.plan) unit_pass_times(unit_pass, t);
    t0 = Clock::now();
    if (rgba != rgba_host_)
      std::memcpy(img.rgba.data(), rgba, pixels * 4);  // the spec says it is the host pointer; be safe
    img.rgb_float.clear();
    if (options_.float_output) {
      float_mapped.wait();
      img.rgb_float.resize(pixels * 3);
      for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 3; ++c) img.rgb_float[p * 3 + c] = planar[c * pixels + p];
      q.enqueueUnmapMemObject(out_float_, const_cast<float*>(planar));
    }
    // Read-back: from the kernel's end to the frame in host memory (device clock), plus host copies.
    const auto kernel_end = done.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    const auto map_end = mapped.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    t.readback_ms = double(map_end > kernel_end ? map_end - kernel_end : 0) * 1e-6 + ms_since(t0);
    t.total_ms = ms_since(frame_start);
  } catch (const cl::Error&) {
    rethrow_cl_error("rendering on '" + device_.info().name + "'");
  }
  return frame;
}

std::vector<std::uint32_t> Renderer::coverage_counts(const Scene& scene) {
  try {
    FrameTimings t;
    FrameStats s;
    prepare(scene, t, s);
    cl::CommandQueue& q = device_.queue();
    const int tile = options_.tile_size;
    const std::size_t pitch = std::size_t(binner_.tiles_x()) * tile, rows = std::size_t(binner_.tiles_y()) * tile;
    ensure(counts_, counts_cap_, pitch * rows * sizeof(std::uint32_t), CL_MEM_WRITE_ONLY);
    cl::Program& program =
        device_.program({"coverage_count.cl"}, "-D TILE=" + std::to_string(tile));
    cl::Kernel kernel(program, "coverage_count");
    kernel.setArg(0, tris_);
    kernel.setArg(1, tile_start_);
    kernel.setArg(2, tile_tris_);
    kernel.setArg(3, cl_int(binner_.tiles_x()));
    kernel.setArg(4, counts_);
    const std::size_t group = 1;  // one work-item per tile
    q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(std::size_t(s.tiles) * group), cl::NDRange(group));
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

}  // namespace parashade
