#include "parashade/memory_budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "parashade/errors.hpp"

namespace parashade {
namespace {

constexpr const char* kVariable = "PARASHADE_MEMORY_LIMIT";

std::string bytes_text(std::uint64_t bytes) {
  char buf[64];
  if (bytes >= (1ull << 30))
    std::snprintf(buf, sizeof buf, "%.1f GiB", double(bytes) / double(1ull << 30));
  else
    std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / double(1ull << 20));
  return buf;
}

std::uint64_t physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : 0;
}

std::uint64_t item_bytes(const MemoryItem& o) {
  return o.triangles * kHostBytesPerTriangle + o.vertices * kHostBytesPerVertex;
}

}  // namespace

std::uint64_t estimate_host_bytes(const std::vector<MemoryItem>& objects, int width, int height,
                                  std::uint64_t extra_bytes_per_pixel) {
  std::uint64_t total = std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0)) *
                        (kHostBytesPerPixel + extra_bytes_per_pixel);
  for (const MemoryItem& o : objects) total += item_bytes(o);
  return total;
}

std::uint64_t host_memory_limit() {
  if (const char* text = std::getenv(kVariable); text && *text) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    double scale = 1;
    if (*end) {
      switch (std::toupper(static_cast<unsigned char>(*end))) {
        case 'K': scale = 1024.0; break;
        case 'M': scale = 1024.0 * 1024; break;
        case 'G': scale = 1024.0 * 1024 * 1024; break;
        case 'T': scale = 1024.0 * 1024 * 1024 * 1024; break;
        default: scale = 0;
      }
      ++end;
    }
    if (end == text || *end || !(scale > 0) || !(value > 0) || !(value * scale < 1.8e19))
      throw UsageError(std::string(kVariable) + "='" + text + "' is not a size: bytes, or a number with K, M, G or T (16G; "
                       "unset it for the default, half of the physical memory)");
    return std::uint64_t(value * scale);
  }
  const std::uint64_t physical = physical_memory();
  return physical ? physical / 2 : std::uint64_t(4) << 30;
}

std::string host_memory_limit_source() {
  if (const char* text = std::getenv(kVariable); text && *text) return std::string("set by ") + kVariable;
  return "half of the physical memory; " + std::string(kVariable) + " changes it, e.g. " + kVariable + "=16G";
}

void check_host_bytes(const std::string& what, std::uint64_t bytes, const std::string& holding) {
  const std::uint64_t limit = host_memory_limit();
  if (bytes <= limit) return;
  throw InputError(what + ": " + holding + " would take about " + bytes_text(bytes) + " of host memory, more than the limit of " +
                   bytes_text(limit) + " (" + host_memory_limit_source() + ")");
}

void check_host_memory(const std::string& what, const std::vector<MemoryItem>& objects, int width, int height,
                       const FrameExtras& extras) {
  const std::uint64_t need = estimate_host_bytes(objects, width, height, extras.bytes_per_pixel) + extras.bytes;
  const std::uint64_t limit = host_memory_limit();
  if (need <= limit) return;
  std::uint64_t triangles = 0;
  for (const MemoryItem& o : objects) triangles += o.triangles;
  std::vector<const MemoryItem*> largest;
  for (const MemoryItem& o : objects) largest.push_back(&o);
  std::stable_sort(largest.begin(), largest.end(),
                   [](const MemoryItem* a, const MemoryItem* b) { return item_bytes(*a) > item_bytes(*b); });
  std::string list;
  for (std::size_t i = 0; i < largest.size() && i < 3; ++i)
    list += (i ? ", " : "") + largest[i]->name + " (" + std::to_string(largest[i]->triangles) + " triangles, about " +
            bytes_text(item_bytes(*largest[i])) + ")";
  if (largest.size() > 3) list += " and " + std::to_string(largest.size() - 3) + " more";
  throw InputError(what + ": rendering needs about " + bytes_text(need) + " of host memory (" +
                   std::to_string(objects.size()) + (objects.size() == 1 ? " object, " : " objects, ") + std::to_string(triangles) + " triangles, a " +
                   std::to_string(width) + "x" + std::to_string(height) + " frame" +
                   (extras.options.empty() ? "" : " with " + extras.options) +
                   (extras.records ? ", its triangle records " + bytes_text(extras.records) + " at once (--band-mib)" : "") +
                   "), more than the limit of " +
                   bytes_text(limit) + " (" + host_memory_limit_source() + "); largest objects: " + list);
}

}  // namespace parashade
