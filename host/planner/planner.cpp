#include "parashade/planner.hpp"

#include <algorithm>
#include <numeric>
#include <queue>

#include "parashade/errors.hpp"
#include "parashade/parallel.hpp"
#include "parashade/kernels/constants.h"
#include "parashade/unit_table.hpp"

namespace parashade {
namespace {

std::uint64_t span_cost(const UnitConfig& unit, int length) {
  return std::uint64_t(SPAN_LOAD_CLOCKS) + std::uint64_t(span_clocks(unit, length));
}

// The least loaded unit (ties: lowest index) by a heap of (load, unit).
class LeastLoaded {
 public:
  explicit LeastLoaded(int units) {
    for (int u = 0; u < units; ++u) heap_.push({0, u});
  }
  int take(std::uint64_t cost) {
    const auto [load, unit] = heap_.top();
    heap_.pop();
    heap_.push({load + cost, unit});
    return unit;
  }

 private:
  using Entry = std::pair<std::uint64_t, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap_;
};

// Work lists for an owner per bin entry (owner(tile, triangle) < groups): each group's entries tile
// by tile in primitive order, a virtual tile per (group, tile) run.
template <typename Owner>
WorkLists build_work_lists(const TileBins& bins, int groups, Owner owner) {
  const std::size_t tiles = std::size_t(bins.tiles());
  const std::size_t entries = bins.tile_start[tiles];
  std::vector<std::uint32_t> first(std::size_t(groups) + 1, 0);
  std::vector<std::uint32_t> entry_group(entries);
  for (std::size_t k = 0; k < tiles; ++k)
    for (std::uint32_t e = bins.tile_start[k]; e < bins.tile_start[k + 1]; ++e) {
      const int g = owner(int(k), bins.tile_list[e]);
      entry_group[e] = std::uint32_t(g);
      ++first[std::size_t(g) + 1];
    }
  std::partial_sum(first.begin(), first.end(), first.begin());
  WorkLists w;
  w.list.resize(entries);
  std::vector<std::uint32_t> tile_of(entries), cursor(first.begin(), first.end() - 1);
  for (std::size_t k = 0; k < tiles; ++k)
    for (std::uint32_t e = bins.tile_start[k]; e < bins.tile_start[k + 1]; ++e) {
      const std::uint32_t at = cursor[entry_group[e]]++;
      w.list[at] = bins.tile_list[e];
      tile_of[at] = std::uint32_t(k);
    }
  w.packet_first.resize(std::size_t(groups) + 1);
  for (int g = 0; g < groups; ++g) {
    w.packet_first[std::size_t(g)] = std::uint32_t(w.vtile_tile.size());
    for (std::uint32_t at = first[std::size_t(g)]; at < first[std::size_t(g) + 1]; ++at)
      if (at == first[std::size_t(g)] || tile_of[at] != tile_of[at - 1]) {
        w.vtile_tile.push_back(tile_of[at]);
        w.vtile_start.push_back(at);
      }
  }
  w.packet_first[std::size_t(groups)] = std::uint32_t(w.vtile_tile.size());
  w.vtile_start.push_back(std::uint32_t(entries));
  return w;
}

// Per screen tile: setup for every triangle binned there, and each span's part inside the tile.
std::vector<UnitLoad> tile_costs(const TriangleGeometry* tris, const TileBins& bins, const UnitConfig& unit,
                                 int setup_clocks) {
  std::vector<UnitLoad> cost(std::size_t(bins.tiles()));
  const int ts = bins.tile_size;
  for (int k = 0; k < bins.tiles(); ++k) {
    UnitLoad& c = cost[std::size_t(k)];
    const int tx = (k % bins.tiles_x) * ts, ty = (k / bins.tiles_x) * ts;
    for (std::uint32_t e = bins.tile_start[k]; e < bins.tile_start[k + 1]; ++e) {
      const TriangleGeometry& t = tris[bins.tile_list[e]];
      c.triangles += 1;
      c.clocks += std::uint64_t(setup_clocks);
      for_each_span(t, [&](int dy, int xl, int xr) {
        const int y = t.y0 + dy;
        if (y < ty || y >= ty + ts) return;
        const int l = std::max(xl + t.x0, tx), r = std::min(xr + t.x0, tx + ts - 1);
        if (l > r) return;
        c.spans += 1;
        c.pixels += std::uint64_t(r - l + 1);
        c.clocks += span_cost(unit, r - l + 1);
      });
    }
  }
  return cost;
}

}  // namespace

Partition parse_partition(const std::string& name) {
  if (name == "round-robin") return Partition::round_robin;
  if (name == "lpt") return Partition::lpt;
  if (name == "tiles") return Partition::tiles;
  if (name == "dynamic") return Partition::dynamic;
  throw UsageError("unknown partition '" + name + "' (round-robin, lpt, tiles or dynamic)");
}

std::string partition_name(Partition p) {
  switch (p) {
    case Partition::round_robin: return "round-robin";
    case Partition::lpt: return "lpt";
    case Partition::tiles: return "tiles";
    case Partition::dynamic: return "dynamic";
  }
  return "";
}

WorkCost triangle_cost(const TriangleGeometry& t, const UnitConfig& unit, int setup_clocks) {
  WorkCost c;
  if (t.x0 > t.x1) return c;  // empty records are never binned: no unit sees them
  c.clocks = std::uint64_t(setup_clocks);
  for_each_span(t, [&](int, int xl, int xr) {
    c.spans += 1;
    c.pixels += std::uint64_t(xr - xl + 1);
    c.clocks += span_cost(unit, xr - xl + 1);
  });
  return c;
}

std::vector<int> assign_round_robin(std::size_t items, int units) {
  std::vector<int> out(items);
  for (std::size_t i = 0; i < items; ++i) out[i] = int(i % std::size_t(units));
  return out;
}

std::vector<int> assign_lpt(const std::vector<std::uint64_t>& cost, int units) {
  std::vector<std::uint32_t> order(cost.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return cost[a] > cost[b]; });
  LeastLoaded least(units);
  std::vector<int> out(cost.size());
  for (std::uint32_t i : order) out[i] = least.take(cost[i]);
  return out;
}

