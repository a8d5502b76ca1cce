// Issue 17, B: inputs that would hang or eat memory. Scene and mesh paths must be regular files of a
// bounded size, checked before reading (item 5); a scene is budgeted across its objects before anything
// is built (item 6); --frames has a limit and long runs show progress on a terminal only (item 7).
#include <pty.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class CliHostileInput : public CliTest {};

// A FIFO used to block the scene reader forever (no writer ever comes).
TEST_F(CliHostileInput, FifoSceneIsRefusedAtOnce) {
  const fs::path fifo = in_dir() / "scene.json";
  fs::create_directories(in_dir());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const RunResult r = run_parashade(render_args(fifo), {}, std::chrono::seconds(10));
  EXPECT_TRUE(fails_with(r, kBadInput, {"scene.json", "not a regular file", "FIFO"}));
  EXPECT_TRUE(nothing_written());
}

// A link to /dev/zero used to be read until memory ran out ("unexpected end of input" after gigabytes).
TEST_F(CliHostileInput, SceneLinkedToADeviceIsRefusedAtOnce) {
  for (const char* device : {"/dev/zero", "/dev/urandom"}) {
    const fs::path link = in_dir() / (std::string("from") + fs::path(device).filename().string() + ".json");
    fs::create_directories(in_dir());
    fs::create_symlink(device, link);
    const RunResult r = run_parashade(render_args(link), {}, std::chrono::seconds(10));
    EXPECT_TRUE(fails_with(r, kBadInput, {link.filename().string(), "not a regular file", "character device"}));
  }
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliHostileInput, MeshLinkedToADeviceOrAFifoIsRefused) {
  fs::create_directories(in_dir());
  fs::create_symlink("/dev/urandom", in_dir() / "noise.obj");
  ASSERT_EQ(::mkfifo((in_dir() / "pipe.obj").c_str(), 0600), 0);
  for (const char* mesh : {"noise.obj", "pipe.obj"}) {
    const fs::path scene = input("scene.json", std::string(R"({"objects": [{"mesh": ")") + mesh + "\"}]}");
    const RunResult r = run_parashade(render_args(scene), {}, std::chrono::seconds(10));
    EXPECT_TRUE(fails_with(r, kBadInput, {mesh, "not a regular file"}));
  }
  EXPECT_TRUE(nothing_written());
}

// A mesh file beyond 4 GiB is refused by its size before a byte is read (a sparse file: no disk used).
TEST_F(CliHostileInput, MeshBeyondTheSizeLimitIsRefused) {
  const fs::path mesh = input("huge.obj", tetrahedron_obj());
  fs::resize_file(mesh, (4ull << 30) + 1);
  const fs::path scene = input("scene.json", R"({"objects": [{"mesh": "huge.obj"}]})");
  const RunResult r = run_parashade(render_args(scene), {}, std::chrono::seconds(20));
  EXPECT_TRUE(fails_with(r, kBadInput, {"huge.obj", "limit", "4294967296"}));
  EXPECT_TRUE(nothing_written());
}

// Scenes hold parameters, not geometry: a file beyond 16 MiB is refused before it is read.
TEST_F(CliHostileInput, SceneBeyondTheSizeLimitIsRefused) {
  const fs::path big = input("big.json", sphere_scene() + std::string((16 << 20) + 1, ' '));
  EXPECT_TRUE(fails_with(run_parashade(render_args(big)), kBadInput, {"big.json", "limit", "16777216"}));
  EXPECT_TRUE(nothing_written());
}

// Item 6: eight different maximal spheres (2^24 triangles each) in a 500-byte scene: refused before
// anything is built, naming the estimate, the limit and the largest objects. Before: gigabytes were
// allocated and the run ended with "out of host memory" naming nothing (or, without a limit, swapped).
TEST_F(CliHostileInput, SceneBeyondTheMemoryBudgetIsRefusedBeforeBuilding) {
  std::string objects;
  for (int i = 0; i < 8; ++i)
    objects += std::string(i ? ", " : "") + R"({"shape": {"type": "sphere", "slices": )" + std::to_string(4096 - i) +
               R"(, "stacks": 2049}})";
  const fs::path scene = input("spheres.json", R"({"objects": [)" + objects + "]}");
  ASSERT_LT(fs::file_size(scene), 600u);
  const auto start = std::chrono::steady_clock::now();
  const RunResult r = run_parashade(render_args(scene), {}, std::chrono::seconds(20));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_TRUE(fails_with(r, kBadInput, {"spheres.json", "host memory", "GiB", "limit", "PARASHADE_MEMORY_LIMIT",
                                        "largest objects", "'object 0' (sphere)"}));
  EXPECT_TRUE(nothing_written());
}

// The limit is PARASHADE_MEMORY_LIMIT when set: a tiny one refuses the small sphere scene (and --size
// is budgeted too), a malformed one is named.
TEST_F(CliHostileInput, MemoryLimitComesFromTheEnvironment) {
  const fs::path scene = input("ball.json", sphere_scene());
  {
    const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "100K");
    EXPECT_TRUE(fails_with(run_parashade(render_args(scene)), kBadInput, {"ball.json", "limit", "set by PARASHADE_MEMORY_LIMIT"}));
  }
  {
    const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "1M");  // the 64x48 scene fits, 4096x4096 does not
    EXPECT_TRUE(succeeds(run_parashade(render_args(scene))));
    fs::remove(image());
    fs::remove(report());
    EXPECT_TRUE(fails_with(run_parashade(render_args(scene, {"--size", "4096x4096"})), kBadInput,
                           {"ball.json at 4096x4096", "limit"}));
    // The budget is judged at the rendered size: a 4096x4096 scene drawn at 64x48 fits (it used to be
    // refused for its own resolution before --size applied).
    nlohmann::json large = nlohmann::json::parse(sphere_scene());
    large["resolution"] = {4096, 4096};
    EXPECT_TRUE(fails_with(run_parashade(render_args(input("large.json", large.dump()))), kBadInput, {"limit"}));
    EXPECT_TRUE(succeeds(run_parashade(render_args(in_dir() / "large.json", {"--size", "64x48"}))));
    fs::remove(image());
    fs::remove(report());
  }
  {
    // A malformed value is a usage error like every bad PARASHADE_* value (issue 47; it was exit 3).
    const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "lots");
    EXPECT_TRUE(fails_with(run_parashade(render_args(scene)), kUsage, {"PARASHADE_MEMORY_LIMIT", "lots"}));
  }
  EXPECT_TRUE(nothing_written());
}

