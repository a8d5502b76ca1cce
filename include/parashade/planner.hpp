#pragma once
// The host task planner: which modeled shading unit (of U) shades which triangles, by a partition
// strategy and a cost model from the unit's modeled clocks (unit_table.hpp, shared with the kernels),
// and the work lists the kernels run it from. The image never depends on the plan: units resolve depth by the order-free
// key (depth, primitive index) (docs/planner.md), so every strategy and U gives the same bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "parashade/units.hpp"
#include "parashade/kernels/triangle_record.h"

namespace parashade {

enum class Partition {
  round_robin,  // triangle i to unit i mod U (static)
  lpt,          // cost-balanced: longest processing time first, each to the least loaded unit (static)
  tiles,        // screen tiles (sort-middle bins) to units by cost, longest first (static)
  dynamic,      // batches of triangles pulled by the units from a shared counter
};

// "round-robin", "lpt", "tiles" or "dynamic"; throws UsageError naming the value.
Partition parse_partition(const std::string& name);
std::string partition_name(Partition p);

struct PlanOptions {
  Partition partition = Partition::lpt;
  int units = 0;         // modeled shading units U; 0: the device's compute units (1 without a device)
  int batch = 64;        // dynamic: triangles per batch a unit pulls from the counter
  int setup_clocks = 1;  // modeled clocks a unit spends to load a triangle's setup record (an assumption: docs/planner.md)
};

// Modeled work of one triangle (or one triangle's part of a tile) on one unit.
// Throws UsageError naming the value: units beyond 0..4096 (0: the device's compute units), batch < 1,
// negative setup clocks.
void check_plan_options(const PlanOptions& o);

struct WorkCost {
  std::uint64_t spans = 0;
  std::uint64_t pixels = 0;  // span pixels, hidden ones included (a unit shades before the depth test)
  std::uint64_t clocks = 0;  // setup_clocks + per span SPAN_LOAD_CLOCKS + span_clocks()
};

// The exact spans of a record by its integer edge functions (the coverage rule of triangle_record.h):
// visit(dy, xl, xr) for each row dy (from y0) with covered pixels xl..xr (from x0), top to bottom.
template <typename Visit>
void for_each_span(const TriangleGeometry& t, Visit visit);
// The same for one row dy of a record with a non-empty box: false when the row has no covered pixel.
inline bool record_row_span(const TriangleGeometry& t, int dy, int& xl, int& xr);

// A whole triangle on one unit (the unit path's rule: every triangle by whole spans).
WorkCost triangle_cost(const TriangleGeometry& t, const UnitConfig& unit, int setup_clocks);

// Assignments of items with the given costs to `units` units (result[i] = unit of item i).
std::vector<int> assign_round_robin(std::size_t items, int units);
// Longest processing time first: items by decreasing cost (ties: lower index first), each to the unit
// with the least load so far (ties: lowest unit).
std::vector<int> assign_lpt(const std::vector<std::uint64_t>& cost, int units);
// Items in order, each to the unit that becomes free first (least load; ties: lowest unit): the
// model of units pulling work from a shared counter.
std::vector<int> assign_in_order(const std::vector<std::uint64_t>& cost, int units);

// Contiguous blocks of `items` in proportion to `weights` (the units of --cu over sub-devices by their
// compute units, or a sub-device's share of the batches by its units): block k is [first[k], first[k + 1]),
// first[k] = round(items * (w_0 + ... + w_{k-1}) / W) with halves rounded up. weights.size() + 1 entries;
// a block may be empty when items < weights.size(). Weights must be >= 0 with a positive sum.
std::vector<int> proportional_blocks(int items, const std::vector<int>& weights);

struct UnitLoad {
  std::uint64_t triangles = 0;  // triangles started (tiles: triangle-tile entries)
  std::uint64_t spans = 0;
  std::uint64_t pixels = 0;
  std::uint64_t clocks = 0;
};

struct PlanReport {
  Partition partition = Partition::lpt;
  int units = 1;
  int tile_size = TILE_DEFAULT;
  int batch = 64;
  int setup_clocks = 1;
  std::vector<UnitLoad> load;  // per unit
  std::uint64_t total_clocks() const;
  std::uint64_t frame_clocks() const;  // the slowest unit's
  double imbalance() const;            // max / mean of the units' clocks (1 when all are idle)
};

// What the unit kernel walks: packet p holds virtual tiles packet_first[p] .. packet_first[p + 1];
// virtual tile v is screen tile vtile_tile[v] with triangles list[vtile_start[v] .. vtile_start[v + 1])
// in primitive order. Static strategies: packet u = unit u's work; dynamic: one packet per batch.
struct WorkLists {
  std::vector<std::uint32_t> packet_first;
  std::vector<std::uint32_t> vtile_tile;
  std::vector<std::uint32_t> vtile_start;
  std::vector<std::uint32_t> list;
  int packets() const { return packet_first.empty() ? 0 : int(packet_first.size()) - 1; }
};

struct Plan {
  PlanReport report;
  WorkLists work;
};

// Sort-middle bins as the Binner made them: tile k's triangles are tile_list[tile_start[k] .. tile_start[k + 1]).
struct TileBins {
  const std::uint32_t* tile_start = nullptr;  // tiles + 1 entries
  const std::uint32_t* tile_list = nullptr;
  int tiles_x = 0, tiles_y = 0, tile_size = TILE_DEFAULT;
  int tiles() const { return tiles_x * tiles_y; }
};

// Plans records tris[0 .. n) (options.units must be >= 1). Throws UsageError for an unusable option.
Plan make_plan(const TriangleGeometry* tris, std::size_t n, const TileBins& bins, const UnitConfig& unit,
               const PlanOptions& options);

// ---- implementation of the template ----

inline bool record_row_span(const TriangleGeometry& t, int dy, int& xl, int& xr) {
  std::int64_t lo = 0, hi = std::int64_t(t.x1) - t.x0;
  for (int e = 0; e < 3 && lo <= hi; ++e) {
    const std::int64_t a = t.edge_a[e];
    const std::int64_t r = t.edge_c[e] + std::int64_t(dy) * t.edge_b[e];  // E at x0 on this row
    if (a == 0) {
      if (r < 0) hi = lo - 1;
    } else if (a > 0) {  // r + a x >= 0  <=>  x >= ceil(-r / a)
      std::int64_t q = -r / a;
      if ((-r) % a != 0 && -r > 0) ++q;
      lo = q > lo ? q : lo;
    } else {  // x <= floor(r / -a)
      const std::int64_t b = -a;
      std::int64_t q = r / b;
      if (r % b != 0 && r < 0) --q;
      hi = q < hi ? q : hi;
    }
  }
  xl = int(lo);
  xr = int(hi);
  return lo <= hi;
}

template <typename Visit>
void for_each_span(const TriangleGeometry& t, Visit visit) {
  if (t.x0 > t.x1 || t.y0 > t.y1) return;
  for (int dy = 0, xl, xr; dy <= t.y1 - t.y0; ++dy)
    if (record_row_span(t, dy, xl, xr)) visit(dy, xl, xr);
}

}  // namespace parashade
