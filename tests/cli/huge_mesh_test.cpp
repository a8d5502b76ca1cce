// Issue 46, items 12 and 13: a mesh or a frame too large for the host memory limit is refused from its
// counts and sizes, before the memory is taken. Each case measures the child's peak resident memory
// (getrusage) and its time: before the fixes a 3.9 GB sparse OBJ with a NUL on line 5 took 27 s and 4.2 GB
// before its refusal, an OBJ of millions of triangles was loaded whole before the budget refused it, and a
// binary PLY declaring hundreds of millions of vertices was read into memory.
#include <chrono>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

constexpr long kRefusalPeakKib = 200 << 10;  // 200 MiB: the process and its libraries, no geometry
// Under AddressSanitizer a peak says little of the program: its quarantine keeps up to 256 MiB of freed memory
// and its shadow an eighth more (a refused OBJ peaked at 683 MiB under scripts/sanitize.sh, under 200 MiB
// without). The peaks are checked by the plain build's run of these tests.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kPeaksMeasured = false;
#else
constexpr bool kPeaksMeasured = true;
#endif

class CliHugeMesh : public CliTest {
 protected:
  // render of a bare mesh, timed.
  RunResult render_mesh(const fs::path& mesh, std::vector<std::string> extra = {}) {
    const auto t0 = std::chrono::steady_clock::now();
    const RunResult r = run_parashade(render_args(mesh, std::move(extra)), {}, std::chrono::seconds(120));
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }
  double seconds_ = 0;
};

// The OBJ scan read line 5 (3.9 GB of NUL bytes) whole before looking at it: lines are read in bounded
// pieces and the NUL byte is refused in the first.
TEST_F(CliHugeMesh, ASparseObjWithANulIsRefusedAtOnce) {
  const fs::path mesh = input("sparse.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  fs::resize_file(mesh, (4ull << 30) - 1);  // sparse: no disk used
  const RunResult r = render_mesh(mesh);
  EXPECT_TRUE(fails_with(r, kBadInput, {"sparse.obj:5", "NUL"}));
  EXPECT_LT(seconds_, 5.0);
  if (kPeaksMeasured) EXPECT_LT(r.max_rss_kib, kRefusalPeakKib) << r;
  EXPECT_TRUE(nothing_written());
}

// 2 M triangles (about 40 MB of text) against a 300 MiB limit: the scan's counts are budgeted before
// OpenMesh reads the file.
TEST_F(CliHugeMesh, AnObjBeyondTheMemoryLimitIsRefusedFromItsCounts) {
  const fs::path mesh = in_dir() / "grid.obj";
  fs::create_directories(in_dir());
  {
    std::ofstream out(mesh);
    constexpr int n = 1000;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) out << "v " << x << ' ' << y << " 0\n";
    for (int y = 0; y + 1 < n; ++y)
      for (int x = 0; x + 1 < n; ++x) {
        const int a = y * n + x + 1;
        out << "f " << a << ' ' << a + 1 << ' ' << a + n << "\nf " << a + 1 << ' ' << a + n + 1 << ' ' << a + n << '\n';
      }
  }
  const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "300M");
  const RunResult r = render_mesh(mesh);
  EXPECT_TRUE(fails_with(r, kBadInput, {"grid.obj", "1996002 triangles", "limit"}));
  if (kPeaksMeasured) EXPECT_LT(r.max_rss_kib, kRefusalPeakKib) << r;
  EXPECT_TRUE(nothing_written());
}

// A binary PLY whose header declares 40 M vertices, and whose (sparse) body holds them: the counts fit the
// file, so only the budget can refuse it, from the header.
TEST_F(CliHugeMesh, ABinaryPlyDeclaringMoreVerticesThanTheLimitIsRefusedFromItsHeader) {
  constexpr std::uint64_t vertices = 40'000'000;
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const fs::path mesh = input("many.ply", header);
  const std::uint64_t body = vertices * 12;
  fs::resize_file(mesh, header.size() + body);
  {
    std::ofstream out(mesh, std::ios::in | std::ios::out | std::ios::binary);
    out.seekp(std::streamoff(header.size() + body));
    const char face[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
    out.write(face, sizeof face);
  }
  const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "1G");
  const RunResult r = render_mesh(mesh);
  EXPECT_TRUE(fails_with(r, kBadInput, {"many.ply", "40000000 vertices", "limit"}));
  if (kPeaksMeasured) EXPECT_LT(r.max_rss_kib, kRefusalPeakKib) << r;
  EXPECT_TRUE(nothing_written());
}

