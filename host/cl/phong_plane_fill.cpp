// The Phong floor's kernel and its one triangle (phong_plane_fill.hpp).
#include "parashade/phong_plane_fill.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "parashade/device_layout.hpp"
#include "parashade/errors.hpp"
#include "parashade/kernels/triangle_record.h"
#include "kernel_variant.hpp"
#include "shading_tables.hpp"

namespace parashade {
namespace {

// The record of a rectangle filling the orthographic view of height 2 at width x height: slot k's value at
// the top-left pixel's centre, its step along a row (k + 3) and down a column (k + 6); normals (nx, ny, nz)
// in slots 0..8, the world position in 9..17. The corner normals are (+-0.3, +-0.3, 0.9) normalized at
// x = +-4, y = +-1.5 (bench_scenes.hpp's fullscreen_quad), which is linear in x and y: one plane is exact.
std::vector<float> screen_record(int width, int height) {
  const float s = 2.0f / float(height);  // world units per pixel
  const float x0 = (0.5f - 0.5f * float(width)) * s, y0 = (0.5f * float(height) - 0.5f) * s;
  const float k = 1.0f / std::sqrt(0.99f);
  std::vector<float> a(PHONG_ATTR_FLOATS, 0.0f);
  a[0] = k * 0.075f * x0, a[3] = k * 0.075f * s;  // nx = k 0.3 x / 4
  a[1] = k * 0.2f * y0, a[7] = -k * 0.2f * s;     // ny = k 0.3 y / 1.5, y falling down the screen
  a[2] = k * 0.9f;
  a[9] = x0, a[12] = s;    // world x
  a[10] = y0, a[16] = -s;  // world y; z = 0
  a[PHONG_MATERIAL_SLOT] = 0.0f;
  return a;
}

}  // namespace

struct PhongPlaneFill::Impl {
  Device& device;
  cl::Kernel kernel;
  cl::Buffer out, record, lights, materials;
  cl::NDRange global;
  int width, height;
};

PhongPlaneFill::PhongPlaneFill(Device& device, const Scene& scene, int width, int height) {
  if (width <= 0 || height <= 0 || width % 16 != 0)
    throw UsageError("phong_plane_fill_limit needs a width that is a multiple of 16 (got " + std::to_string(width) + ")");
  RenderOptions options;
  options.method = Method::phong;
  KernelVariant variant = kernel_variant(scene, options);
  std::vector<cl_float4> light_values = light_table(scene), material_values = material_table(scene, options.specular);
  std::vector<float> record = screen_record(width, height);
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  try {
    cl::Context& c = device.context();
    impl_.reset(new Impl{device,
                         cl::Kernel(device.program({"common.h", "triangle_record.h", "method_phong.h", "phong_fill_limit.cl"},
                                                   variant.build_options()),
                                    "phong_plane_fill_limit"),
                         cl::Buffer(c, CL_MEM_WRITE_ONLY | CL_MEM_ALLOC_HOST_PTR, pixels * 4),
                         cl::Buffer(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, record.size() * 4, record.data()),
                         cl::Buffer(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, light_values.size() * sizeof(cl_float4),
                                    light_values.data()),
                         cl::Buffer(c, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                    material_values.size() * sizeof(cl_float4), material_values.data()),
                         cl::NDRange(std::size_t(device_work_items(device.info(), int(pixels / 16)))), width, height});
    cl::Kernel& k = impl_->kernel;
    k.setArg(0, impl_->out);
    k.setArg(1, impl_->record);
    k.setArg(2, cl_float4{{0.5f, 0.0f, 0.0f, 0.0f}});  // the rectangle's depth, flat
    k.setArg(3, cl_int(width));
    k.setArg(4, cl_int(height));
    k.setArg(5, impl_->lights);
    k.setArg(6, impl_->materials);
    k.setArg(7, viewer_value(scene, variant.local_viewer));
  } catch (const cl::Error&) {
    rethrow_cl_error("setting up phong_plane_fill_limit on '" + device.info().name + "'");
  }
}

PhongPlaneFill::~PhongPlaneFill() = default;

double PhongPlaneFill::run_ms() {
  try {
    cl::Event done;
    impl_->device.queue().enqueueNDRangeKernel(impl_->kernel, cl::NullRange, impl_->global, cl::NullRange, nullptr, &done);
    done.wait();
    return double(done.getProfilingInfo<CL_PROFILING_COMMAND_END>() - done.getProfilingInfo<CL_PROFILING_COMMAND_START>()) *
           1e-6;
  } catch (const cl::Error&) {
    rethrow_cl_error("running phong_plane_fill_limit on '" + impl_->device.info().name + "'");
  }
}

std::vector<std::uint32_t> PhongPlaneFill::pixels() {
  std::vector<std::uint32_t> p(std::size_t(impl_->width) * std::size_t(impl_->height));
  try {
    impl_->device.queue().enqueueReadBuffer(impl_->out, CL_TRUE, 0, p.size() * 4, p.data());
  } catch (const cl::Error&) {
    rethrow_cl_error("reading phong_plane_fill_limit's frame on '" + impl_->device.info().name + "'");
  }
  return p;
}

}  // namespace parashade
