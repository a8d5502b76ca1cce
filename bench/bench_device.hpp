#pragma once
// What bench_frame and bench_llvmpipe share: the device they time (PARASHADE_DEVICE, as `render --device`;
// else the default device) and its fill limit, the ceiling of every frame benchmark.
#include <cstdlib>
#include <functional>
#include <memory>

#include <benchmark/benchmark.h>

#include <CL/opencl.hpp>

#include "parashade/kernels/constants.h"
#include "parashade/device.hpp"
#include "parashade/device_layout.hpp"

namespace parashade {

inline Device& bench_device() {
  static std::unique_ptr<Device> device = [] {
    const char* sel = std::getenv("PARASHADE_DEVICE");
    return open_device(sel ? sel : "");
  }();
  return *device;
}

// A floor kernel's benchmark: two untimed launches, then one a benchmark iteration, each timed by `launch`
// (the kernel's milliseconds from its profiling events); frame_ms and mpixel_per_s of a width x height frame.
inline void time_floor_launches(benchmark::State& state, const std::function<double()>& launch, int width,
                                int height) {
  for (int i = 0; i < 2; ++i) launch();
  double sum_ms = 0.0;
  for (auto _ : state) {
    const double ms = launch();
    state.SetIterationTime(ms * 1e-3);
    sum_ms += ms;
  }
  const double frame_ms = sum_ms / double(state.iterations());
  state.counters["frame_ms"] = frame_ms;
  state.counters["mpixel_per_s"] = double(width) * height / (frame_ms * 1e3);
}

// A kernel that only writes every pixel of a width x height RGBA8 frame (kernels/fill_limit.cl), timed by
// its profiling event after two untimed launches. plane: the Gouraud floor instead (plane_fill_limit: each
// pixel's colour and depth from planes, packed and written), for widths that are a multiple of 16.
inline void run_fill_limit(benchmark::State& state, Device& device, int width, int height, bool plane = false) {
  const int vectors = (width * height + 15) / 16;
  cl::Buffer out(device.context(), CL_MEM_WRITE_ONLY | CL_MEM_ALLOC_HOST_PTR, std::size_t(vectors) * 16 * 4);
  cl::Kernel kernel(device.program({"common.h", "fill_limit.cl"}, ""), plane ? "plane_fill_limit" : "fill_limit");
  kernel.setArg(0, out);
  if (plane) {
    if (width % 16 != 0) {
      state.SkipWithError("plane_fill_limit needs a width that is a multiple of 16");
      return;
    }
    // A gradient over the frame's levels and a depth in (0, 1), so every lane rounds and packs real values.
    kernel.setArg(1, cl_float4{{10.0f, 200.0f, 30.0f, 0.25f}});
    kernel.setArg(2, cl_float4{{100.0f / float(width), -50.0f / float(width), 0.0f, 1e-5f}});
    kernel.setArg(3, cl_float4{{0.0f, 40.0f / float(height), 200.0f / float(height), 1e-5f}});
    kernel.setArg(4, cl_int(width));
    kernel.setArg(5, cl_int(height));
  } else {
    kernel.setArg(1, cl_uint(0xFF336699u));
    kernel.setArg(2, cl_int(vectors));
  }
  // plane: the frame kernel's default work-items on a CPU (device_layout.hpp), one a vector at most.
  const cl::NDRange global{plane ? std::size_t(device_work_items(device.info(), vectors)) : std::size_t(vectors)};
  const auto launch = [&] {
    cl::Event done;
    device.queue().enqueueNDRangeKernel(kernel, cl::NullRange, global, cl::NullRange, nullptr, &done);
    done.wait();
    return double(done.getProfilingInfo<CL_PROFILING_COMMAND_END>() - done.getProfilingInfo<CL_PROFILING_COMMAND_START>()) *
           1e-6;
  };
  time_floor_launches(state, launch, width, height);
}

}  // namespace parashade
