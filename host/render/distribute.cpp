// The --distribute values and the figures rank 0 gathers: in the render step (its report reads them),
// compiled with or without MPI.
#include "parashade/distributed.hpp"

#include "parashade/errors.hpp"
#include "parashade/statistics.hpp"

namespace parashade {

Distribute parse_distribute(const std::string& name) {
  if (name == "sort-last") return Distribute::sort_last;
  if (name == "sort-first") return Distribute::sort_first;
  throw UsageError("unknown --distribute '" + name + "' (valid: sort-last, sort-first)");
}

const char* distribute_name(Distribute d) { return d == Distribute::sort_last ? "sort-last" : "sort-first"; }

DeviceMode distribute_device_mode(Distribute d) {
  return d == Distribute::sort_last ? DeviceMode::ranks_sort_last : DeviceMode::ranks_sort_first;
}

std::vector<RankFigures> DistributedFigures::rank_medians() const {
  std::vector<RankFigures> out(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) {
    auto med = [&](double RankFigures::*field) {
      std::vector<double> v;
      for (const auto& f : frames) v.push_back(f[r].*field);
      return median(v);
    };
    RankFigures& m = out[r];
    for (double RankFigures::*field :
         {&RankFigures::faces, &RankFigures::records, &RankFigures::pixels, &RankFigures::won_pixels,
          &RankFigures::modeled_clocks, &RankFigures::prepare_ms, &RankFigures::render_ms, &RankFigures::frame_ms,
          &RankFigures::composite_ms, &RankFigures::bytes_sent, &RankFigures::band_first, &RankFigures::band_rows,
          &RankFigures::record_bytes, &RankFigures::pack_ms, &RankFigures::gather_ms})
      m.*field = med(field);
    if (mode == Distribute::sort_first) {  // the last frame's band
      m.band_first = frames.back()[r].band_first;
      m.band_rows = frames.back()[r].band_rows;
    }
  }
  return out;
}

}  // namespace parashade
