// parashade vectors: test vectors for a shading unit's hardware from its golden model (test_vectors.hpp,
// docs/hardware.md): span inputs and the expected pixels per clock, for the Verilator testbenches
// (tests/hw/) and for a designer's own RTL. This reads the command line and writes the file.
#include <filesystem>
#include <memory>
#include <string>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "parashade/command_files.hpp"
#include "parashade/errors.hpp"
#include "parashade/report.hpp"
#include "parashade/test_vectors.hpp"
#include "parashade/unit_table.hpp"

namespace parashade::cli {
namespace {

struct VectorsArgs {
  std::string unit;
  std::string arith = "fixed:12.12";
  int spans = 200;
  std::uint64_t seed = 1;
  std::string out, report;
  bool quiet = false;
};

int run(const VectorsArgs& args) {
  const UnitConfig unit = parse_units(args.unit);
  if (!has_test_vectors(unit))
    throw UsageError("--unit '" + args.unit + "': test vectors are for the span units with hardware in hw/ (" +
                     unit_specs_help(true) + ")");
  const Arithmetic a = parse_arith(args.arith);
  if (!a.fixed) throw UsageError("--arith '" + args.arith + "': test vectors need fixed-point registers, fixed:I.F");
  CommandFiles files;  // before the work: a missing folder stops the run
  files.output("-o", args.out);
  files.output("--report", args.report);
  files.check();
  const std::vector<SpanLoad> spans = test_vector_spans(unit, a, args.spans, args.seed);
  const std::string text = test_vectors_text(unit, a, spans, args.seed);
  write_text_atomically(args.out, text);
  if (!args.report.empty())
    write_report(args.report,
                 {{"unit", unit_name(unit)}, {"arith", arith_name(a)}, {"seed", args.seed},
                  {"random_spans", args.spans}, {"spans", spans.size()}, {"vectors_file", args.out},
                  {"vectors_bytes", text.size()}},
                 "vectors");
  print_wrote({args.out, args.report});
  return 0;
}

}  // namespace

Command add_vectors_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "vectors", "Write test vectors for a unit's hardware (hw/) from its golden model: span inputs and the expected "
                 "pixels per clock (format: docs/hardware.md)");
  auto args = std::make_shared<VectorsArgs>();
  cmd->add_option("--unit", args->unit, "The unit: " + unit_specs_help(true))->required();
  cmd->add_option("--arith", args->arith, "Span register format fixed:I.F (9 <= I, 1 <= F, I + F <= 32)")
      ->capture_default_str();
  cmd->add_option("--spans", args->spans, "Random spans of 1..4096 pixels after the hand-picked ones")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the random spans")->capture_default_str();
  cmd->add_option("-o,--output", args->out, "The vectors file (written whole or not at all)")->required();
  add_report_option(*cmd, args->report, "the unit, arithmetic, seed and span count of the vectors");
  add_quiet_flag(*cmd, args->quiet);  // nothing to silence: vectors prints what it wrote and errors
  return {cmd, [args]() { return run(*args); }};
}

}  // namespace parashade::cli
