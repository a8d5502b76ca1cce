// The planner's assignment rules and cost model on hand-built cases; every expected value is worked
// out by hand in the comments, not taken from the code.
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "parashade/errors.hpp"
#include "parashade/planner.hpp"

namespace parashade {
namespace {

std::vector<std::uint64_t> loads_of(const std::vector<int>& owner, const std::vector<std::uint64_t>& cost, int units) {
  std::vector<std::uint64_t> load(std::size_t(units), 0);
  for (std::size_t i = 0; i < cost.size(); ++i) load[std::size_t(owner[i])] += cost[i];
  return load;
}

TEST(PlannerAssign, RoundRobinDealsInTurn) {
  EXPECT_EQ(assign_round_robin(7, 3), (std::vector<int>{0, 1, 2, 0, 1, 2, 0}));
}

TEST(PlannerAssign, LptBeatsRoundRobinOnAConstructedCase) {
  // Costs 5 5 4 4 3 3 3 on 3 units. Round-robin: unit 0 gets items 0, 3, 6 = 5 + 4 + 3 = 12, unit 1
  // items 1, 4 = 8, unit 2 items 2, 5 = 7. LPT (already in decreasing order): 5 -> u0, 5 -> u1, 4 -> u2,
  // 4 -> u2 (least, 4) = 8, 3 -> u0 (5, lowest of the tie) = 8, 3 -> u1 = 8, 3 -> u0 (all 8) = 11.
  const std::vector<std::uint64_t> cost{5, 5, 4, 4, 3, 3, 3};
  const auto rr = loads_of(assign_round_robin(cost.size(), 3), cost, 3);
  EXPECT_EQ(rr, (std::vector<std::uint64_t>{12, 8, 7}));
  const std::vector<int> lpt = assign_lpt(cost, 3);
  EXPECT_EQ(lpt, (std::vector<int>{0, 1, 2, 2, 0, 1, 0}));
  EXPECT_EQ(loads_of(lpt, cost, 3), (std::vector<std::uint64_t>{11, 8, 8}));
}

TEST(PlannerAssign, LptTakesLongestFirstNotInOrder) {
  // 1 1 1 1 4 on 2 units in order would put 4 on top of 2: LPT places 4 first (u0), then the ones on
  // u1, u1, u1, u1 (u1 stays below 4): loads 4 and 4.
  const std::vector<std::uint64_t> cost{1, 1, 1, 1, 4};
  const std::vector<int> lpt = assign_lpt(cost, 2);
  EXPECT_EQ(lpt, (std::vector<int>{1, 1, 1, 1, 0}));
  // The textbook case where LPT is not optimal: 3 3 2 2 2 on 2 units gives 7 (3+2+2), the optimum is 6.
  EXPECT_EQ(loads_of(assign_lpt({3, 3, 2, 2, 2}, 2), {3, 3, 2, 2, 2}, 2), (std::vector<std::uint64_t>{7, 5}));
}

TEST(PlannerAssign, InOrderModelsUnitsPullingFromACounter) {
  // 4 1 1 1 3 on 2 units: u0 takes 4; u1 (free first) takes 1, 1, 1 (loads 1, 2, 3); the 3 goes to u1
  // (3 < 4): loads 4 and 6.
  const std::vector<std::uint64_t> cost{4, 1, 1, 1, 3};
  const std::vector<int> order = assign_in_order(cost, 2);
  EXPECT_EQ(order, (std::vector<int>{0, 1, 1, 1, 1}));
  EXPECT_EQ(loads_of(order, cost, 2), (std::vector<std::uint64_t>{4, 6}));
}

TEST(PlannerAssign, ProportionalBlocksOfUnitsOverSubDevices) {
  // Units over sub-devices by compute units: 8 over 1+1 -> 4 and 4; 3 over 1+1 -> 2 and 1 (1.5 rounds
  // up); 8 over 1+3 -> 2 and 6; 1 over 1+1 -> 1 and none; 5 over 2+1+1 -> 2.5 -> 3, 3.75 -> 4: 3, 1, 1.
  EXPECT_EQ(proportional_blocks(8, {1, 1}), (std::vector<int>{0, 4, 8}));
  EXPECT_EQ(proportional_blocks(3, {1, 1}), (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(proportional_blocks(8, {1, 3}), (std::vector<int>{0, 2, 8}));
  EXPECT_EQ(proportional_blocks(1, {1, 1}), (std::vector<int>{0, 1, 1}));
  EXPECT_EQ(proportional_blocks(5, {2, 1, 1}), (std::vector<int>{0, 3, 4, 5}));
  // Batches over sub-devices by their units: a sub-device without units gets no batches.
  EXPECT_EQ(proportional_blocks(99, {1, 0}), (std::vector<int>{0, 99, 99}));
}

// The right triangle x >= 0, y >= 0, x + y <= 3 on a 4x4 box at (0, 0): rows of 4, 3, 2, 1 pixels.
TriangleGeometry staircase(int x0, int y0) {
  TriangleGeometry t{};
  t.edge_a[0] = 1;  t.edge_b[0] = 0;  t.edge_c[0] = 0;   // x >= 0
  t.edge_a[1] = 0;  t.edge_b[1] = 1;  t.edge_c[1] = 0;   // y >= 0
  t.edge_a[2] = -1; t.edge_b[2] = -1; t.edge_c[2] = 3;   // 3 - x - y >= 0
  t.x0 = ps_short(x0);
  t.y0 = ps_short(y0);
  t.x1 = ps_short(x0 + 3);
  t.y1 = ps_short(y0 + 3);
  return t;
}

TEST(PlannerCost, SpansOfAStaircase) {
  std::vector<std::array<int, 3>> spans;
  for_each_span(staircase(5, 7), [&](int dy, int xl, int xr) { spans.push_back({dy, xl, xr}); });
  EXPECT_EQ(spans, (std::vector<std::array<int, 3>>{{0, 0, 3}, {1, 0, 2}, {2, 0, 1}, {3, 0, 0}}));
}

TEST(PlannerCost, ClocksPerUnitKind) {
  const TriangleGeometry t = staircase(0, 0);
  // Classic: setup 2 + per span 1 load + L clocks: 2 + 5 + 4 + 3 + 2 = 16.
  WorkCost c = triangle_cost(t, UnitConfig{}, 2);
  EXPECT_EQ(c.spans, 4u);
  EXPECT_EQ(c.pixels, 10u);
  EXPECT_EQ(c.clocks, 16u);
  // Counter (2 per clock, ceil): spans 4 3 2 1 take 2 2 1 1: 1 + (3 + 3 + 2 + 2) = 11.
  UnitConfig counter;
  counter.kind = UnitKind::counter;
  counter.lanes = 2;
  EXPECT_EQ(triangle_cost(t, counter, 1).clocks, 11u);
  // Segment P = 4: one clock per span: 0 + 4 * (1 + 1) = 8.
  UnitConfig segment;
  segment.kind = UnitKind::segment;
  segment.lanes = 4;
  EXPECT_EQ(triangle_cost(t, segment, 0).clocks, 8u);
  // An empty record costs nothing (never binned).
  TriangleGeometry empty = t;
  empty.x1 = ps_short(empty.x0 - 1);
  EXPECT_EQ(triangle_cost(empty, UnitConfig{}, 5).clocks, 0u);
}

// Staircases on an 8x8 screen in 4x4 tiles: a triangle at each tile corner, bins built by hand.
struct Fixture {
  std::vector<TriangleGeometry> tris;
  std::vector<std::uint32_t> start, list;
  TileBins bins() const { return {start.data(), list.data(), 2, 2, 4}; }
};

Fixture four_tiles() {
  Fixture f;
  // tile 0 (0,0): triangles 0, 2; tile 1 (4,0): 1; tile 2 (0,4): 3; tile 3 (4,4): 4, 5.
  f.tris = {staircase(0, 0), staircase(4, 0), staircase(0, 0), staircase(0, 4), staircase(4, 4), staircase(4, 4)};
  f.start = {0, 2, 3, 4, 6};
  f.list = {0, 2, 1, 3, 4, 5};
  return f;
}

TEST(PlannerPlan, LoadsSumToTheTotalAndListsHoldEveryEntryOnce) {
  const Fixture f = four_tiles();
  // Every staircase costs 1 + 14 = 15 classic clocks (setup 1): 6 triangles = 90 clocks, 60 pixels.
  for (Partition p : {Partition::round_robin, Partition::lpt, Partition::tiles, Partition::dynamic})
    for (int units : {1, 2, 3, 8}) {
      PlanOptions o;
      o.partition = p;
      o.units = units;
      o.batch = 2;
      const Plan plan = make_plan(f.tris.data(), f.tris.size(), f.bins(), UnitConfig{}, o);
      SCOPED_TRACE(partition_name(p) + " U=" + std::to_string(units));
      ASSERT_EQ(plan.report.load.size(), std::size_t(units));
      std::uint64_t pixels = 0, triangles = 0;
      for (const UnitLoad& l : plan.report.load) {
        pixels += l.pixels;
        triangles += l.triangles;
      }
      // Each triangle lies inside one tile, so the tile split changes nothing here.
      EXPECT_EQ(plan.report.total_clocks(), 90u);
      EXPECT_EQ(pixels, 60u);
      EXPECT_EQ(triangles, 6u);
      const std::uint64_t ideal = (90 + std::uint64_t(units) - 1) / std::uint64_t(units);
      EXPECT_GE(plan.report.frame_clocks(), std::max<std::uint64_t>(ideal, 15));
      // The work lists: each (tile, triangle) entry once, in primitive order within a virtual tile.
      const WorkLists& w = plan.work;
      std::vector<std::pair<std::uint32_t, std::uint32_t>> seen;
      for (int pk = 0; pk < w.packets(); ++pk)
        for (std::uint32_t v = w.packet_first[std::size_t(pk)]; v < w.packet_first[std::size_t(pk) + 1]; ++v)
          for (std::uint32_t e = w.vtile_start[v]; e < w.vtile_start[v + 1]; ++e) {
            seen.push_back({w.vtile_tile[v], w.list[e]});
            if (e > w.vtile_start[v]) EXPECT_LT(w.list[e - 1], w.list[e]);
          }
      std::sort(seen.begin(), seen.end());
      EXPECT_EQ(seen, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 0}, {0, 2}, {1, 1}, {2, 3}, {3, 4}, {3, 5}}));
    }
}

TEST(PlannerPlan, ImbalanceOfHandWorkedPlans) {
  const Fixture f = four_tiles();
  PlanOptions o;
  o.units = 4;
  // Round-robin on 4 units: units 0 and 1 get two triangles (30), units 2 and 3 one (15): max 30, mean
  // 90 / 4 = 22.5, imbalance 30 / 22.5 = 4/3.
  o.partition = Partition::round_robin;
  Plan rr = make_plan(f.tris.data(), f.tris.size(), f.bins(), UnitConfig{}, o);
  EXPECT_EQ(rr.report.frame_clocks(), 30u);
  EXPECT_NEAR(rr.report.imbalance(), 4.0 / 3.0, 1e-12);
  // Tiles on 4 units: tile costs 30, 15, 15, 30, LPT: 30 -> u0, 30 -> u1, 15 -> u2, 15 -> u3: max 30.
  o.partition = Partition::tiles;
  Plan tiles = make_plan(f.tris.data(), f.tris.size(), f.bins(), UnitConfig{}, o);
  EXPECT_EQ(tiles.report.frame_clocks(), 30u);
  // On 3 units LPT of six equal triangles gives 30 each: imbalance exactly 1.
  o.units = 3;
  o.partition = Partition::lpt;
  EXPECT_DOUBLE_EQ(make_plan(f.tris.data(), f.tris.size(), f.bins(), UnitConfig{}, o).report.imbalance(), 1.0);
}

TEST(PlannerPlan, RefusesBadOptions) {
  const Fixture f = four_tiles();
  PlanOptions o;
  o.units = 0;
  EXPECT_THROW(make_plan(f.tris.data(), f.tris.size(), f.bins(), UnitConfig{}, o), UsageError);
  o.units = 2;
  o.batch = 0;
  EXPECT_THROW(make_plan(f.tris.data(), f.tris.size(), f.bins(), UnitConfig{}, o), UsageError);
  EXPECT_THROW(parse_partition("greedy"), UsageError);
}

}  // namespace
}  // namespace parashade
