#pragma once
// The C++ side of the Python module parashade (docs/python.md): what python/parashade/__init__.py calls.
// Each function takes the command's arguments as words ("--method", "phong"), which the command's own
// CLI11 definition parses, so every option name, default and message is the command line's.
#include <mutex>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace parashade::python {

// `parashade render` without its process: parsed, resolved and rendered by the library's render step with
// the GIL released; the outputs the words name (-o, --report, pictures) written as the command writes them.
// Returns {"rgba": uint8 HxWx4, "rgb_float": float32 HxWx3 or None, "report": the report's text}.
pybind11::dict render(const std::vector<std::string>& words, const std::vector<std::string>& kept_key);

// The scene file loaded as render loads it, at `size` ("WxH", or "" for the scene's): its name, width, height
// and triangles.
pybind11::dict scene_info(const std::string& path, const std::string& size);

// Runs another command (words[0]: compare, tune, devices, ...) in this process as the command line runs it;
// returns its exit code (compare: 1 above --fail). Errors raise as render's do.
int run_command(const std::vector<std::string>& words);

// The kept devices, programs and last renderer dropped (the module's parashade.clear_cache()).
void clear_cache();
// The module's lock (one call at a time: the devices, the kept render and the report's command line are
// shared), with the last renderer dropped: a command run in between (tune) may change what it resolved to.
std::unique_lock<std::mutex> hold_without_kept_render();

// The library's errors as the exceptions of parashade.errors, each carrying the command's message and exit code.
void register_error_translation();

}  // namespace parashade::python
