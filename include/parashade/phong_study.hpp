#pragma once
// The Phong-family study (`parashade phong-study`; docs/phong-methods.md, docs/phong-study.md): every
// normalization method, approximation and specular model of [Dembitsky 2025, software/hardware rendering] ch. 2–3 measured against
// double-precision exact values, each numeric claim of the sources with its measured figure and a
// verdict. Deterministic: no random draws.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace parashade {

struct PhongStudy {
  nlohmann::json report;              // every measurement and the claims (id, source figure, measured, verdict)
  std::string markdown;               // the tables and the claims table
  std::uint64_t nonfinite_spans = 0;  // spans a method left with non-finite normals: the study failed
};

PhongStudy phong_study();

}  // namespace parashade
