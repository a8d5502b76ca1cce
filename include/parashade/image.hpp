#pragma once
// A rendered frame on the host, and writing/reading images through OpenImageIO.
#include <cstdint>
#include <filesystem>
#include <new>
#include <vector>

#include <glm/glm.hpp>

namespace parashade {

// Page-aligned storage, so an OpenCL device can write a frame straight into it (CL_MEM_USE_HOST_PTR).
template <class T>
struct PageAlignedAllocator {
  using value_type = T;
  static constexpr std::align_val_t alignment{4096};
  PageAlignedAllocator() = default;
  template <class U>
  PageAlignedAllocator(const PageAlignedAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), alignment)); }
  void deallocate(T* p, std::size_t) { ::operator delete(p, alignment); }
  template <class U>
  bool operator==(const PageAlignedAllocator<U>&) const { return true; }
  template <class U>
  bool operator!=(const PageAlignedAllocator<U>&) const { return false; }
};

struct RenderedImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t, PageAlignedAllocator<std::uint8_t>> rgba;  // 8-bit RGBA, row 0 at the top; alpha 255 where covered, 0 elsewhere
  std::vector<float> rgb_float;       // optional: unclamped RGB in 8-bit levels (empty when not rendered)
  bool covered(std::size_t pixel) const { return rgba[4 * pixel + 3] != 0; }
};

// Writes RGB without alpha (format from the extension: png, jpg, tif, ppm, bmp, exr ...), 8-bit except
// EXR, which gets 32-bit float values in [0,1]-scale (levels / 255) from rgb_float when present, else
// from the 8-bit image. The file appears whole or not at all (written to a temporary file in the same
// directory, then renamed).
// Throws InputError for an unknown extension or an unwritable path.
void write_image(const std::filesystem::path& path, const RenderedImage& image);

// Throws the InputError write_image would throw for `path` itself (no such directory, a directory, no
// or an unknown extension), so a caller can refuse a destination before the work that fills it.
void check_image_destination(const std::filesystem::path& path);

// Reads an image as 8-bit RGBA (alpha 255 where the file has none; grey files give R = G = B). Float
// files (EXR) also fill rgb_float with their values in levels (x255). `channels`, when given, receives
// the file's channel count. Throws InputError.
RenderedImage read_image(const std::filesystem::path& path, int* channels = nullptr);

// An image of values in levels (row 0 at the top; alpha 255): 8-bit channels rounded to the nearest
// level after clamping to [0, 255], and rgb_float holding the values themselves (EXR writes them).
// Throws InputError when `levels` does not hold width x height values.
RenderedImage levels_image(const std::vector<glm::dvec3>& levels, int width, int height);

// An ID buffer: each pixel's visible triangle (`triangle`: an index per pixel, -1 where none, as
// ReferenceImage::triangle) plus one in 24 bits, R the high byte and B the low, 0 where none; alpha 255.
// Lossless only in lossless formats (triangle_map_destination checks). Throws InputError when `triangle`
// does not hold width x height indices or an index does not fit in 24 bits.
RenderedImage triangle_map_image(const std::vector<std::int32_t>& triangle, int width, int height);

// Throws InputError unless `path` names a format that keeps 8-bit channels exactly (png, tif, tiff, ppm):
// a lossy one would change the triangles' numbers.
void check_triangle_map_destination(const std::filesystem::path& path);

}  // namespace parashade
