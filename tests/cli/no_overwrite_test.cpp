// No command writes over one of its inputs, another of its outputs, or a destination that is not a regular
// file (issue 44; command_files.hpp). Each case names an output that is an input (the scene, its mesh, a
// tune cache, a triangle list, an image compared) and must be refused before any work with exit 2, the
// input's bytes unchanged; a FIFO or a folder as a destination is refused with exit 3 and stays what it
// was; a symbolic link is written through (its target replaced, the link kept). The MPI renders are held
// to the same in tests/mpi/mpi_test.py (group faults).
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class CliNoOverwrite : public CliTest {
 protected:
  CliNoOverwrite() {
    mesh_ = input("tetra.obj", tetrahedron_obj());
    scene_ = input("tetra.json", R"({
  "resolution": [48, 32],
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
  "lights": [{"type": "directional", "direction": [0, 0, -1]}],
  "objects": [{"mesh": "tetra.obj"}]
})");
  }

  // The run is refused with `code` naming `option`, and every input file keeps its bytes.
  void expect_refused(const std::vector<std::string>& args, int code, const std::string& option) {
    const std::string scene = bytes_of(scene_), mesh = bytes_of(mesh_);
    const RunResult r = run_parashade(args);
    EXPECT_TRUE(fails_with(r, code, {option}));
    EXPECT_EQ(bytes_of(scene_), scene) << "the scene file was changed";
    EXPECT_EQ(bytes_of(mesh_), mesh) << "the mesh file was changed";
  }

  // render SCENE -o out/image.png, one quiet frame without the error figures, then `extra` (no --report).
  std::vector<std::string> render_to(std::vector<std::string> extra) const {
    std::vector<std::string> a = {"render", scene_.string(), "-o", image().string(), "--frames", "1", "--warmup", "0",
                                  "-q", "--no-error"};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }

  std::vector<std::string> tune(std::vector<std::string> extra) const {
    std::vector<std::string> a = {"tune", scene_.string(), "--frames", "1", "--budget-runs", "1", "-q",
                                  "--cache", (out_dir() / "cache.json").string()};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }

  fs::path scene_, mesh_;
};

TEST_F(CliNoOverwrite, RenderRefusesItsSceneMeshListAndCache) {
  expect_refused(render_to({"--report", mesh_.string()}), kUsage, "--report");
  const fs::path list = input("phong.txt", "0 2\n");
  expect_refused(render_to({"--method", "combined:0", "--triangle-choice", "list:" + list.string(),
                                      "--report", list.string()}),
                 kUsage, "--triangle-choice list:");
  EXPECT_EQ(bytes_of(list), "0 2\n");
  const fs::path cache = input("tc.json", "{}");
  expect_refused(render_to({"--tune-cache", cache.string(), "--report", cache.string()}), kUsage, "--tune-cache");
  EXPECT_EQ(bytes_of(cache), "{}");
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliNoOverwrite, TuneRefusesItsSceneMeshAndCache) {
  expect_refused(tune({"--report", scene_.string()}), kUsage, "the scene");
  expect_refused(tune({"--report", mesh_.string()}), kUsage, "a mesh of the scene");
  expect_refused(tune({"--export-kt", mesh_.string()}), kUsage, "--export-kt");
  expect_refused(tune({"--export-t4", mesh_.string()}), kUsage, "--export-t4");
  expect_refused(tune({"--report", (out_dir() / "cache.json").string()}), kUsage, "--cache");
  expect_refused({"tune", scene_.string(), "--cache", scene_.string(), "-q"}, kUsage, "--cache");
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliNoOverwrite, ScalingAndPlanRefuseTheMesh) {
  expect_refused({"scaling", scene_.string(), "--units", "classic", "--frames", "1", "-q", "--report", mesh_.string()},
                 kUsage, "--report");
  expect_refused({"plan", scene_.string(), "--report", mesh_.string()}, kUsage, "--report");
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliNoOverwrite, CompareRefusesTheImagesItCompares) {
  ASSERT_TRUE(succeeds(render(scene_)));
  const fs::path a = in_dir() / "a.png";
  fs::copy_file(image(), a);
  const std::string bytes = bytes_of(a);
  for (const char* option : {"--report", "--error-map", "--flip-map"}) {
    const RunResult r = run_parashade({"compare", a.string(), image().string(), option, a.string()});
    EXPECT_TRUE(fails_with(r, kUsage, {option}));
    EXPECT_EQ(bytes_of(a), bytes) << option;
  }
}

TEST_F(CliNoOverwrite, NoDestinationThatIsNotARegularFile) {
  const fs::path fifo = out_dir() / "fifo.json", folder = out_dir() / "folder.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directory(folder);
  const std::vector<std::vector<std::string>> commands = {
      render_to({}),
      tune({}),
      {"scaling", scene_.string(), "--units", "classic", "--frames", "1", "-q"},
      {"plan", scene_.string()},
      {"devices"},
      {"combinations"},
      {"unit-error", "--units", "classic", "--arith", "fixed:12.12", "--trials", "1"},
      {"vectors", "--unit", "classic", "--arith", "fixed:12.12", "--spans", "1", "-o", (out_dir() / "v.txt").string()},
  };
  for (std::vector<std::string> args : commands)
    for (const fs::path& bad : {fifo, folder}) {
      std::vector<std::string> a = args;
      a.insert(a.end(), {"--report", bad.string()});
      const RunResult r = run_parashade(a);
      EXPECT_TRUE(fails_with(r, kBadInput, {bad.string()})) << a[0];
    }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_directory(folder) && fs::is_empty(folder));
  // An image destination too: a FIFO would have been renamed over.
  const fs::path png_fifo = out_dir() / "pipe.png";
  ASSERT_EQ(::mkfifo(png_fifo.c_str(), 0600), 0);
  EXPECT_TRUE(fails_with(run_parashade({"render", scene_.string(), "-o", png_fifo.string(), "-q", "--no-error"}), kBadInput,
                         {"FIFO"}));
  EXPECT_TRUE(fs::is_fifo(png_fifo));
}

TEST_F(CliNoOverwrite, ALinkIsWrittenThrough) {
  const fs::path target = out_dir() / "target.json", link = out_dir() / "link.json";
  { std::ofstream(target) << "old"; }
  fs::create_symlink(target, link);
  ASSERT_TRUE(succeeds(run_parashade(render_to({"--report", link.string()}))));
  EXPECT_TRUE(fs::is_symlink(link)) << "the link was replaced by a file";
  EXPECT_NE(bytes_of(target), "old") << "the link's target was not written";
  EXPECT_EQ(nlohmann::json::parse(bytes_of(target))["schema"], "parashade.render/2");
}

}  // namespace
}  // namespace parashade
