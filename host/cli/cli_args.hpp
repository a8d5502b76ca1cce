#pragma once
// Command-line values the commands share: lists, sizes, output destinations.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "parashade/errors.hpp"
#include "parashade/frame_config.hpp"
#include "parashade/render_step.hpp"
#include "parashade/scene.hpp"

namespace parashade::cli {

// "a,b,c" -> {"a", "b", "c"}; an empty entry is a usage error naming the option.
std::vector<std::string> split_list(const std::string& list, const std::string& option);

// Runs `call` (a library parser or device opener) and puts `option` in front of its usage error: the
// library names the value at fault but knows no flags ("--units: unit 'interleave:17': M = 17 is not in
// 1..16").
template <typename Call>
decltype(auto) for_option(const std::string& option, Call&& call) {
  try {
    return call();
  } catch (const UsageError& e) {
    throw UsageError(option + ": " + e.what());
  }
}

// A comma-separated list of values, each parsed; two entries naming the same value (by `name`) are a
// usage error naming the option.
template <typename Parse, typename Name>
auto parse_unique_list(const std::string& list, const std::string& option, Parse parse, Name name) {
  std::vector<decltype(parse(list))> out;
  std::vector<std::string> names;
  for (const std::string& spec : split_list(list, option)) {
    auto value = for_option(option, [&] { return parse(spec); });
    const std::string n = name(value);
    for (const std::string& seen : names)
      if (seen == n) throw UsageError(option + " lists '" + spec + "' twice (as " + n + ")");
    names.push_back(n);
    out.push_back(std::move(value));
  }
  return out;
}

// --size WIDTHxHEIGHT parsed and within the resolution limit (nullopt when not given); UsageError (exit 2)
// when not, as size_validator refuses it when the command line is read.
std::optional<std::pair<int, int>> checked_size(const std::string& size);

// The scene file at `size` when given (--size overrides the scene's resolution, and the memory budget is
// judged at it). `files`, when given, receives every file read (load_scene in scene_files.hpp).
Scene load_scene_at(const std::string& file, const std::optional<std::pair<int, int>>& size,
                    std::vector<std::filesystem::path>* files = nullptr);

// Runs `call` (which checks `config` on `devices` against the table of combinations: check_render_options,
// resolve_render); a refused combination becomes a usage error that names this command line's options for
// the values at fault.
void with_option_names(const FrameConfig& config, DeviceMode devices, const std::function<void()>& call);

// resolve_render (with `devices` kept between requests, when given), its refusals named by the command
// line's options.
ResolvedRender resolve_with_option_names(const RenderRequest& request, CommandFiles& files,
                                         DeviceCache* devices = nullptr);

// What resolving decided that the user should hear before the work, on stderr: the warnings (the scene's, a
// tune cache's), then the notes (the default device taken, the tuned entry, ...; none with -q). Every
// command that resolves a render (render, tune, scaling) says them alike.
void print_resolved(const ResolvedRender& r);

}  // namespace parashade::cli
