// The host memory a render's frame takes beyond the scene's own budget (frame_memory.hpp).
#include "frame_memory.hpp"

#include <algorithm>

#include "parashade/flip.hpp"
#include "parashade/frame_pipeline.hpp"

namespace parashade {
namespace {

// Host bytes a pixel of what a render keeps beyond the frame it shades, rounded up from the peak resident
// memory of 4096x4096 Phong frames with and without each option (+35, +7, +3.3 and +0.5; docs/robustness.md).
// FLIP: its two float RGB inputs and its map (24 + 4); its bands of rows are counted apart (ldr_flip_working_bytes).
// --against / --against-device: a second renderer's frame buffers (4096x4096 sphere, Gouraud and Phong: +70 and
// +73 MiB, 4.4-4.6 bytes a pixel, with a second context on the same device), and its own records.
constexpr std::uint64_t kFloatBytesPerPixel = 40, kReferenceImageBytesPerPixel = 8, kErrorMapBytesPerPixel = 8,
                        kTriangleMapBytesPerPixel = 4, kFlipBytesPerPixel = 28, kFlipMapBytesPerPixel = 4,
                        kSecondRendererBytesPerPixel = 8;

// The triangle records (setup's output, one buffer the kernels read) the frame holds at once: every
// triangle's, unless the frame may stream (frame_can_stream) and they exceed its records budget, when a
// band's, at most that budget (record_budget). The scene's triangles bound the screen's. The per-triangle
// estimate (memory_budget.hpp) was measured on streamed frames of 16 MiB bands: 2 M unculled Phong triangles
// at 1920x1080 peaked 294 MiB higher with --band-mib 0 (all their records), over the estimate by 54 MiB.
std::uint64_t held_record_bytes(const RenderOptions& o, int width, int height, std::uint64_t triangles) {
  const std::uint64_t all = triangles * triangle_record_bytes(o.method);
  if (!frame_can_stream(o)) return all;
  const RecordBudget budget = record_budget(o.band_record_bytes, width, height);
  return all > budget.stream_above ? std::min<std::uint64_t>(all, budget.band) : all;
}

}  // namespace

FrameExtras frame_extras(const RenderRequest& request, int width, int height, std::uint64_t triangles) {
  FrameExtras x;
  const auto add = [&x](const std::string& option, std::uint64_t bytes) {
    x.bytes_per_pixel += bytes;
    x.options += (x.options.empty() ? "" : ", ") + option;
  };
  if (request.options.float_output) add("--float", kFloatBytesPerPixel);
  if (request.flip.enabled) {
    add("--flip", kFlipBytesPerPixel);
    x.bytes += ldr_flip_working_bytes(width, height);
  }
  for (const std::string& p : request.pictures)
    add(p, p == "--reference-image" ? kReferenceImageBytesPerPixel
           : p == "--error-map"     ? kErrorMapBytesPerPixel
           : p == "--flip-map"      ? kFlipMapBytesPerPixel
                                    : kTriangleMapBytesPerPixel);
  x.records = held_record_bytes(request.options, width, height, triangles);
  x.bytes += x.records;
  if (request.against || !request.against_device.empty()) {
    add(request.against ? "--against" : "--against-device", kSecondRendererBytesPerPixel);
    RenderOptions second = request.options;
    if (request.against) second.method = *request.against;
    x.bytes += held_record_bytes(second, width, height, triangles);
  }
  return x;
}

void check_frame_memory(const Scene& scene, const RenderRequest& request) {
  std::vector<MemoryItem> objects;
  std::uint64_t triangles = 0;
  for (const Object& o : scene.objects)
    if (o.mesh) {
      objects.push_back({"'" + o.name + "'", o.mesh->triangles.size(), o.mesh->positions.size()});
      triangles += o.mesh->triangles.size();
    }
  check_host_memory(request.scene_file.string() + " at " + std::to_string(scene.width) + "x" + std::to_string(scene.height),
                    objects, scene.width, scene.height, frame_extras(request, scene.width, scene.height, triangles));
}

}  // namespace parashade
