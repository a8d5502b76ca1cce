#include "parashade/report_header.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <numeric>

#include "parashade/version.hpp"
#include "parashade/errors.hpp"
#include "parashade/json_number.hpp"
#include "parashade/statistics.hpp"

namespace parashade {
namespace {

std::vector<std::string>& command_line() {
  static std::vector<std::string> args;
  return args;
}

// The build: the commit as a bare hash, and whether the working tree had uncommitted changes beside it
// (git_hash.cmake appends "-dirty"), so that a reader never has to parse the hash.
nlohmann::json build_json() {
  const std::string hash = parashade::git_hash, suffix = "-dirty";
  const bool dirty = hash.size() > suffix.size() && hash.compare(hash.size() - suffix.size(), suffix.size(), suffix) == 0;
  return {{"version", parashade::version},
          {"git_hash", dirty ? hash.substr(0, hash.size() - suffix.size()) : hash},
          {"dirty", dirty}};
}

}  // namespace

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

void set_report_command_line(int argc, const char* const* argv) {
  command_line().assign(argv, argv + argc);
}

const std::vector<std::string>& report_command_line() { return command_line(); }

double host_load_1min() {
  std::ifstream in("/proc/loadavg");
  double load = -1.0;
  if (!(in >> load)) return -1.0;
  return load;
}

nlohmann::json& stamp_report(nlohmann::json& report, const std::string& kind, int version) {
  if (!report.is_object()) throw std::logic_error("stamp_report: a report is a JSON object");
  const double load = host_load_1min();
  const nlohmann::json header = {
      {"schema", "parashade." + kind + "/" + std::to_string(version)},
      {"parashade", build_json()},
      {"created_utc", utc_now_iso8601()},
      {"command_line", report_command_line()},
      {"host", {{"load_1min", load >= 0 ? nlohmann::json(load) : nlohmann::json(nullptr)}}}};
  for (const auto& [key, value] : header.items())
    if (report.contains(key)) throw std::logic_error("stamp_report: the body has a header key '" + key + "'");
  report.update(header);
  return report;
}

nlohmann::json timing_json(const std::vector<double>& samples_ms, int warmup) {
  const std::size_t n = samples_ms.size();
  double mean = 0, stddev = 0, lo = 0;
  if (n) {
    mean = std::accumulate(samples_ms.begin(), samples_ms.end(), 0.0) / double(n);
    lo = *std::min_element(samples_ms.begin(), samples_ms.end());
  }
  if (n > 1) {
    double squares = 0;
    for (double v : samples_ms) squares += (v - mean) * (v - mean);
    stddev = std::sqrt(squares / double(n - 1));
  }
  return {{"frames", n},         {"warmup", warmup},
          {"samples_ms", samples_ms}, {"min_ms", number_or_null(lo)},
          {"median_ms", number_or_null(median(samples_ms))}, {"mean_ms", number_or_null(mean)},
          {"stddev_ms", number_or_null(stddev)}};
}

std::string frame_ms_note(int frames, int warmup, const std::string& what, const std::string& how) {
  return "median of " + std::to_string(frames) + " " + what + " after " + std::to_string(warmup) + " warm-up frame(s)" +
         how;
}

const char* const kWholeFrame = "whole frame: geometry, setup, binning, kernel, read-back";

std::string report_text(nlohmann::json body, const std::string& kind) {
  stamp_report(body, kind);
  return body.dump(2) + "\n";
}

}  // namespace parashade
