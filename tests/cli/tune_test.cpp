// parashade tune (docs/tuning.md): the search space of --param and its errors, the strategies' sequences
// and budgets, the error-budget objective, cache invalidation by build and device, and the Kernel Tuner
// export. A small procedural scene at a small size; one timed frame per candidate.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <future>
#include <thread>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"
#include "parashade/kernels/constants.h"

namespace parashade {
namespace {

using namespace testing_support;

class CliTune : public CliTest {
 protected:
  std::filesystem::path cache() const { return out_dir() / "cache.json"; }

  // tune SCENE --cache out/cache.json --report out/report.json --frames 1 -q on the test device, then `extra`.
  RunResult tune(std::vector<std::string> extra, const std::filesystem::path& cache_file = {}) const {
    std::vector<std::string> args = {"tune",     scene_.string(), "--cache", (cache_file.empty() ? cache() : cache_file).string(),
                                     "--report", report().string(), "--frames", "1", "-q"};
    const std::vector<std::string> device = device_args();
    args.insert(args.end(), device.begin(), device.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return run_parashade(args, {}, std::chrono::seconds(300));
  }

  // The candidates' parameters in the report, in order.
  std::vector<nlohmann::json> visited() const {
    std::vector<nlohmann::json> out;
    for (const auto& c : field(read_report(), "/candidates")) out.push_back(c["params"]);
    return out;
  }

  nlohmann::json read_json(const std::filesystem::path& p) const {
    std::ifstream in(p);
    return nlohmann::json::parse(in, nullptr, false);
  }

  // The error of the image `render` gives for `method`, against exact Phong, measured by render itself.
  double render_error(const std::string& method) const {
    const RunResult r = render(scene_, {"--method", method, "--no-tuned"}, ErrorFigures::compute);
    EXPECT_TRUE(succeeds(r));
    return field(read_report(), "/error/method/max_abs").get<double>();
  }

  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

// --- the space ---------------------------------------------------------------------------------------

TEST_F(CliTune, UnknownParameterNamesTheValidOnes) {
  const RunResult r = tune({"--param", "colour=red"});
  EXPECT_TRUE(fails_with(r, kUsage, {"colour", "tile", "work_items", "partition", "cu", "batch", "method", "units",
                                     "normalize", "specular"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliTune, BadValuesNameTheParameterAndTheValidValues) {
  // Each valid-value list comes from the project's own tables (tile sizes, partitions, the unit table,
  // the method axis of the table of combinations, the Phong parsers).
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"tile=17", {"--param tile", "17", "16, 32 or 64"}},
      {"tile=big", {"--param tile", "big"}},
      {"partition=lpt,zigzag", {"--param partition", "zigzag", "none", "round-robin", "dynamic"}},
      {"cu=99999", {"--param cu", "99999", "4096"}},
      {"batch=0", {"--param batch", "0"}},
      {"method=gouraud,toon", {"--param method", "toon", "flat", "phong", "combined:auto"}},
      {"method=combined:99", {"--param method", "combined:99"}},
      {"units=abacus", {"--param units", "abacus", "classic", "sierpinski", "interleave"}},
      {"normalize=nearest", {"--param normalize", "nearest", "slerp"}},
      {"specular=mirror", {"--param specular", "mirror", "quadratic"}},
      {"tile=16,32,16", {"--param tile", "twice"}},
      {"tile=", {"--param tile", "16, 32 or 64"}},
  };
  for (const auto& [param, culprits] : cases) {
    SCOPED_TRACE(param);
    const RunResult r = tune({"--param", param});
    ASSERT_TRUE(r.exited()) << r;
    EXPECT_EQ(r.exit_code, kUsage) << r;
    for (const std::string& c : culprits) EXPECT_NE(r.err.find(c), std::string::npos) << "stderr lacks '" << c << "'" << r;
  }
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliTune, BadOptionsAreUsageErrors) {
  EXPECT_TRUE(fails_with(tune({"--strategy", "genetic"}), kUsage, {"--strategy", "genetic", "anneal"}));
  EXPECT_TRUE(fails_with(tune({"--objective", "slowest"}), kUsage, {"--objective", "slowest", "fastest"}));
  EXPECT_TRUE(fails_with(tune({"--max-error", "-1"}), kUsage, {"--max-error"}));
  EXPECT_TRUE(fails_with(tune({"--mpi", "--strategy", "anneal"}), kUsage, {"--mpi", "anneal"}));
  EXPECT_TRUE(fails_with(tune({"--param", "method=flat", "--param", "units=counter"}), kUsage, {"no point"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliTune, RefusedCombinationsAreSkippedAndCounted) {
  // flat through a shading unit is refused by the table of combinations; flat without one is not.
  const RunResult r = tune({"--param", "tile=16", "--param", "work_items=0", "--param", "partition=none",
                            "--param", "method=flat,gouraud", "--param", "units=none,counter", "--budget-runs", "10"});
  ASSERT_TRUE(succeeds(r));
  EXPECT_NE(r.out.find("3 valid, 1 refused"), std::string::npos) << r;
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/points/refused"), 1);
  EXPECT_EQ(field(rep, "/points/valid"), 3);
  EXPECT_EQ(field(rep, "/candidates").size(), 3u);
  for (const auto& p : visited()) EXPECT_FALSE(p["method"] == "flat" && p["units"] == "counter") << p;
}

TEST_F(CliTune, UnitsAndBatchAreOnlyVariedWhereAPlanReadsThem) {
  const RunResult r = tune({"--param", "tile=16", "--param", "work_items=0", "--param", "partition=none,lpt,dynamic",
                            "--param", "cu=2,4", "--param", "batch=16,64", "--budget-runs", "20"});
  ASSERT_TRUE(succeeds(r));
  // none: 1 point; lpt: 2 (U); dynamic: 2 x 2.
  EXPECT_EQ(field(read_report(), "/points/valid"), 7);
  EXPECT_EQ(field(read_report(), "/points/not_applicable"), 12 - 7);
  std::set<std::string> seen;
  for (const auto& p : visited()) seen.insert(p.dump());
  EXPECT_EQ(seen.size(), 7u);
  EXPECT_EQ(seen.count(nlohmann::json({{"tile", 16}, {"work_items", 0}, {"kernel_shape", "vector"},
                                       {"work_group_size", 0}, {"partition", "none"}, {"cu", "-"},
                                       {"batch", "-"}, {"method", "gouraud"}, {"units", "none"}, {"normalize", "exact"},
                                       {"specular", "exact"}}).dump()), 1u);
}

// The kernel's shape and work-group are layout parameters like the tile: searched when asked, each point's image
// verified against the default layout's (the same bytes for Gouraud), work_items unread by the lanes shape (a
// work-group per tile) and a lanes work-group larger than the tile's pixels not applicable; the cache keeps the
// lanes entries' shape and work-group.
TEST_F(CliTune, SearchesTheKernelShapeAndWorkGroupSize) {
  const std::filesystem::path cache = out_dir() / "cache.json";
  const RunResult r = tune({"--param", "tile=16", "--param", "work_items=0,8", "--param", "kernel_shape=vector,lanes",
                            "--param", "work_group_size=0,64,512", "--param", "partition=none"},
                           cache);
  ASSERT_TRUE(succeeds(r));
  // vector: 2 work_items x 3 groups (512: the vector shape's work-items in whole groups); lanes: 0 and 64 (512 > 16 x 16).
  EXPECT_EQ(field(read_report(), "/points/valid"), 6 + 2);
  EXPECT_EQ(field(read_report(), "/candidates").size(), 8u);
  int lanes = 0;
  for (const auto& c : field(read_report(), "/candidates")) {
    EXPECT_TRUE(c["verified"].get<bool>()) << c;
    if (c["params"]["kernel_shape"] == "lanes") {
      ++lanes;
      EXPECT_EQ(c["params"]["work_items"], "-") << c;
    }
  }
  EXPECT_EQ(lanes, 2);
  int cached_lanes = 0;
  const nlohmann::json entries = read_json(cache)["entries"];
  for (const auto& e : entries) cached_lanes += e["params"].value("kernel_shape", "") == "lanes";
  EXPECT_EQ(cached_lanes, 2);
}

// The best's "render with:" line is the render options of its parameters (each parameter is named as the
// option it sets): rendering with them gives the best's layout and shading.
TEST_F(CliTune, RenderWithGivesTheBestsParameters) {
  const RunResult r = tune({"--param", "tile=32", "--param", "work_items=8", "--param", "partition=lpt",
                            "--param", "cu=3", "--param", "method=phong", "--param", "units=counter"});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json best = field(read_report(), "/best/params");
  const std::size_t at = r.out.find("render with: ");
  ASSERT_NE(at, std::string::npos) << r;
  std::istringstream line(r.out.substr(at + 13, r.out.find('\n', at) - at - 13));
  std::vector<std::string> flags{std::istream_iterator<std::string>(line), std::istream_iterator<std::string>()};
  flags.push_back("--no-tuned");
  // The work-group left to the device (the space's 0) is left out, as render's default: not --work-group-size 0.
  EXPECT_EQ(std::find(flags.begin(), flags.end(), "--work-group-size"), flags.end()) << r.out;
  ASSERT_TRUE(succeeds(render(scene_, flags))) << r.out;
  const nlohmann::json rep = read_report();
  EXPECT_EQ(rep["tile"], best["tile"]);
  // The report's work-items are the kernel's: at most one per tile (this frame has 4 tiles of 32).
  const auto wi = std::find(flags.begin(), flags.end(), "--work-items");
  ASSERT_NE(wi, flags.end());
  EXPECT_EQ(std::stoi(*(wi + 1)), best["work_items"].get<int>());
  EXPECT_EQ(rep["method"], best["method"]);
  EXPECT_EQ(rep["units"], best["units"]);
  EXPECT_EQ(field(rep, "/plan/units"), best["cu"]);
  EXPECT_EQ(field(rep, "/plan/partition"), best["partition"]);
}

// --- strategies ------------------------------------------------------------------------------------------

const std::vector<std::string> kLayout = {"--param", "tile=16,32,64", "--param", "work_items=0,8",
                                          "--param", "partition=none,lpt", "--param", "cu=2,4"};

TEST_F(CliTune, RandomVisitsTheSameSequenceForTheSameSeed) {
  std::vector<std::string> args = kLayout;
  args.insert(args.end(), {"--strategy", "random", "--seed", "7", "--budget-runs", "4"});
  ASSERT_TRUE(succeeds(tune(args, out_dir() / "a.json")));
  const auto first = visited();
  ASSERT_EQ(first.size(), 4u);
  ASSERT_TRUE(succeeds(tune(args, out_dir() / "b.json")));
  EXPECT_EQ(visited(), first);
  args[args.size() - 3] = "8";  // --seed 8
  ASSERT_TRUE(succeeds(tune(args, out_dir() / "c.json")));
  EXPECT_NE(visited(), first);
}

TEST_F(CliTune, BruteMeasuresTheDefaultFirstAndResumesFromTheCache) {
  std::vector<std::string> args = kLayout;
  args.insert(args.end(), {"--budget-runs", "3"});
  ASSERT_TRUE(succeeds(tune(args)));
  const auto first = visited();
  ASSERT_EQ(first.size(), 3u);
  EXPECT_EQ(first[0]["tile"], TILE_MAX);  // the default configuration first: render's tile for this Gouraud frame
  EXPECT_EQ(first[0]["work_items"], 0);
  EXPECT_EQ(first[0]["partition"], "none");
  // The next run continues the same sequence after what is cached.
  const RunResult second = tune(args);
  ASSERT_TRUE(succeeds(second));
  EXPECT_NE(second.out.find("3 already in the cache"), std::string::npos) << second;
  const auto next = visited();
  ASSERT_EQ(next.size(), 3u);
  for (const auto& p : next)
    for (const auto& q : first) EXPECT_NE(p, q);
}

TEST_F(CliTune, AnnealKeepsToItsBudget) {
  std::vector<std::string> args = kLayout;
  args.insert(args.end(), {"--strategy", "anneal", "--seed", "3", "--budget-runs", "5"});
  ASSERT_TRUE(succeeds(tune(args)));
  const auto seen = visited();
  EXPECT_EQ(seen.size(), 5u);
  std::set<std::string> distinct;
  for (const auto& p : seen) distinct.insert(p.dump());
  EXPECT_EQ(distinct.size(), 5u);
}

// --- the error budget --------------------------------------------------------------------------------

TEST_F(CliTune, AnErrorBudgetChoosesTheExactMethodOverTheFastOneThatMissesIt) {
  // The budget lies between Phong's and Gouraud's error as render measures them: Gouraud must be
  // recorded over the budget and the best must be Phong, however fast Gouraud is.
  const double gouraud = render_error("gouraud"), phong = render_error("phong");
  ASSERT_LT(phong + 1.0, gouraud) << "the scene does not separate the methods";
  const double budget = (gouraud + phong) / 2;
  const RunResult r = tune({"--param", "tile=16", "--param", "work_items=0", "--param", "partition=none", "--param",
                            "method=gouraud,phong", "--max-error", std::to_string(budget)});
  ASSERT_TRUE(succeeds(r));
  const nlohmann::json rep = read_report();
  ASSERT_EQ(field(rep, "/candidates").size(), 2u) << rep.dump(2);
  for (const auto& c : rep["candidates"]) {
    const bool is_gouraud = c["params"]["method"] == "gouraud";
    EXPECT_NEAR(c["max_abs"].get<double>(), is_gouraud ? gouraud : phong, 1e-9) << c.dump();
    EXPECT_EQ(c["within_budget"], !is_gouraud) << c.dump();
    EXPECT_TRUE(c["verified"].get<bool>()) << c.dump();
  }
  EXPECT_EQ(field(rep, "/best/params/method"), "phong") << rep.dump(2);
  EXPECT_NE(r.out.find("render with: --method phong"), std::string::npos) << r;
  // Without the budget Gouraud is eligible too (which is faster is the machine's business).
  ASSERT_TRUE(succeeds(tune({"--param", "tile=16", "--param", "work_items=0", "--param", "partition=none", "--param",
                             "method=gouraud,phong"},
                            out_dir() / "nobudget.json")));
  for (const auto& c : field(read_report(), "/candidates")) EXPECT_TRUE(c["within_budget"].get<bool>()) << c.dump();
}

TEST_F(CliTune, AnNmseBudgetNoCandidateMeetsLeavesNoBest) {
  const RunResult r = tune({"--param", "tile=16", "--param", "work_items=0", "--param", "partition=none", "--param",
                            "method=gouraud", "--max-nmse", "1e-30"});
  ASSERT_TRUE(succeeds(r));
  EXPECT_TRUE(field(read_report(), "/best").is_null());
  EXPECT_NE(r.out.find("no candidate is eligible"), std::string::npos) << r;
}

// --- the cache -----------------------------------------------------------------------------------------

TEST_F(CliTune, CacheEntriesOfAnotherBuildOrDeviceAreNotUsed) {
  ASSERT_TRUE(succeeds(tune({"--param", "tile=32", "--param", "work_items=0", "--param", "partition=none"})));
  const nlohmann::json good = read_json(cache());
  ASSERT_EQ(field(good, "/entries").size(), 1u) << good.dump(2);
  // The entry is used as it is ...
  RunResult used = render(scene_, {"--tune-cache", cache().string()});
  ASSERT_TRUE(succeeds(used));
  // A note as every note reads (notes.hpp); before 2026-12-07 this one and the stale entries' lacked the prefix.
  EXPECT_NE(used.err.find("parashade: note: using the tuned configuration"), std::string::npos) << used;
  for (const char* setting : {"kernel_shape", "work_group_size", "work_items", "tile"})
    EXPECT_EQ(field(read_report(), std::string("/layout/sources/") + setting), "tune cache") << setting;

  const auto rewrite = [&](const std::string& pointer, const nlohmann::json& value, const std::string& name) {
    nlohmann::json c = good;
    c["entries"][0][nlohmann::json::json_pointer(pointer)] = value;
    const std::filesystem::path p = out_dir() / name;
    std::ofstream(p) << c.dump(1);
    return p;
  };
  const auto other_build = rewrite("/version", "0.0.1+deadbee", "other_build.json");
  const auto other_cus = rewrite("/compute_units", good["entries"][0]["compute_units"].get<int>() + 7, "other_cus.json");
  const auto other_driver = rewrite("/driver_version", "driver from elsewhere", "other_driver.json");
  // Two implementations may give one CPU the same name (PoCL's and Intel's runtimes): the platform tells them apart.
  const auto other_platform = rewrite("/platform", "Intel(R) OpenCL", "other_platform.json");
  const std::string name = good["entries"][0]["device_name"];
  for (const auto& [path, why] : std::vector<std::pair<std::filesystem::path, std::string>>{
           {other_build, "another parashade build (0.0.1+deadbee"},
           {other_cus, "another device"},
           {other_driver, "another device (" + good["entries"][0]["platform"].get<std::string>() + " / " + name +
                              ", driver driver from elsewhere"},
           {other_platform, "1 entry of another device (Intel(R) OpenCL / " + name + ", driver "}}) {
    SCOPED_TRACE(path.filename().string());
    // ... but not by render, which says why ...
    const RunResult r = render(scene_, {"--tune-cache", path.string()});
    ASSERT_TRUE(succeeds(r));
    EXPECT_EQ(r.err.find("using the tuned configuration"), std::string::npos) << r;
    const RunResult noisy = run_parashade({"render", scene_.string(), "-o", image().string(), "--frames", "1",
                                           "--warmup", "0", "--no-error", "--tune-cache", path.string()});
    EXPECT_NE(noisy.err.find(why), std::string::npos) << noisy;
    EXPECT_NE(noisy.err.find("parashade: note: tune cache '" + path.string() + "': "), std::string::npos) << noisy;
    EXPECT_TRUE(field(read_report(), "/tuned").is_null());
    // ... and tune measures the configuration again instead of skipping it.
    const RunResult again = tune({"--param", "tile=32", "--param", "work_items=0", "--param", "partition=none"}, path);
    ASSERT_TRUE(succeeds(again));
    EXPECT_NE(again.out.find("0 already in the cache"), std::string::npos) << again;
    EXPECT_EQ(field(read_report(), "/candidates").size(), 1u);
  }
}

// Issue 46, item 5: two tune runs on one cache. Each run read the cache once and every write replaced the
// file with what it had read plus its own entries: the entries the other run wrote meanwhile were lost
// (whichever wrote last won). Now every write merges with the file under a lock. The first run measures
// 180 configurations of a 21 000-triangle frame (several seconds); the second starts while it runs.
TEST_F(CliTune, TwoRunsOnOneCacheKeepEachOthersEntries) {
  const std::filesystem::path fine = input("fine.json", many_triangles_scene());
  const auto tune_fine = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"tune", fine.string(), "--cache", cache().string(), "--frames", "3", "-q"};
    const std::vector<std::string> device = device_args();
    args.insert(args.end(), device.begin(), device.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return run_parashade(args, {}, std::chrono::seconds(300));
  };
  std::string many;
  for (int w = 1; w <= 60; ++w) many += (w > 1 ? "," : "") + std::to_string(w);
  auto first = std::async(std::launch::async, [&] {
    return tune_fine({"--param", "tile=16,32,64", "--param", "work_items=" + many, "--param", "partition=none",
                      "--budget-runs", "180"});
  });
  // The first run has read the cache once it has written its first entry.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!std::filesystem::exists(cache()) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(std::filesystem::exists(cache())) << "the first run wrote no cache";
  const bool overlapped = first.wait_for(std::chrono::seconds(0)) == std::future_status::timeout;
  const RunResult second = tune_fine({"--param", "tile=16", "--param", "work_items=97", "--param", "partition=none"});
  const RunResult first_run = first.get();
  ASSERT_TRUE(succeeds(second));
  ASSERT_TRUE(succeeds(first_run));
  ASSERT_TRUE(overlapped) << "the first run ended before the second started: make it longer" << first_run;
  int of_first = 0, of_second = 0;
  for (const auto& e : field(read_json(cache()), "/entries"))
    (e["params"]["work_items"] == 97 ? of_second : of_first) += 1;
  EXPECT_EQ(of_second, 1);
  EXPECT_EQ(of_first, 180);
}

// The default cache's folder may not exist yet (a fresh machine): tune makes it. It was refused since the
// outputs' folders are checked before the work ("directory '.../parashade' does not exist").
TEST_F(CliTune, TheDefaultCacheFolderIsMadeOnAFreshMachine) {
  const std::filesystem::path home = out_dir() / "fresh-cache-home";
  const ScopedEnv explicit_cache("PARASHADE_TUNE_CACHE", nullptr);
  const ScopedEnv xdg("XDG_CACHE_HOME", home.string());
  std::vector<std::string> args = {"tune", scene_.string(), "--report", report().string(), "--frames", "1", "-q",
                                   "--param", "tile=32", "--param", "work_items=0", "--param", "partition=none"};
  const std::vector<std::string> device = device_args();
  args.insert(args.end(), device.begin(), device.end());
  ASSERT_TRUE(succeeds(run_parashade(args)));
  EXPECT_EQ(field(read_json(home / "parashade" / "tune.json"), "/entries").size(), 1u);
}

// A message of issue 46: entries a hand or another program broke were used and printed as if valid
// (work_items -1), or ended tune with an internal error (a string for max_error). Such entries are set
// aside with one warning naming the cache and the first fault; the valid ones are still used.
TEST_F(CliTune, EntriesThatAreNotUnderstoodAreSetAsideWithAWarning) {
  ASSERT_TRUE(succeeds(tune({"--param", "tile=32", "--param", "work_items=0,5", "--param", "partition=none"})));
  const nlohmann::json good = read_json(cache());
  ASSERT_EQ(field(good, "/entries").size(), 2u) << good.dump(2);
  const std::vector<std::pair<std::string, nlohmann::json>> faults = {
      {"/params/work_items", -1},      {"/params/work_items", 0.5},   {"/params/tile", 17},
      {"/params/tile", "big"},         {"/problem/units", "bogus:999"}, {"/objective", "fast"},
      {"/max_error", "x"},             {"/params", "none"}};
  for (const auto& [pointer, value] : faults) {
    SCOPED_TRACE(pointer + " = " + value.dump());
    nlohmann::json c = good;
    nlohmann::json bad = c["entries"][0];
    bad["objective"] = 1e-6;  // the best, were it used
    bad[nlohmann::json::json_pointer(pointer)] = value;
    c["entries"].push_back(bad);
    const std::filesystem::path path = out_dir() / "garbage.json";
    std::ofstream(path) << c.dump(1);
    const RunResult r = run_parashade({"render", scene_.string(), "-o", image().string(), "--frames", "1", "--warmup",
                                       "0", "--no-error", "--tune-cache", path.string()});
    ASSERT_TRUE(succeeds(r));
    EXPECT_NE(r.err.find("garbage.json"), std::string::npos) << r;
    EXPECT_NE(r.err.find("1 entry not understood"), std::string::npos) << r;
    EXPECT_NE(r.err.find("using the tuned configuration"), std::string::npos) << r;  // a valid entry
    EXPECT_EQ(r.err.find(value.dump() + "}"), std::string::npos) << r;
    const RunResult t = tune({"--param", "tile=32", "--param", "work_items=0,5", "--param", "partition=none"}, path);
    EXPECT_TRUE(succeeds(t));
    EXPECT_NE(t.err.find("1 entry not understood"), std::string::npos) << t;
    EXPECT_EQ(field(read_json(path), "/entries").size(), 3u) << "the entry set aside is kept in the file";
  }
}

// --- the Kernel Tuner export -------------------------------------------------------------------------

TEST_F(CliTune, KernelTunerExportHoldsEveryPointOfItsTuneParams) {
  const std::filesystem::path kt = out_dir() / "kt.json";
  std::vector<std::string> args = kLayout;
  args.insert(args.end(), {"--budget-runs", "5", "--export-kt", kt.string()});
  ASSERT_TRUE(succeeds(tune(args)));
  const nlohmann::json k = read_json(kt);
  ASSERT_FALSE(k.is_discarded()) << "not JSON";
  // Kernel Tuner's reader treats a cache file as open for appending unless it ends in "}\n}" with the
  // cache last (its util.correct_open_cache); anything else it "closes" again and fails to parse.
  std::ifstream text_in(kt);
  std::string text((std::istreambuf_iterator<char>(text_in)), std::istreambuf_iterator<char>());
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  EXPECT_EQ(text.substr(text.size() - 3), "}\n}");
  const nlohmann::ordered_json ordered = nlohmann::ordered_json::parse(text);
  EXPECT_EQ(ordered.items().begin().key(), "schema_version");
  std::string last;
  for (const auto& item : ordered.items()) last = item.key();
  EXPECT_EQ(last, "cache");
  for (const char* key : {"schema_version", "device_name", "kernel_name", "problem_size", "tune_params_keys",
                          "tune_params", "objective", "restrictions", "cache"})
    EXPECT_TRUE(k.contains(key)) << key;
  EXPECT_EQ(k["problem_size"], nlohmann::json({64, 48}));
  EXPECT_EQ(k["objective"], "time");
  const nlohmann::json rep = read_report();
  EXPECT_EQ(k["device_name"], rep["device"]["name"]);
  // Kernel Tuner's simulation mode looks up every point of tune_params' product (before, the export held
  // the 5 measured ones and the replay of this partial run failed): tile 3 x work_items 2 x partition 2 x
  // cu (2, 4 and "-" without a plan) x batch ("-" alone: no point has a dynamic partition) = 36; of the 18
  // points of the space, 5 measured and 13 not, the other 18 combinations are no point of the space.
  EXPECT_EQ(k["tune_params"]["cu"], nlohmann::json({2, 4, "-"}));
  EXPECT_EQ(k["tune_params"]["batch"], nlohmann::json({"-"}));
  ASSERT_EQ(k["cache"].size(), 36u);
  std::map<std::string, int> statuses;
  for (const auto& [key, e] : k["cache"].items()) {
    ++statuses[e["status"].get<std::string>()];
    if (e["status"] != "measured") {
      EXPECT_EQ(e["time"], "InvalidConfig") << key;
      EXPECT_EQ(e["__error__"], "InvalidConfig") << key;
    }
  }
  EXPECT_EQ(statuses, (std::map<std::string, int>{{"measured", 5}, {"not_measured", 13}, {"not_a_point", 18}}));
  ASSERT_EQ(rep["candidates"].size(), 5u);
  const std::vector<std::string> keys = k["tune_params_keys"];
  for (const auto& c : rep["candidates"]) {
    std::string key;
    for (const std::string& n : keys) {
      const nlohmann::json& v = c["params"][n];
      key += (key.empty() ? "" : ",") + (v.is_string() ? v.get<std::string>() : v.dump());
    }
    ASSERT_TRUE(k["cache"].contains(key)) << key;
    const nlohmann::json& e = k["cache"][key];
    for (const char* f : {"time", "times", "compile_time", "verification_time", "benchmark_time", "strategy_time",
                          "framework_time", "timestamp"})
      EXPECT_TRUE(e.contains(f)) << key << " lacks " << f;
    EXPECT_EQ(e["time"], c["frame_ms"]);
    // The report's names (report format 2) under the export's own: every timed frame, the measured error.
    EXPECT_EQ(e["times"], c["timing"]["samples_ms"]) << key;
    EXPECT_FALSE(e["times"].empty()) << key;
    EXPECT_EQ(e["max_error"], c["max_abs"]) << key;
    for (const std::string& n : keys) EXPECT_EQ(e[n], c["params"][n]) << key;
  }
}

TEST_F(CliTune, ExportsMarkOverBudgetCandidatesInvalid) {
  // A budget between Phong's and Gouraud's error as render measures them: Gouraud is over it. Before, the
  // over-budget entry carried its time and Kernel Tuner took it as valid.
  const double gouraud = render_error("gouraud"), phong = render_error("phong");
  ASSERT_LT(phong + 1.0, gouraud) << "the scene does not separate the methods";
  const std::filesystem::path kt = out_dir() / "kt.json", t4 = out_dir() / "t4.json";
  ASSERT_TRUE(succeeds(tune({"--param", "tile=16", "--param", "work_items=0", "--param", "partition=none", "--param",
                             "method=gouraud,phong", "--max-error", std::to_string((gouraud + phong) / 2),
                             "--export-kt", kt.string(), "--export-t4", t4.string()})));
  const nlohmann::json k = read_json(kt), t = read_json(t4), rep = read_report();
  ASSERT_EQ(rep["candidates"].size(), 2u);
  std::size_t over = 0;
  for (const auto& [key, e] : k["cache"].items()) {
    if (e["method"] != "gouraud" || e["status"] == "not_a_point") continue;
    ++over;
    EXPECT_EQ(e["status"], "over_budget") << key;
    EXPECT_EQ(e["time"], "InvalidConfig") << key;
    EXPECT_EQ(e["within_budget"], false) << key;
  }
  EXPECT_EQ(over, 1u);
  ASSERT_EQ(t["results"].size(), 2u) << t.dump(1);
  for (const auto& r : t["results"]) {
    const bool gouraud = r["configuration"]["method"] == "gouraud";
    EXPECT_EQ(r["invalidity"], gouraud ? "correctness" : "correct") << r.dump();
    EXPECT_EQ(r["correctness"], gouraud ? 0 : 1) << r.dump();
  }
  EXPECT_EQ(t["schema_version"], "1.0.0");
}

// --- restrictions and the Pareto objective ----------------------------------------------------------------

TEST_F(CliTune, RestrictionsExcludePointsAndGoIntoTheExport) {
  const std::filesystem::path kt = out_dir() / "kt.json";
  const RunResult r = tune({"--param", "tile=16,32,64", "--param", "work_items=0,8", "--param", "partition=none",
                            "--restrict", "tile*work_items<=128", "--restrict", "tile>=32 || work_items==0",
                            "--budget-runs", "10", "--export-kt", kt.string()});
  ASSERT_TRUE(succeeds(r));
  // Of the 6 points, 16x8=128 fails the second, 32x8 and 64x8 the first: 3 left, all measured.
  EXPECT_NE(r.out.find("3 valid, 0 refused"), std::string::npos) << r;
  EXPECT_NE(r.out.find("where nothing reads them, 3 excluded by --restrict"), std::string::npos) << r;
  const nlohmann::json rep = read_report();
  EXPECT_EQ(field(rep, "/points/restricted"), 3);
  for (const auto& p : visited()) EXPECT_EQ(p["work_items"], 0) << p;
  const nlohmann::json k = read_json(kt);
  EXPECT_EQ(k["restrictions"], nlohmann::json({"tile*work_items<=128", "tile>=32 or work_items==0"}));
  std::size_t restricted = 0;
  for (const auto& [key, e] : k["cache"].items()) restricted += e["status"] == "restricted";
  EXPECT_EQ(restricted, 3u);
}

TEST_F(CliTune, BadRestrictionsAreUsageErrorsNamingTheExpression) {
  EXPECT_TRUE(fails_with(tune({"--restrict", "tile*<=4096"}), kUsage, {"--restrict 'tile*<=4096'"}));
  EXPECT_TRUE(fails_with(tune({"--restrict", "tiel*work_items<=4096"}), kUsage,
                         {"--restrict 'tiel*work_items<=4096'", "unknown name 'tiel'", "did you mean 'tile'"}));
  EXPECT_TRUE(fails_with(tune({"--restrict", "method==1"}), kUsage, {"'method==1'", "method is a name, not a number"}));
  EXPECT_TRUE(fails_with(tune({"--restrict", "tile>1000"}), kUsage, {"--restrict", "exclude every one"}));
  EXPECT_TRUE(nothing_written());
}

// --export-kt writes the restrictions as Python for Kernel Tuner: what has no Python reading there (muParser's
// ?:, a function other than min, max and abs, a constant) is refused before the search, naming the expression.
// Before: the search ran and the export held invalid Python ("tile>16 ? work_items<8 : 1").
TEST_F(CliTune, RestrictionsWithoutAPythonReadingAreRefusedWithTheExport) {
  const std::string kt = (out_dir() / "kt.json").string();
  EXPECT_TRUE(fails_with(tune({"--restrict", "tile>16 ? work_items<8 : 1", "--export-kt", kt}), kUsage,
                         {"--restrict 'tile>16 ? work_items<8 : 1'", "--export-kt", "the conditional a ? b : c"}));
  EXPECT_TRUE(fails_with(tune({"--restrict", "sqrt(tile)<=8", "--export-kt", kt}), kUsage,
                         {"--restrict 'sqrt(tile)<=8'", "the function 'sqrt'"}));
  EXPECT_TRUE(fails_with(tune({"--restrict", "tile<_pi*20", "--export-kt", kt}), kUsage,
                         {"--restrict 'tile<_pi*20'", "the constant '_pi'"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliTune, TheParetoObjectivePrintsAndReportsTheSpeedErrorFront) {
  const RunResult r = tune({"--param", "tile=16,32", "--param", "work_items=0", "--param", "partition=none",
                            "--param", "method=gouraud,combined:2,phong", "--objective", "pareto"});
  ASSERT_TRUE(succeeds(r));
  EXPECT_NE(r.out.find("speed-vs-error Pareto front"), std::string::npos) << r;
  const nlohmann::json rep = read_report();
  const nlohmann::json& front = field(rep, "/pareto_front");
  ASSERT_FALSE(front.empty());
  // Each point of the front is beaten on both time and error by no candidate; each candidate off it is
  // beaten by one on it; fastest first (every candidate here is verified: the layouts keep the image).
  const auto beats = [](const nlohmann::json& a, const nlohmann::json& b) {
    const double ta = a["frame_ms"], tb = b["frame_ms"], ea = a["max_abs"], eb = b["max_abs"];
    return ta <= tb && ea <= eb && (ta < tb || ea < eb);
  };
  for (const auto& f : front)
    for (const auto& c : rep["candidates"]) EXPECT_FALSE(beats(c, f)) << c.dump() << " beats " << f.dump();
  for (const auto& c : rep["candidates"])
    if (std::find(front.begin(), front.end(), c) == front.end())
      EXPECT_TRUE(std::any_of(front.begin(), front.end(), [&](const nlohmann::json& f) { return beats(f, c) || f == c; }))
          << c.dump();
  for (std::size_t i = 1; i < front.size(); ++i) EXPECT_LE(front[i - 1]["frame_ms"], front[i]["frame_ms"]);
  // Without a budget the best is the fastest candidate, the front's first.
  EXPECT_EQ(front[0]["params"], field(rep, "/best/params"));
  EXPECT_EQ(field(rep, "/objective/kind"), "pareto");
}

}  // namespace
}  // namespace parashade