// render_args with `option` (given there) set to `value`.
std::vector<std::string> with(std::vector<std::string> args, const std::string& option, const std::string& value) {
  const auto at = std::find(args.begin(), args.end(), option);
  if (at != args.end() && at + 1 != args.end()) *(at + 1) = value;
  return args;
}

// Item 7: --frames and --warmup have a limit (a typo of a few digits would run for days).
TEST_F(CliHostileInput, FramesBeyondTheLimitAreAUsageError) {
  const fs::path scene = input("ball.json", sphere_scene());
  EXPECT_TRUE(fails_with(run_parashade(with(render_args(scene), "--frames", "100001"), {}, std::chrono::seconds(20)),
                         kUsage, {"--frames", "100000"}));
  EXPECT_TRUE(fails_with(run_parashade(with(render_args(scene), "--warmup", "100001"), {}, std::chrono::seconds(20)),
                         kUsage, {"--warmup", "100000"}));
  EXPECT_TRUE(nothing_written());
}

// Runs parashade on a pseudo-terminal (stdout and stderr a TTY) and returns all it printed.
std::string run_on_terminal(std::vector<std::string> args) {
  std::vector<std::string> text = {parashade_binary().string()};
  text.insert(text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : text) argv.push_back(a.data());
  argv.push_back(nullptr);
  int master = -1;
  const pid_t pid = ::forkpty(&master, nullptr, nullptr, nullptr);
  if (pid < 0) return "forkpty failed";
  if (pid == 0) {
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = ::read(master, buf, sizeof buf)) > 0;) out.append(buf, std::size_t(n));  // EIO at the end
  ::close(master);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return out;
}

TEST_F(CliHostileInput, ProgressOnATerminalOnly) {
  const fs::path scene = input("ball.json", sphere_scene());
  std::vector<std::string> args = with(with(render_args(scene), "--frames", "3"), "--warmup", "1");
  args.erase(std::find(args.begin(), args.end(), "-q"));
  const std::string terminal = run_on_terminal(args);
  EXPECT_NE(terminal.find("[4/4]"), std::string::npos) << terminal;
  EXPECT_NE(terminal.find("s left"), std::string::npos) << terminal;
  const RunResult logged = run_parashade(args);  // stderr to a file
  EXPECT_TRUE(succeeds(logged));
  EXPECT_EQ(logged.err.find("[4/4]"), std::string::npos) << logged.err;
  args.push_back("-q");
  const std::string quiet = run_on_terminal(args);
  EXPECT_EQ(quiet.find("[4/4]"), std::string::npos) << quiet;
  EXPECT_NE(quiet.find("wrote"), std::string::npos) << quiet;
}

// Issue 46, item 8: compare read /dev/zero (or /dev/urandom, a FIFO, a link to one) until killed. Its
// images are checked as scene files are: a regular file, before anything is read.
TEST_F(CliHostileInput, CompareRefusesDevicesAndFifosAtOnce) {
  fs::create_directories(in_dir());
  const fs::path good = input("good.ppm", std::string("P6\n2 1\n255\n") + std::string(6, '\x40'));
  fs::create_symlink("/dev/urandom", in_dir() / "noise.png");
  ASSERT_EQ(::mkfifo((in_dir() / "pipe.png").c_str(), 0600), 0);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/dev/zero", "character device"}, {(in_dir() / "noise.png").string(), "character device"},
      {(in_dir() / "pipe.png").string(), "FIFO"}};
  for (const auto& [path, kind] : cases) {
    for (const bool as_reference : {true, false}) {
      const std::vector<std::string> args = as_reference ? std::vector<std::string>{"compare", good.string(), path}
                                                         : std::vector<std::string>{"compare", path, good.string()};
      const RunResult r = run_parashade(args, {}, std::chrono::seconds(10));
      EXPECT_TRUE(fails_with(r, kBadInput, {fs::path(path).filename().string(), "not a regular file", kind}));
    }
  }
}

// Item 9: --triangle-choice list:/dev/zero grew without bound (4.2 GB in 20 s); a FIFO hung.
TEST_F(CliHostileInput, TriangleListFromADeviceOrAFifoIsRefusedAtOnce) {
  fs::create_directories(in_dir());
  const fs::path scene = input("ball.json", sphere_scene());
  ASSERT_EQ(::mkfifo((in_dir() / "pipe.txt").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", in_dir() / "zeros.txt");
  for (const std::string list : {std::string("/dev/zero"), (in_dir() / "pipe.txt").string(), (in_dir() / "zeros.txt").string()}) {
    const RunResult r = run_parashade(
        render_args(scene, {"--method", "combined:0", "--triangle-choice", "list:" + list}), {}, std::chrono::seconds(10));
    EXPECT_TRUE(fails_with(r, kBadInput, {fs::path(list).filename().string(), "not a regular file"}));
  }
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
