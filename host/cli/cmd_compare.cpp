// `parashade compare A B`: the error of image A against image B (the reference) in 8-bit levels, by the
// metrics the render report uses (metrics.hpp), optionally a pass/fail limit, an error map and a report.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "../render/error_pictures.hpp"
#include "parashade/command_files.hpp"
#include "parashade/errors.hpp"
#include "parashade/image.hpp"
#include "parashade/metrics.hpp"
#include "parashade/output_file.hpp"
#include "parashade/report.hpp"

namespace parashade::cli {
namespace {

struct CompareArgs {
  std::string a, b, diff, report;
  double fail = 0;
  bool fail_given = false, quiet = false;
};

// A file's values as a reference in levels: the float values (clamped to [0, 255], as the metrics clamp
// the compared image) when the file has them, else its 8-bit channels.
std::vector<glm::dvec3> values_of(const RenderedImage& image) {
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  std::vector<glm::dvec3> v(n);
  for (std::size_t p = 0; p < n; ++p)
    for (int c = 0; c < 3; ++c)
      v[p][c] = image.rgb_float.empty() ? double(image.rgba[4 * p + c])
                                        : std::clamp(double(image.rgb_float[3 * p + c]), 0.0, 255.0);
  return v;
}

// Compare's report body; report_text adds the header (schemas/compare.schema.json).
nlohmann::json compare_report(const CompareArgs& args, const RenderedImage& a, int channels, const ErrorMetrics& m,
                              std::uint64_t differing, bool passed) {
  return {{"a", args.a},
          {"b", args.b},
          {"width", a.width},
          {"height", a.height},
          {"channels", channels},
          {"error", to_json(m)},
          {"pixels_differing", differing},
          {"fail_levels", args.fail_given ? nlohmann::json(args.fail) : nlohmann::json()},
          {"passed", passed}};
}

int run_compare(const CompareArgs& args) {
  if (args.fail_given && !(args.fail >= 0 && args.fail <= 255))  // NaN fails too
    throw UsageError("--fail must be a number of levels in [0, 255]");
  CommandFiles files;
  files.input("A", args.a);
  files.input("B", args.b);
  files.output("--diff", args.diff, OutputKind::image);
  files.output("--report", args.report);
  files.check();

  int channels_a = 0, channels_b = 0;
  RenderedImage a = read_image(args.a, &channels_a);
  const RenderedImage b = read_image(args.b, &channels_b);
  if (a.width != b.width || a.height != b.height)
    throw InputError(args.a + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) + ", " + args.b +
                     " is " + std::to_string(b.width) + "x" + std::to_string(b.height) + ": images of one size only");
  if (channels_a != channels_b)
    throw InputError(args.a + " has " + std::to_string(channels_a) + " channels, " + args.b + " has " +
                     std::to_string(channels_b) + ": compare needs the same channels (grey, RGB or RGBA)");
  // Every pixel is compared, whatever an alpha channel says: compare looks at colours, not coverage.
  for (std::size_t p = 0; p < a.rgba.size(); p += 4) a.rgba[p + 3] = 255;
  const std::vector<std::uint8_t> all(std::size_t(a.width) * std::size_t(a.height), 1);
  const std::vector<glm::dvec3> reference = values_of(b);

  const ErrorMetrics m = compare_to_reference(a, all, reference, args.b);
  const std::vector<double> errors = pixel_errors(a, all, reference);
  const std::uint64_t differing = std::uint64_t(std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0; }));
  const bool passed = !args.fail_given || m.max_abs <= args.fail;

  std::vector<std::string> lines;
  std::optional<StagedFile> diff, report;
  if (!args.diff.empty()) diff.emplace(stage_error_map(args.diff, a, all, reference, {}, lines));
  if (!args.report.empty())
    report.emplace(stage_text(args.report, report_text(compare_report(args, a, channels_a, m, differing, passed), "compare")));
  if (diff) diff->commit();
  if (report) report->commit();

  std::printf("%s vs %s: %dx%d, %d channel%s%s\n", args.a.c_str(), args.b.c_str(), a.width, a.height, channels_a,
              channels_a == 1 ? "" : "s", channels_a == 2 || channels_a > 3 ? " (alpha not compared)" : "");
  std::printf("max %.3f levels, mean %.4f levels, NMSE %.4g, PSNR %.2f dB\n", m.max_abs, m.mean_abs, m.nmse, m.psnr_db);
  std::printf("differing pixels: %llu of %llu, %llu more than 1 level off\n", (unsigned long long)differing,
              (unsigned long long)m.pixels_compared, (unsigned long long)m.pixels_over_1_level);
  if (!args.quiet)
    for (const std::string& l : lines) std::printf("%s\n", l.c_str());
  if (args.fail_given)
    std::printf("%s: max %.3f levels %s the limit %g\n", passed ? "PASS" : "FAIL", m.max_abs, passed ? "within" : "over",
                args.fail);
  print_wrote({args.diff, args.report});
  return passed ? 0 : 1;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  auto* cmd = app.add_subcommand(
      "compare", "Compare image A with image B: error in 8-bit levels, NMSE, PSNR, differing pixels (docs/pictures.md)");
  cmd->footer(
      "Any format OpenImageIO reads (float files in levels, x255; alpha not compared). Exit 1 when the max error "
      "is above --fail, 2 usage error, 3 unreadable files or different sizes or channels.\n"
      "OpenImageIO's 'idiff A B' (openimageio-tools) does much the same for those who have it.");
  cmd->add_option("a", args->a, "The image to judge")->required();
  cmd->add_option("b", args->b, "The reference image (NMSE's denominator); same size and channels as A")->required();
  cmd->add_option("--fail", args->fail, "Exit 1 when the max error is above LEVELS (equal passes)")
      ->type_name("LEVELS")
      ->each([args](const std::string&) { args->fail_given = true; });
  cmd->add_option("--diff", args->diff,
                  "Write the per-pixel error (largest channel difference) as a colour map with its scale "
                  "(as render --error-map)");
  add_report_option(*cmd, args->report, "the figures, both files, the verdict");
  cmd->add_flag("-q,--quiet", args->quiet, "Only the figures and what was written (no error map scale line)");
  return {cmd, [args] { return run_compare(*args); }};
}

}  // namespace parashade::cli
