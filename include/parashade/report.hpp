#pragma once
// JSON forms of what a run measured, shared by the CLI and the benchmarks. Non-finite numbers
// (an identical image has PSNR +inf) become null.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "parashade/device.hpp"
#include "parashade/json_number.hpp"
#include "parashade/metrics.hpp"
#include "parashade/renderer.hpp"

namespace parashade {

nlohmann::json to_json(const DeviceInfo& d);
nlohmann::json to_json(const ErrorMetrics& m);
nlohmann::json to_json(const FrameTimings& t);
nlohmann::json to_json(const FrameStats& s);
nlohmann::json to_json(const ModeledClocks& c);
nlohmann::json to_json(const PlanReport& r);  // per-unit load, frame clocks, imbalance
// With a plan: how the units' depth pass was mapped (U work-items of one device, or which sub-device ran
// which units and packets) and each share's measured pass time, from `t` (medians or one frame).
nlohmann::json unit_mapping_json(const FrameStats& s, const FrameTimings& t);

// Writes text to `path` whole or not at all (temporary file in the same directory, then rename).
// Throws InputError naming the path.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace parashade
