#pragma once
// What makes a JSON report self-describing (docs/reports.md; schemas/): which schema it follows, which
// build wrote it, when, from which command line, and how loaded the host was. Every report the CLI
// writes starts from stamp_report; timed runs add timing_json. Device-free: the device goes in as JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parashade {

// The command line a report names; main records it once (argv as given).
void set_report_command_line(int argc, const char* const* argv);
const std::vector<std::string>& report_command_line();

// The format version every report kind carries (docs/reports.md): raised, for all kinds at once, when a key
// is renamed, removed or changes meaning. 2: one name per quantity (CHANGELOG).
constexpr int kReportVersion = 2;

// Adds the header to `report`: "schema": "parashade.<kind>/<version>", "parashade": {version, git_hash, dirty},
// "created_utc" (ISO 8601), "command_line" (array), "host": {"load_1min"} (null where /proc/loadavg is
// unreadable). Keys the body already has are not overwritten (a body may not take a header key).
nlohmann::json& stamp_report(nlohmann::json& report, const std::string& kind, int version = kReportVersion);
// `body` stamped as parashade.<kind>/<kReportVersion>, as the text a report file holds.
std::string report_text(nlohmann::json body, const std::string& kind);

// Now, UTC, as 2026-12-02T22:10:00Z (the header's created_utc).
std::string utc_now_iso8601();

// Timed frames: {"frames", "warmup", "samples_ms", "min_ms", "median_ms", "mean_ms", "stddev_ms"}
// (standard deviation of the samples, n - 1 in the denominator; 0 for one sample).
nlohmann::json timing_json(const std::vector<double>& samples_ms, int warmup);

// Every report's frame_ms_note, in one wording: "median of <frames> <what> after <warmup> warm-up
// frame(s)<how>" (what: "frames", "split frames", "frames per configuration"; how: what the clock spans).
std::string frame_ms_note(int frames, int warmup, const std::string& what, const std::string& how);
// How a whole frame of one device is timed (the stages frame_ms adds up).
extern const char* const kWholeFrame;

// The one-minute load average from /proc/loadavg; negative when unreadable.
double host_load_1min();

}  // namespace parashade
