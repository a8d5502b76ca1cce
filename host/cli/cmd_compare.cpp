// `parashade compare A B`: the error of image A against image B (the reference) in 8-bit levels, by the
// metrics the render report uses (metrics.hpp), where the largest error is, optionally LDR-FLIP, an
// idiff-style pass/fail verdict, the error and FLIP maps and a report.
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
#include "parashade/flip.hpp"
#include "parashade/image.hpp"
#include "parashade/memory_budget.hpp"
#include "parashade/metrics.hpp"
#include "parashade/output_file.hpp"
#include "parashade/report.hpp"

namespace parashade::cli {
namespace {

struct CompareArgs {
  std::string a, b, error_map, error_legend, error_scale = "gamma", flip_map, report;
  double fail = 0, fail_percent = 0;
  bool fail_given = false, fail_percent_given = false, flip = false, quiet = false;
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

// Where the largest error is, as idiff says it: the first such pixel in reading order and its channel.
struct MaxAt {
  int x = 0, y = 0;
  char channel = 'R';
};

// The verdict and the figures behind it (idiff's: a pixel fails when some channel is more than the limit off;
// with a percentage, the comparison fails when more than that share of the pixels fail).
struct Verdict {
  double limit = 0;                // levels: --fail, else 0
  std::uint64_t pixels_over = 0;   // pixels more than `limit` off
  bool passed = true;
};

struct Comparison {
  RenderedImage a;
  int channels = 0;
  ErrorMetrics m;
  std::vector<double> errors;  // per pixel, levels
  std::uint64_t differing = 0;
  std::optional<MaxAt> max_at;  // none when the images are identical
  Verdict verdict;
  std::vector<float> flip_map;
};

std::optional<MaxAt> max_location(const RenderedImage& a, const std::vector<glm::dvec3>& reference,
                                  const std::vector<double>& errors, double max_abs) {
  if (!(max_abs > 0)) return std::nullopt;
  const auto it = std::find(errors.begin(), errors.end(), max_abs);
  if (it == errors.end()) return std::nullopt;
  const std::size_t p = std::size_t(it - errors.begin());
  const glm::dvec3 e = channel_errors(a, p, reference[p]);
  MaxAt at{int(p % std::size_t(a.width)), int(p / std::size_t(a.width)), 'R'};
  at.channel = e.x == max_abs ? 'R' : e.y == max_abs ? 'G' : 'B';
  return at;
}

Verdict verdict_of(const CompareArgs& args, const ErrorMetrics& m, const std::vector<double>& errors) {
  Verdict v;
  v.limit = args.fail_given ? args.fail : 0.0;
  v.pixels_over = std::uint64_t(std::count_if(errors.begin(), errors.end(), [&](double e) { return e > v.limit; }));
  if (args.fail_percent_given) v.passed = double(v.pixels_over) <= args.fail_percent / 100.0 * double(errors.size());
  else if (args.fail_given) v.passed = m.max_abs <= args.fail;
  return v;
}

Comparison compare_files(const CompareArgs& args) {
  Comparison c;
  int channels_b = 0;
  c.a = read_image(args.a, &c.channels);
  const RenderedImage b = read_image(args.b, &channels_b);
  if (c.a.width != b.width || c.a.height != b.height)
    throw InputError(args.a + " is " + std::to_string(c.a.width) + "x" + std::to_string(c.a.height) + ", " + args.b +
                     " is " + std::to_string(b.width) + "x" + std::to_string(b.height) + ": images of one size only");
  if (c.channels != channels_b)
    throw InputError(args.a + " has " + std::to_string(c.channels) + " channels, " + args.b + " has " +
                     std::to_string(channels_b) + ": compare needs the same channels (grey, RGB or RGBA)");
  // Every pixel is compared, whatever an alpha channel says: compare looks at colours, not coverage.
  for (std::size_t p = 0; p < c.a.rgba.size(); p += 4) c.a.rgba[p + 3] = 255;
  const std::vector<std::uint8_t> all(std::size_t(c.a.width) * std::size_t(c.a.height), 1);
  const std::vector<glm::dvec3> reference = values_of(b);
  c.m = compare_to_reference(c.a, all, reference, args.b);
  c.errors = pixel_errors(c.a, all, reference);
  c.differing = std::uint64_t(std::count_if(c.errors.begin(), c.errors.end(), [](double e) { return e > 0; }));
  c.max_at = max_location(c.a, reference, c.errors, c.m.max_abs);
  c.verdict = verdict_of(args, c.m, c.errors);
  if (args.flip || !args.flip_map.empty()) {
    // FLIP's two float RGB inputs and its map: 28 bytes a pixel beside the images already read.
    check_host_bytes("--flip", 28 * std::uint64_t(c.a.width) * std::uint64_t(c.a.height),
                     "LDR-FLIP of two " + std::to_string(c.a.width) + "x" + std::to_string(c.a.height) + " images");
    c.flip_map = ldr_flip(flip_input(reference), flip_input(c.a), c.a.width, c.a.height);
    c.m.flip = flip_figures(c.flip_map);
  }
  return c;
}

// Compare's report body; report_text adds the header (schemas/compare.schema.json).
nlohmann::json compare_report(const CompareArgs& args, const Comparison& c) {
  const bool limited = args.fail_given || args.fail_percent_given;
  nlohmann::json max_at;  // null: identical images have no largest error
  if (c.max_at) max_at = {{"x", c.max_at->x}, {"y", c.max_at->y}, {"channel", std::string(1, c.max_at->channel)}};
  return {{"a", args.a},
          {"b", args.b},
          {"width", c.a.width},
          {"height", c.a.height},
          {"channels", c.channels},
          {"exact", c.m.status == MetricsStatus::identical},
          {"error", to_json(c.m)},
          {"max_at", max_at},
          {"pixels_differing", c.differing},
          {"fail_levels", args.fail_given ? nlohmann::json(args.fail) : nlohmann::json()},
          {"fail_percent", args.fail_percent_given ? nlohmann::json(args.fail_percent) : nlohmann::json()},
          {"pixels_over_fail", limited ? nlohmann::json(c.verdict.pixels_over) : nlohmann::json()},
          {"passed", c.verdict.passed}};
}

void print_figures(const CompareArgs& args, const Comparison& c) {
  const ErrorMetrics& m = c.m;
  std::printf("%s vs %s: %dx%d, %d channel%s%s\n", args.a.c_str(), args.b.c_str(), c.a.width, c.a.height, c.channels,
              c.channels == 1 ? "" : "s", c.channels == 2 || c.channels > 3 ? " (alpha not compared)" : "");
  if (m.status == MetricsStatus::identical) {
    std::printf("exact: max 0.000 levels, mean 0.0000 levels, NMSE 0, PSNR exact (the images are identical)\n");
  } else {
    std::printf("max %.3f levels at (%d, %d) channel %c, mean %.4f levels, NMSE %.4g, PSNR %.2f dB\n", m.max_abs,
                c.max_at->x, c.max_at->y, c.max_at->channel, m.mean_abs, m.nmse, m.psnr_db);
  }
  if (m.flip) std::printf("FLIP %.4g (LDR-FLIP mean over the image; max %.3g)\n", m.flip->mean, m.flip->max);
  std::printf("differing pixels: %llu of %llu, %llu more than 1 level off\n", (unsigned long long)c.differing,
              (unsigned long long)m.pixels_compared, (unsigned long long)m.pixels_over_1_level);
}

void print_verdict(const CompareArgs& args, const Comparison& c) {
  const char* word = c.verdict.passed ? "PASS" : "FAIL";
  if (args.fail_percent_given) {
    const double share = 100.0 * double(c.verdict.pixels_over) / double(std::max<std::size_t>(c.errors.size(), 1));
    std::printf("%s: %llu pixels (%.3g%%) more than %g levels off, %s the limit %g%%\n", word,
                (unsigned long long)c.verdict.pixels_over, share, c.verdict.limit,
                c.verdict.passed ? "within" : "over", args.fail_percent);
  } else if (args.fail_given) {
    std::printf("%s: max %.3f levels %s the limit %g\n", word, c.m.max_abs, c.verdict.passed ? "within" : "over",
                args.fail);
  }
}

int run_compare(const CompareArgs& args) {
  if (args.fail_given && !(args.fail >= 0 && args.fail <= 255))  // NaN fails too
    throw UsageError("--fail must be a number of levels in [0, 255]");
  if (args.fail_percent_given && !(args.fail_percent >= 0 && args.fail_percent <= 100))
    throw UsageError("--fail-percent must be a percentage of the pixels in [0, 100]");
  const ErrorPictureFiles pictures{args.error_map, args.error_legend, parse_error_scale(args.error_scale)};
  check_error_picture_options(pictures, "--error-map");
  CommandFiles files;
  files.input("A", args.a);
  files.input("B", args.b);
  files.output("--error-map", args.error_map, OutputKind::image);
  files.output("--error-legend", args.error_legend, OutputKind::image);
  files.output("--flip-map", args.flip_map, OutputKind::image);
  files.output("--report", args.report);
  files.check();

  const Comparison c = compare_files(args);
  std::vector<std::string> lines;
  std::vector<StagedFile> staged = stage_error_pictures(pictures, c.errors, c.a.width, c.a.height, lines);
  if (!args.flip_map.empty()) staged.push_back(stage_flip_map(args.flip_map, c.flip_map, c.a.width, c.a.height, lines));
  if (!args.report.empty()) staged.push_back(stage_text(args.report, report_text(compare_report(args, c), "compare")));
  for (StagedFile& f : staged) f.commit();

  print_figures(args, c);
  if (!args.quiet)
    for (const std::string& l : lines) std::printf("%s\n", l.c_str());
  print_verdict(args, c);
  print_wrote({args.error_map, args.error_legend, args.flip_map, args.report});
  return c.verdict.passed ? 0 : 1;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  auto* cmd = app.add_subcommand(
      "compare", "Compare image A with image B: error in 8-bit levels and where it is largest, NMSE, PSNR, "
                 "differing pixels, optionally FLIP (docs/pictures.md)");
  cmd->footer(
      "Any format OpenImageIO reads (float files in levels, x255; alpha not compared). Exit 1 when the max error "
      "is above --fail, or with --fail-percent when more than that share of the pixels are above it; 2 usage "
      "error, 3 unreadable files or different sizes or channels.\n"
      "OpenImageIO's 'idiff A B' (openimageio-tools) does much the same for those who have it; docs/pictures.md "
      "says where the two differ.");
  cmd->add_option("a", args->a, "The image to judge")->required();
  cmd->add_option("b", args->b, "The reference image (NMSE's denominator); same size and channels as A")->required();
  cmd->add_option("--fail", args->fail,
                  "Exit 1 when the max error is above LEVELS (equal passes); with --fail-percent, the limit a pixel "
                  "fails above (default 0)")
      ->type_name("LEVELS")
      ->each([args](const std::string&) { args->fail_given = true; });
  cmd->add_option("--fail-percent", args->fail_percent,
                  "As idiff's -failpercent: exit 1 only when more than P % of the pixels are more than --fail levels "
                  "off (the max alone no longer fails)")
      ->type_name("P")
      ->each([args](const std::string&) { args->fail_percent_given = true; });
  CLI::Option* map = cmd->add_option("--error-map", args->error_map,
                                     "Write the per-pixel error (largest channel difference), as render --error-map "
                                     "does: a colour map of the images' size, or to .exr the values in levels");
  add_deprecated_spelling(*cmd, map, "--diff", args->error_map);
  add_error_picture_options(*cmd, args->error_scale, args->error_legend, args->flip, args->flip_map);
  add_report_option(*cmd, args->report, "the figures, both files, the verdict");
  cmd->add_flag("-q,--quiet", args->quiet, "Only the figures and what was written (no error map scale line)");
  return {cmd, [args] { return run_compare(*args); }};
}

}  // namespace parashade::cli
