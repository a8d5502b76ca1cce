#pragma once
// A host memory budget across a scene's objects and its frame, checked before anything large is
// allocated (docs/robustness.md): a small scene file may ask for many maximal shapes.
#include <cstdint>
#include <string>
#include <vector>

namespace parashade {

// What one object will cost: its triangles and vertices.
struct MemoryItem {
  std::string name;  // "object 3 (sphere)"
  std::uint64_t triangles = 0, vertices = 0;
};

// Bytes of host memory a render takes, measured (docs/robustness.md): per triangle and vertex of the
// scene through the mesh, the vertex stage, setup, binning and the reference, and per pixel of the frame.
constexpr std::uint64_t kHostBytesPerTriangle = 400, kHostBytesPerVertex = 48, kHostBytesPerPixel = 96;

// What a render keeps beyond the frame it shades: per pixel (--float's values, FLIP's, the pictures of the
// error), and whatever the frame's size (`bytes`: FLIP's bands of rows, and the triangle records it holds at
// once, `records`, of them); the options that ask for them ("--float, --error-map") for messages.
struct FrameExtras {
  std::uint64_t bytes_per_pixel = 0;
  std::uint64_t bytes = 0, records = 0;
  std::string options;
};

std::uint64_t estimate_host_bytes(const std::vector<MemoryItem>& objects, int width, int height,
                                  std::uint64_t extra_bytes_per_pixel = 0);

// The limit: PARASHADE_MEMORY_LIMIT (bytes, or with a suffix K, M, G, T: powers of 1024) when set, else
// half of the physical memory (sysconf). A malformed PARASHADE_MEMORY_LIMIT is an InputError.
std::uint64_t host_memory_limit();
// Where the limit came from, for messages.
std::string host_memory_limit_source();

// Throws InputError "<what>: <holding> would take about X of host memory, more than the limit of Y (...)" when
// `bytes` exceed the limit: one allocation sized by a file's header (an image, a mesh's counts).
void check_host_bytes(const std::string& what, std::uint64_t bytes, const std::string& holding);

// Throws InputError "<what>: rendering needs about X of host memory (...), more than the limit of Y
// (...); largest objects: ..." when the estimate exceeds the limit.
void check_host_memory(const std::string& what, const std::vector<MemoryItem>& objects, int width, int height,
                       const FrameExtras& extras = {});

}  // namespace parashade
