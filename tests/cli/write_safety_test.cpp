// Issue 17, A: nothing is ever lost on write. A failed write keeps the previous files (item 1), outputs
// that are the same file as another output or an input are refused before rendering (item 2), a signal
// during a write leaves no temporary file (item 3), and a replaced file keeps its permission bits (4).
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

std::string bytes_of(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p, std::ios::binary).rdbuf();
  return s.str();
}

mode_t mode_of(const fs::path& p) {
  struct stat st {};
  ::stat(p.c_str(), &st);
  return st.st_mode & 07777;
}

// A started parashade whose stderr goes to a file; `file_size_limit` (RLIMIT_FSIZE, SIGXFSZ ignored)
// makes a write past it fail with EFBIG as a full disk fails with ENOSPC.
struct Child {
  pid_t pid = -1;
  fs::path err_file;
  std::string err() const { return bytes_of(err_file); }
  // Waits; the exit code, or -signal.
  int wait() const {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  }
};

Child start(const std::vector<std::string>& args, const fs::path& err_file, rlim_t file_size_limit = RLIM_INFINITY) {
  std::vector<std::string> text = {parashade_binary().string()};
  text.insert(text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : text) argv.push_back(a.data());
  argv.push_back(nullptr);
  Child c;
  c.err_file = err_file;
  c.pid = ::fork();
  if (c.pid == 0) {
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int null = ::open("/dev/null", O_WRONLY);
    if (err < 0 || null < 0 || ::dup2(null, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
    if (file_size_limit != RLIM_INFINITY) {
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit rl{file_size_limit, file_size_limit};
      if (::setrlimit(RLIMIT_FSIZE, &rl) != 0) ::_exit(126);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return c;
}

class CliWriteSafety : public CliTest {
 protected:
  std::vector<std::string> args(const fs::path& image_path, const fs::path& report_path, std::vector<std::string> extra) {
    std::vector<std::string> a = {"render", scene_.string(), "-o", image_path.string(), "--frames", "1", "--warmup", "0",
                                  "-q", "--no-error"};
    if (!report_path.empty()) a.insert(a.end(), {"--report", report_path.string()});
    const std::vector<std::string> device = device_args();
    a.insert(a.end(), device.begin(), device.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }
  fs::path err_file() const { return dir_.path() / "stderr.txt"; }

  fs::path scene_ = input("ball.json", sphere_scene());
};

// Item 1: on a full disk (here: a file size limit of 1 MiB; PoCL's compiler writes files of a few
// hundred KiB on every run) a large image fails part-way: a 2048x2048 image of 12 MiB (uncompressed
// formats: the small scene's PNG or JPEG would fit; test_core covers those with random pixels). The
// previous image and report stay, nothing else is left, the exit code is 3 and the message names the
// file and the system's error.
class CliFullDisk : public CliWriteSafety, public ::testing::WithParamInterface<std::string> {};

TEST_P(CliFullDisk, FailedWriteKeepsThePreviousImageAndReport) {
  const fs::path image_path = out_dir() / ("image." + GetParam());
  // The first run writes the good files (and warms the kernel cache).
  ASSERT_TRUE(succeeds(run_parashade(args(image_path, report(), {}))));
  const std::string image_before = bytes_of(image_path), report_before = bytes_of(report());
  const Child c = start(args(image_path, report(), {"--size", "2048x2048"}), err_file(), 1 << 20);
  const int code = c.wait();
  const std::string err = c.err();
  EXPECT_EQ(code, kBadInput) << err;
  EXPECT_NE(err.find(image_path.string()), std::string::npos) << err;
  EXPECT_NE(err.find(std::strerror(EFBIG)), std::string::npos) << err;
  EXPECT_EQ(bytes_of(image_path), image_before);
  EXPECT_EQ(bytes_of(report()), report_before);
  EXPECT_EQ(out_entries(), (std::vector<std::string>{image_path.filename().string(), "report.json"}));
}

INSTANTIATE_TEST_SUITE_P(Formats, CliFullDisk, ::testing::Values("bmp", "tga", "ppm"), StringParamName());

// Item 1: a report that cannot be written (here: its folder takes no new file, even for root) fails
// after the image was written; the previous image must stay (it used to be replaced, then removed).
TEST_F(CliWriteSafety, FailedReportKeepsThePreviousImage) {
  ASSERT_TRUE(succeeds(run_parashade(args(image(), report(), {}))));
  const std::string image_before = bytes_of(image());
  const RunResult r = run_parashade(args(image(), "/proc/parashade-report.json", {"--size", "32x24"}));
  EXPECT_TRUE(fails_with(r, kBadInput, {"/proc/parashade-report.json"}));
  EXPECT_EQ(bytes_of(image()), image_before);
  EXPECT_EQ(out_entries(), (std::vector<std::string>{"image.png", "report.json"}));
}

// Item 2: outputs that are the same file as another output or an input are refused before rendering
// (usage error), compared as files: through "..", a symbolic link, a hard link.
TEST_F(CliWriteSafety, ImageAndReportOnOneFileAreRefused) {
  const RunResult r = run_parashade(args(image(), out_dir() / "sub" / ".." / "image.png", {}));
  EXPECT_TRUE(fails_with(r, kUsage, {"-o", "--report", "same file"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliWriteSafety, ReportOverTheSceneIsRefused) {
  const std::string scene_before = bytes_of(scene_);
  EXPECT_TRUE(fails_with(run_parashade(args(image(), scene_, {})), kUsage, {"--report", "input file"}));
  fs::create_symlink(scene_, out_dir() / "link.json");
  EXPECT_TRUE(fails_with(run_parashade(args(image(), out_dir() / "link.json", {})), kUsage, {"input file"}));
  fs::create_hard_link(scene_, in_dir() / "hard.json");
  EXPECT_TRUE(fails_with(run_parashade(args(image(), in_dir() / "hard.json", {})), kUsage, {"input file"}));
  EXPECT_EQ(bytes_of(scene_), scene_before);
  EXPECT_EQ(std::distance(fs::directory_iterator(out_dir()), fs::directory_iterator()), 1);  // the link alone
}

TEST_F(CliWriteSafety, OutputOverAMeshOfTheSceneIsRefused) {
  const fs::path mesh = input("tetra.obj", tetrahedron_obj());
  const fs::path scene = input("tetra.json", R"({"objects": [{"mesh": "tetra.obj"}]})");
  std::vector<std::string> a = args(image(), mesh, {});
  a[1] = scene.string();
  EXPECT_TRUE(fails_with(run_parashade(a), kUsage, {"--report", "tetra.obj", "input file"}));
  EXPECT_EQ(bytes_of(mesh), tetrahedron_obj());
  EXPECT_TRUE(nothing_written());
}

// Item 3: SIGTERM or SIGINT while the image is written leaves no temporary file and exits 128 + signal.
// A 4096x4096 EXR takes long enough to write (about a second here) that the signal lands while the
// temporary file is there (the test waits for it to appear).
class CliSignal : public CliWriteSafety, public ::testing::WithParamInterface<int> {};

TEST_P(CliSignal, DuringTheWriteLeavesNoTemporaryFile) {
  const fs::path image_path = out_dir() / "image.exr";
  ASSERT_TRUE(succeeds(run_parashade(args(image_path, {}, {"--size", "16x16"}))));  // warm kernel cache
  fs::remove(image_path);
  const Child c = start(args(image_path, {}, {"--size", "4096x4096"}), err_file());
  bool seen = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!seen && std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;  // entries may vanish while listed
    for (fs::directory_iterator it(out_dir(), ec), end; !ec && it != end; it.increment(ec))
      seen = seen || it->path().filename().string().find(".tmp-") != std::string::npos;
    int status = 0;
    if (!seen && ::waitpid(c.pid, &status, WNOHANG) == c.pid) FAIL() << "the render ended before its write was seen";
    if (!seen) std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  ASSERT_TRUE(seen) << "no temporary file appeared";
  ::kill(c.pid, GetParam());
  EXPECT_EQ(c.wait(), 128 + GetParam()) << c.err();
  EXPECT_TRUE(nothing_written());
}

// Issue 46: SIGQUIT and SIGUSR1 were swallowed once PoCL's LLVM had compiled a kernel (its handlers
// replaced the defaults) and the render completed; SIGHUP and SIGUSR2 are handled the same way.
INSTANTIATE_TEST_SUITE_P(Signals, CliSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2),
                         [](const ::testing::TestParamInfo<int>& i) { return std::string("SIG") + sigabbrev_np(i.param); });

// Issue 46: a legal name of 250 bytes: the temporary file beside it (".NAME.tmp-PID-N.png") was longer than 255.
TEST_F(CliWriteSafety, ALongButLegalOutputNameIsWritten) {
  const fs::path long_image = out_dir() / (std::string(246, 'a') + ".png");
  const fs::path long_report = out_dir() / (std::string(245, 'r') + ".json");
  EXPECT_TRUE(succeeds(run_parashade(args(long_image, long_report, {}))));
  EXPECT_TRUE(fs::is_regular_file(long_image));
  EXPECT_TRUE(fs::is_regular_file(long_report));
}

// Item 4: replaced outputs keep their permission bits.
TEST_F(CliWriteSafety, ReplacedOutputsKeepTheirPermissionBits) {
  ASSERT_TRUE(succeeds(run_parashade(args(image(), report(), {}))));
  ::chmod(image().c_str(), 0444);
  ::chmod(report().c_str(), 0600);
  ASSERT_TRUE(succeeds(run_parashade(args(image(), report(), {}))));
  EXPECT_EQ(mode_of(image()), 0444u);
  EXPECT_EQ(mode_of(report()), 0600u);
}

}  // namespace
}  // namespace parashade