std::vector<int> assign_in_order(const std::vector<std::uint64_t>& cost, int units) {
  LeastLoaded least(units);
  std::vector<int> out(cost.size());
  for (std::size_t i = 0; i < cost.size(); ++i) out[i] = least.take(cost[i]);
  return out;
}

std::vector<int> proportional_blocks(int items, const std::vector<int>& weights) {
  const std::int64_t total = std::accumulate(weights.begin(), weights.end(), std::int64_t(0));
  std::vector<int> first{0};
  std::int64_t before = 0;
  for (int w : weights) {
    before += w;
    first.push_back(total > 0 ? int((2 * std::int64_t(items) * before + total) / (2 * total)) : items);
  }
  return first;
}

std::uint64_t PlanReport::total_clocks() const {
  std::uint64_t sum = 0;
  for (const UnitLoad& l : load) sum += l.clocks;
  return sum;
}

std::uint64_t PlanReport::frame_clocks() const {
  std::uint64_t most = 0;
  for (const UnitLoad& l : load) most = std::max(most, l.clocks);
  return most;
}

double PlanReport::imbalance() const {
  const std::uint64_t total = total_clocks();
  if (total == 0 || load.empty()) return 1.0;
  return double(frame_clocks()) * double(load.size()) / double(total);
}

void check_plan_options(const PlanOptions& o) {
  if (o.units < 0 || o.units > MAX_MODELED_UNITS)
    throw UsageError("modeled units " + std::to_string(o.units) + " out of range (1.." +
                     std::to_string(MAX_MODELED_UNITS) + "; 0: the device's compute units)");
  if (o.batch < 1) throw UsageError("batch " + std::to_string(o.batch) + " must be at least 1 triangle");
  if (o.setup_clocks < 0) throw UsageError("setup clocks " + std::to_string(o.setup_clocks) + " must not be negative");
}

