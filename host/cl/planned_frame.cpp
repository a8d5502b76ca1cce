// The planned frame (docs/planner.md): the planner's work lists for U modeled units, the units' depth
// pass (render_tiles.cl with PLAN_PASS=1: a work-item per unit, or units pulling batches from a
// counter), then the usual tile kernel as the resolve (PLAN_PASS=2), shading only each pixel's winner.
#include <chrono>

#include "parashade/errors.hpp"
#include "parashade/renderer.hpp"

namespace parashade {

void Renderer::plan_frame(const TriangleGeometry* tris, std::size_t n, const std::uint32_t* tile_list, FrameTimings& t,
                          FrameStats& s) {
  const auto t0 = std::chrono::steady_clock::now();
  if (options_.dda_coverage) throw UsageError("--cu does not plan with --coverage dda (its spans come from a row table)");
  PlanOptions o = *options_.plan;
  if (o.units == 0) o.units = std::max(1, device_.info().compute_units);
  const TileBins bins{binner_.tile_start().data(), tile_list, binner_.tiles_x(), binner_.tiles_y(), binner_.tile_size()};
  plan_ = make_plan(tris, n, bins, options_.unit(), o);
  s.plan = plan_.report;
  t.planning_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void Renderer::enqueue_unit_pass(cl::Kernel& resolve, const std::vector<std::string>& files, const std::string& options,
                                 cl_float4 viewer, cl_float4 background, const Scene& scene, cl::Event& done) {
  cl::CommandQueue& q = device_.queue();
  const WorkLists& w = plan_.work;
  const std::size_t pixels = std::size_t(scene.width) * scene.height;
  ensure(keys_, keys_cap_, pixels * sizeof(cl_ulong), CL_MEM_READ_WRITE);
  q.enqueueFillBuffer(keys_, ~cl_ulong(0), 0, pixels * sizeof(cl_ulong));
  ensure(plan_counter_, plan_counter_cap_, sizeof(cl_int), CL_MEM_READ_WRITE);
  q.enqueueFillBuffer(plan_counter_, cl_int(0), 0, sizeof(cl_int));
  auto upload = [&](cl::Buffer& b, std::size_t& cap, const std::vector<std::uint32_t>& v) {
    ensure(b, cap, v.size() * sizeof(std::uint32_t), CL_MEM_READ_ONLY);
    if (!v.empty()) q.enqueueWriteBuffer(b, CL_FALSE, 0, v.size() * sizeof(std::uint32_t), v.data());
  };
  upload(plan_packets_, plan_packets_cap_, w.packet_first);
  upload(plan_vtiles_, plan_vtiles_cap_, w.vtile_tile);
  upload(plan_starts_, plan_starts_cap_, w.vtile_start);
  upload(plan_list_, plan_list_cap_, w.list);

  const bool dynamic = plan_.report.partition == Partition::dynamic;
  cl::Program& units = device_.program(files, options + " -D PLAN_PASS=1 -D PLAN_DYNAMIC=" + (dynamic ? "1" : "0"));
  cl::Kernel k(units, "render_tiles");
  // The resolve kernel's arguments, with the plan's virtual tiles and lists in place of the bins.
  k.setArg(0, tris_);
  k.setArg(1, attrs_);
  k.setArg(2, plan_starts_);
  k.setArg(3, plan_list_);
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
  for (cl::Kernel* kernel : {&k, &resolve}) {
    kernel->setArg(19, keys_);
    kernel->setArg(20, plan_packets_);
    kernel->setArg(21, plan_vtiles_);
    kernel->setArg(22, plan_counter_);
    kernel->setArg(23, cl_int(w.packets()));
  }
  // One work-item per modeled unit: U units run as U work-items whatever the device's cores.
  q.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(std::size_t(plan_.report.units)), cl::NDRange(1), nullptr, &done);
}

}  // namespace parashade
