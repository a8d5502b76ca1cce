#pragma once
// A figure in a JSON report: the number, or null where it is not finite (JSON has no inf or nan).
// Device-free, so the studies (host/studies) and the renderer's reports write figures alike.
#include <cmath>

#include <nlohmann/json.hpp>

namespace parashade {

inline nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace parashade
