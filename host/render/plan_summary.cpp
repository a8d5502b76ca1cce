// The planner's load and the units' mapping as text (plan_summary.hpp).
#include "plan_summary.hpp"

#include <cstdio>

namespace parashade {

void print_plan(const PlanReport& r, bool per_unit, std::FILE* out) {
  std::fprintf(out, "plan %s, U = %d, tile %d%s: modeled frame clocks %llu (slowest unit), total %llu, imbalance %.3f\n",
              partition_name(r.partition).c_str(), r.units, r.tile_size,
              r.partition == Partition::dynamic ? (", batch " + std::to_string(r.batch)).c_str() : "",
              (unsigned long long)r.frame_clocks(), (unsigned long long)r.total_clocks(), r.imbalance());
  if (!per_unit) return;
  std::fprintf(out, "  %5s %12s %12s %12s %14s\n", "unit", "triangles", "spans", "pixels", "clocks");
  for (std::size_t u = 0; u < r.load.size(); ++u) {
    const UnitLoad& l = r.load[u];
    std::fprintf(out, "  %5zu %12llu %12llu %12llu %14llu\n", u, (unsigned long long)l.triangles, (unsigned long long)l.spans,
                (unsigned long long)l.pixels, (unsigned long long)l.clocks);
  }
}

void print_unit_mapping(const FrameStats& s, const FrameTimings& t, std::FILE* out) {
  if (!s.unit_pass_on_sub_devices) {
    if (!s.unit_pass.empty())
      std::fprintf(out, "units as %d work-items (work-group size 1) of one kernel on %s\n", s.unit_pass[0].units,
                  s.unit_pass[0].device.c_str());
    return;
  }
  std::fprintf(out, "units on %zu sub-devices (contiguous blocks; keys min-merged in %.3f ms):\n", s.unit_pass.size(),
              t.key_merge_ms);
  for (std::size_t k = 0; k < s.unit_pass.size(); ++k) {
    const UnitPassShare& u = s.unit_pass[k];
    const double ms = k < t.unit_pass_share_ms.size() ? t.unit_pass_share_ms[k] : 0.0;
    if (u.units == 0)
      std::fprintf(out, "  %-48s %d CU: no units\n", u.device.c_str(), u.compute_units);
    else
      std::fprintf(out, "  %-48s %d CU: units %d..%d, %d packet(s) from %d, pass %.3f ms\n", u.device.c_str(),
                  u.compute_units, u.first_unit, u.first_unit + u.units - 1, u.packets, u.first_packet, ms);
  }
}

}  // namespace parashade
