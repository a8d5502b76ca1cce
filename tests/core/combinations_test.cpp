// The table of what combines (combinations.hpp): every refusal is reachable and enforced on configurations
// written here by hand (one per rule, from the models' own limits in docs/units.md, docs/planner.md and
// docs/phong-methods.md), and configurations the project models pass.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/combinations.hpp"
#include "parashade/frame_config.hpp"

namespace parashade {
namespace {

FrameConfig config(Method m) {
  FrameConfig c;
  c.method = m;
  return c;
}

struct Refused {
  const char* label;
  FrameConfig config;
  DeviceMode devices;
  std::vector<std::string> named;  // words the message must hold: the values at fault
};

std::vector<Refused> refused_cases() {
  std::vector<Refused> out;
  auto add = [&](const char* label, FrameConfig c, std::vector<std::string> named, DeviceMode d = DeviceMode::one) {
    out.push_back({label, c, d, named});
  };
  FrameConfig c = config(Method::flat);
  c.units = parse_units("counter");
  add("flat on a unit", c, {"flat", "counter"});
  c = config(Method::flat);
  c.arith = parse_arith("fixed:12.12");  // fixed point implies the classic unit
  add("flat in fixed point", c, {"flat", "classic"});
  c = config(Method::phong);
  c.units = parse_units("sierpinski:2");
  add("phong on the extra triangulation", c, {"phong", "sierpinski:2"});
  c = config(Method::gouraud);
  c.units = parse_units("sierpinski");
  c.dda_coverage = true;
  add("sierpinski with dda", c, {"sierpinski", "dda"});
  c = config(Method::gouraud);
  c.specular = parse_specular("quadratic");
  add("specular model without phong", c, {"gouraud", "quadratic"});
  c = config(Method::combined);
  c.normalize = parse_normalize("slerp");
  add("normalization without phong", c, {"slerp"});
  c = config(Method::phong);
  c.units = parse_units("classic");
  c.normalize = parse_normalize("slerp");
  add("per-span normals on a unit", c, {"classic", "slerp"});
  c = config(Method::phong);
  c.dda_coverage = true;
  add("dda for phong", c, {"phong", "dda"});
  c = config(Method::combined);
  c.combined = parse_combined("combined:auto");
  c.units = parse_units("interleave:4");
  add("combined on a unit", c, {"interleave:4"});
  c = config(Method::gouraud);
  c.combined.rule = TriangleRule::bound;
  add("triangle choice without combined", c, {"gouraud"});
  c = config(Method::phong);
  c.combined.highlight_test = true;
  add("highlight test without combined", c, {"phong"});
  c = config(Method::gouraud);
  c.units = parse_units("counter");
  c.division = parse_division("exact");
  add("division in float", c, {"float", "exact"});
  c.arith = parse_arith("fixed:12.12");
  c.units = parse_units("interleave:4:own");
  add("division on own steps", c, {"interleave:4:own"});
  c = config(Method::combined);
  c.combined = parse_combined("combined:2");
  c.plan = PlanOptions{};
  add("combined planned", c, {"combined:2", "planned"});
  c = config(Method::gouraud);
  c.dda_coverage = true;
  c.plan = PlanOptions{};
  add("dda planned", c, {"dda"});
  c = config(Method::gouraud);
  c.units = parse_units("sierpinski");
  c.plan = PlanOptions{};
  add("sierpinski planned", c, {"sierpinski"});
  c = config(Method::gouraud);
  c.plan = PlanOptions{};
  add("plan across a device list", c, {"planned", "bands"}, DeviceMode::bands);
  c = config(Method::gouraud);
  c.plan = PlanOptions{};
  c.band_rows = 2;  // a band of a frame is a device list's share
  add("plan on a band", c, {"planned", "bands"});
  add("sub-devices for units without a plan", config(Method::gouraud), {"unit-sub-devices"}, DeviceMode::unit_sub_devices);
  // MPI ranks (docs/distributed.md)
  c = config(Method::gouraud);
  c.plan = PlanOptions{};
  add("plan on sort-first ranks", c, {"planned", "ranks-sort-first"}, DeviceMode::ranks_sort_first);
  c = config(Method::combined);
  c.combined = parse_combined("combined:2");
  add("combined on sort-last ranks", c, {"combined", "ranks-sort-last"}, DeviceMode::ranks_sort_last);
  c = config(Method::gouraud);
  c.dda_coverage = true;
  add("dda on sort-last ranks", c, {"dda", "ranks-sort-last"}, DeviceMode::ranks_sort_last);
  c = config(Method::gouraud);
  c.units = parse_units("sierpinski:1");
  add("sierpinski on sort-last ranks", c, {"sierpinski:1", "ranks-sort-last"}, DeviceMode::ranks_sort_last);
  // The lanes kernel shape: the plain frame's passes only.
  c = config(Method::gouraud);
  c.kernel_shape = KernelShape::lanes;
  c.units = parse_units("segment:4");
  add("lanes on a unit", c, {"lanes", "segment:4"});
  c.units.reset();
  c.arith = parse_arith("fixed:12.12");  // on the classic unit
  add("lanes in fixed point", c, {"lanes", "classic"});
  c = config(Method::phong);
  c.kernel_shape = KernelShape::lanes;
  c.normalize = parse_normalize("slerp");
  add("lanes with per-span normals", c, {"lanes", "slerp"});
  c = config(Method::gouraud);
  c.kernel_shape = KernelShape::lanes;
  c.plan = PlanOptions{};
  add("lanes planned", c, {"lanes", "planned"});
  c.plan.reset();
  add("lanes on sort-last ranks", c, {"lanes", "ranks-sort-last"}, DeviceMode::ranks_sort_last);
  return out;
}

TEST(Combinations, EveryRefusalIsEnforcedNamingTheValues) {
  const std::vector<Refused> cases = refused_cases();
  std::vector<bool> row_hit(refused_combinations().size(), false);
  for (const Refused& r : cases) {
    try {
      check_frame_config(r.config, r.devices);
      ADD_FAILURE() << r.label << ": accepted";
    } catch (const ConfigError& e) {
      for (const std::string& word : r.named)
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << r.label << ": " << e.what();
      EXPECT_FALSE(e.axes.empty()) << r.label;
    }
    const Refusal* row = find_refusal(combination_of(r.config, r.devices));
    if (row) row_hit[std::size_t(row - refused_combinations().data())] = true;
  }
  // Every row of the table is reached by some case above: no rule is dead or untested.
  for (std::size_t i = 0; i < row_hit.size(); ++i)
    EXPECT_TRUE(row_hit[i]) << "no case reaches the refusal '" << refused_combinations()[i].reason << "'";
}

TEST(Combinations, ModeledConfigurationsPass) {
  std::vector<FrameConfig> modeled;
  FrameConfig c = config(Method::gouraud);
  c.units = parse_units("counter");
  c.arith = parse_arith("fixed:12.12");
  c.division = parse_division("shiftadd:12");
  c.plan = PlanOptions{};
  c.tile_size = 64;
  modeled.push_back(c);
  c = config(Method::phong);
  c.units = parse_units("segment:8");
  c.arith = parse_arith("fixed:10.4");
  modeled.push_back(c);
  c = config(Method::phong);
  c.normalize = parse_normalize("dichotomy:linear:3");
  c.specular = parse_specular("cosk:lobe:4");
  modeled.push_back(c);
  c = config(Method::combined);
  c.combined = parse_combined("combined:auto");
  c.combined.rule = TriangleRule::bound;
  c.combined.highlight_test = true;
  modeled.push_back(c);
  c = config(Method::gouraud);
  c.dda_coverage = true;
  c.arith = parse_arith("fixed:12.12");
  modeled.push_back(c);
  c = config(Method::gouraud);
  c.units = parse_units("sierpinski:1:touch");
  modeled.push_back(c);
  // The lanes shape: every method of the plain frame, specular models, the combined method's choices.
  for (Method m : {Method::flat, Method::gouraud, Method::phong, Method::combined}) {
    c = config(m);
    c.kernel_shape = KernelShape::lanes;
    modeled.push_back(c);
  }
  c.combined = parse_combined("combined:auto");
  c.combined.rule = TriangleRule::bound;
  c.combined.highlight_test = true;
  modeled.push_back(c);
  c = config(Method::phong);
  c.kernel_shape = KernelShape::lanes;
  c.specular = parse_specular("quadratic");
  modeled.push_back(c);
  for (const FrameConfig& m : modeled) EXPECT_NO_THROW(check_frame_config(m)) << describe_combinations();
  c = config(Method::phong);
  c.plan = PlanOptions{};
  EXPECT_NO_THROW(check_frame_config(c, DeviceMode::unit_sub_devices));
  EXPECT_NO_THROW(check_frame_config(config(Method::flat), DeviceMode::bands));
  // MPI ranks: combined and dda by bands (sort-first), fixed-point units by depth keys (sort-last).
  FrameConfig combined = config(Method::combined);
  combined.combined = parse_combined("combined:2");
  EXPECT_NO_THROW(check_frame_config(combined, DeviceMode::ranks_sort_first));
  combined.kernel_shape = KernelShape::lanes;  // bands of a frame: a global offset
  EXPECT_NO_THROW(check_frame_config(combined, DeviceMode::ranks_sort_first));
  EXPECT_NO_THROW(check_frame_config(combined, DeviceMode::bands));
  FrameConfig fixed_unit = config(Method::gouraud);
  fixed_unit.units = parse_units("counter");
  fixed_unit.arith = parse_arith("fixed:12.12");
  EXPECT_NO_THROW(check_frame_config(fixed_unit, DeviceMode::ranks_sort_last));
  fixed_unit.plan = PlanOptions{};
  EXPECT_NO_THROW(check_frame_config(fixed_unit, DeviceMode::ranks_sort_last));
}

TEST(Combinations, ValuesOutOfRangeAreUsageErrors) {
  FrameConfig c = config(Method::gouraud);
  c.tile_size = 24;
  EXPECT_THROW(check_frame_config(c), UsageError);
  c.tile_size = 16;
  c.plan = PlanOptions{};
  c.plan->batch = 0;
  EXPECT_THROW(check_frame_config(c), UsageError);
  c.plan->batch = 1;
  c.plan->units = 4097;
  EXPECT_THROW(check_frame_config(c), UsageError);
}

TEST(Combinations, TheListingShowsEveryAxisAndReason) {
  const std::string text = describe_combinations();
  for (int a = 0; a < kAxes; ++a) EXPECT_NE(text.find(axis_name(Axis(a))), std::string::npos) << axis_name(Axis(a));
  for (const Refusal& r : refused_combinations()) EXPECT_NE(text.find(r.reason), std::string::npos) << r.reason;
  EXPECT_NE(text.find("combinations are modeled"), std::string::npos);
}

}  // namespace
}  // namespace parashade
