#pragma once
// Wraps and saturations of a fixed-point frame's span registers (kernels/fixed_point.h): counted on the
// host by running each unit's golden model over the prepared frame's spans. The kernels reproduce the
// golden models bit for bit (tests/cl/unit_golden_test.cpp), so these are the kernel's events, and the
// kernels need no counter (the images stay as they are). `render` reports them and warns (docs/units.md).
#include <cstdint>

#include "parashade/frame_config.hpp"
#include "parashade/frame_pipeline.hpp"
#include "parashade/scene.hpp"

namespace parashade {

struct RegisterEvents {
  std::uint64_t spans = 0;            // spans run through the unit (each with three channels)
  std::uint64_t span_pixels = 0;      // their pixels, hidden ones included (the unit shades before the depth test)
  std::uint64_t wrapped_pixels = 0;   // span pixels where some channel's register wrapped around
  std::uint64_t wrapped_spans = 0;    // spans with a wrapped pixel
  std::uint64_t saturated_loads = 0;  // register loads (span start, end, increment; per channel) that saturated
};

// A register value wrapped when it lies half the register range (2^(I-1) levels) or more from the exact
// plane value it stands for: no rounding error comes near that (docs/unit-error.md), only a carry lost
// out of the register. A load saturates when the rounded plane value does not fit the I.F register.
// `frame` must be prepared with `config` (a fixed-point unit path) and still valid. Empty result for a
// float arithmetic.
RegisterEvents count_register_events(const PreparedFrame& frame, const FrameConfig& config);
// The same for `scene` prepared on the host (a plan, which does not change the records, is left out).
RegisterEvents count_register_events(const Scene& scene, const FrameConfig& config);

}  // namespace parashade
