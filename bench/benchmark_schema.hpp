#pragma once
// The "schema" of a Google Benchmark program's --benchmark_out JSON (docs/reports.md): Google Benchmark writes
// the file, so parashade's kind and version go in its context, as context.schema = "parashade.benchmark/<n>"
// (schemas/benchmark.schema.json), beside the build that ran it.
#include <string>

#include <benchmark/benchmark.h>

#include "parashade/report_header.hpp"
#include "parashade/version.hpp"

namespace parashade {

inline void add_schema_context() {
  benchmark::AddCustomContext("schema", "parashade.benchmark/" + std::to_string(kReportVersion));
  benchmark::AddCustomContext("parashade_version", version);
  benchmark::AddCustomContext("parashade_git_hash", git_hash);
}

}  // namespace parashade
