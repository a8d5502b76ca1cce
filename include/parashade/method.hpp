#pragma once
// Shading methods: what is computed per pixel.
#include <string>

namespace parashade {

enum class Method {
  flat,     // one Blinn–Phong value per triangle (centroid, face normal)
  gouraud,  // Blinn–Phong at vertices; linear interpolation with the constant span increment
  phong,    // per-pixel interpolated, normalized normals; Blinn–Phong per pixel
  combined, // Phong at the ends of 2^k-pixel segments, linear inside (combined.hpp; "combined:K|auto")
};

Method parse_method(const std::string& name);  // throws UsageError listing the valid names
const char* method_name(Method m);

}  // namespace parashade