// Item 13: --float, --reference-image, --error-map and --triangle-map hold whole frames of their own; the
// estimate left them out (4096x4096 Phong: estimated 1.5 GiB, peak 1.96 GB). A limit the plain frame fits
// refuses the frame with all four, naming them.
TEST_F(CliHugeMesh, TheFrameEstimateCountsTheExtraPictures) {
  const fs::path scene = input("ball.json", sphere_scene());
  const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "1700M");
  std::vector<std::string> args =
      render_args(scene, {"--size", "4096x4096", "--method", "phong", "--float", "--reference-image",
                          (out_dir() / "ref.exr").string(), "--error-map", (out_dir() / "map.png").string(),
                          "--triangle-map", (out_dir() / "ids.png").string()},
                  ErrorFigures::compute);
  args[3] = (out_dir() / "f.exr").string();
  const RunResult r = run_parashade(args, {}, std::chrono::seconds(120));
  EXPECT_TRUE(fails_with(r, kBadInput, {"ball.json at 4096x4096", "limit", "--float", "--reference-image", "--error-map",
                                        "--triangle-map"}));
  EXPECT_TRUE(nothing_written());
}

// FLIP's bands of rows were left out of the estimate: with 64 host threads a 4096x1024 frame has 32 bands of
// 32 rows in flight at once, 553 MB beside FLIP's 28 bytes a pixel (compare --flip of two such images: 632 MiB
// over the plain compare's peak, 639 MiB estimated; one thread: 198 and 199). A limit that the frame with
// FLIP's per-pixel values fits (520 MB) refuses the frame with its bands (1.07 GB). Before: rendered.
TEST_F(CliHugeMesh, TheFrameEstimateCountsFlipsBands) {
  const fs::path scene = input("ball.json", sphere_scene());
  const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "800M");
  const ScopedEnv threads("PARASHADE_HOST_THREADS", "64");
  const RunResult r = run_parashade(render_args(scene, {"--size", "4096x1024", "--flip"}, ErrorFigures::compute), {},
                                    std::chrono::seconds(120));
  EXPECT_TRUE(fails_with(r, kBadInput, {"ball.json at 4096x1024", "limit", "with --flip"}));
  EXPECT_TRUE(nothing_written());
}

// A frame that does not stream (--band-mib 0) holds every triangle's record at once; the per-triangle
// estimate was measured on frames streamed in 16 MiB bands (2 M unculled Phong triangles at 1920x1080: 294
// MiB more with --band-mib 0, 54 MiB over the estimate). 524 288 Phong records (84 MB) take a 640x480 frame
// past a limit of 300 MiB (estimated 336 MB; streamed in the default bands, 269 MB). Before: rendered.
TEST_F(CliHugeMesh, TheFrameEstimateCountsTheRecordsOfAFrameThatDoesNotStream) {
  const fs::path scene = input("ball.json", R"({
  "name": "ball", "resolution": [640, 480],
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov": 40, "near": 1, "far": 10},
  "lights": [{"type": "directional", "direction": [0, 0, -1]}],
  "objects": [{"shape": {"type": "sphere", "slices": 512, "stacks": 513}}]
})");
  const ScopedEnv limit("PARASHADE_MEMORY_LIMIT", "300M");
  const RunResult r = render_mesh(scene, {"--method", "phong", "--band-mib", "0"});
  EXPECT_TRUE(fails_with(r, kBadInput, {"ball.json at 640x480", "limit", "triangle records", "--band-mib"}));
  EXPECT_LT(seconds_, 10.0);
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
