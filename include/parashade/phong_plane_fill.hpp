#pragma once
// The Phong floor of a frame (bench_llvmpipe's phong_plane_fill_limit, kernels/phong_fill_limit.cl): every
// pixel's normal and position from one plane each, normalized and lit by a scene's lights with the frame
// kernel's own shading code and build options, packed and written, nothing else. Its planes are those of a
// screen-filling rectangle whose corner normals lean 0.3 off the view axis (bench/peer/bench_scenes.hpp's
// fullscreen_quad), so the full-screen quad's Phong frame can be set against it.
#include <cstdint>
#include <memory>
#include <vector>

#include "parashade/device.hpp"
#include "parashade/scene.hpp"

namespace parashade {

class PhongPlaneFill {
 public:
  // Builds the kernel for `scene`'s lights, first material and viewer at width x height (width a multiple of
  // 16; throws UsageError otherwise) on `device`, which must outlive it. Throws DeviceError.
  PhongPlaneFill(Device& device, const Scene& scene, int width, int height);
  ~PhongPlaneFill();
  PhongPlaneFill(const PhongPlaneFill&) = delete;
  PhongPlaneFill& operator=(const PhongPlaneFill&) = delete;
  // One launch, waited for: the kernel's time in ms from its profiling events.
  double run_ms();
  // The last frame's pixels, RGBA8 (read back; for tests).
  std::vector<std::uint32_t> pixels();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parashade