Plan make_plan(const TriangleGeometry* tris, std::size_t n, const TileBins& bins, const UnitConfig& unit,
               const PlanOptions& o) {
  check_plan_options(o);
  if (o.units == 0) throw UsageError("make_plan: modeled units 0 (the device's compute units) must be resolved first");
  if (unit.kind == UnitKind::sierpinski)  // refused by check_frame_config; the records here would be copies
    throw UsageError("make_plan: the plan does not model the extra triangulation (its records are sub-triangle copies)");
  Plan plan;
  PlanReport& r = plan.report;
  r.partition = o.partition;
  r.units = o.units;
  r.tile_size = bins.tile_size;
  r.batch = o.batch;
  r.setup_clocks = o.setup_clocks;
  r.load.assign(std::size_t(o.units), UnitLoad{});

  if (o.partition == Partition::tiles) {
    const std::vector<UnitLoad> cost = tile_costs(tris, bins, unit, o.setup_clocks);
    std::vector<std::uint64_t> clocks(cost.size());
    for (std::size_t k = 0; k < cost.size(); ++k) clocks[k] = cost[k].clocks;
    const std::vector<int> owner = assign_lpt(clocks, o.units);
    for (std::size_t k = 0; k < cost.size(); ++k) {
      UnitLoad& l = r.load[std::size_t(owner[k])];
      l.triangles += cost[k].triangles;
      l.spans += cost[k].spans;
      l.pixels += cost[k].pixels;
      l.clocks += cost[k].clocks;
    }
    plan.work = build_work_lists(bins, o.units, [&](int tile, std::uint32_t) { return owner[std::size_t(tile)]; });
    return plan;
  }

  std::vector<WorkCost> cost(n);
  parallel_for_ranges(n, 4096, [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) cost[i] = triangle_cost(tris[i], unit, o.setup_clocks);
  });
  std::vector<int> owner;  // unit of each triangle
  int groups = o.units;
  std::vector<int> group;  // work-list group (packet) of each triangle
  if (o.partition == Partition::round_robin) {
    owner = assign_round_robin(n, o.units);
  } else if (o.partition == Partition::lpt) {
    std::vector<std::uint64_t> clocks(n);
    for (std::size_t i = 0; i < n; ++i) clocks[i] = cost[i].clocks;
    owner = assign_lpt(clocks, o.units);
  } else {  // dynamic: consecutive batches, modeled as pulled in order by the first free unit
    const std::size_t batches = (n + std::size_t(o.batch) - 1) / std::size_t(o.batch);
    std::vector<std::uint64_t> clocks(batches, 0);
    for (std::size_t i = 0; i < n; ++i) clocks[i / std::size_t(o.batch)] += cost[i].clocks;
    const std::vector<int> batch_unit = assign_in_order(clocks, o.units);
    owner.resize(n);
    group.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      owner[i] = batch_unit[i / std::size_t(o.batch)];
      group[i] = int(i / std::size_t(o.batch));
    }
    groups = int(std::max<std::size_t>(batches, 1));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (tris[i].x0 > tris[i].x1) continue;
    UnitLoad& l = r.load[std::size_t(owner[i])];
    l.triangles += 1;
    l.spans += cost[i].spans;
    l.pixels += cost[i].pixels;
    l.clocks += cost[i].clocks;
  }
  if (group.empty()) plan.work = build_work_lists(bins, groups, [&](int, std::uint32_t t) { return owner[t]; });
  else plan.work = build_work_lists(bins, groups, [&](int, std::uint32_t t) { return group[t]; });
  return plan;
}

}  // namespace parashade
