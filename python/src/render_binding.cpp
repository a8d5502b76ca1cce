// parashade.render (docs/python.md): render's words through the command's parser, the library's render step
// with the GIL released, the image as NumPy arrays and the report as the command writes it.
#include <iostream>
#include <memory>
#include <mutex>

#include <pybind11/numpy.h>

#include "../../host/cl/build_notice.hpp"
#include "../../host/cli/cli_args.hpp"
#include "../../host/cli/render_call.hpp"
#include "bindings.hpp"
#include "parashade/environment.hpp"
#include "parashade/render_report.hpp"
#include "parashade/report_header.hpp"

namespace parashade::python {
namespace {

// What the module keeps between calls: the open devices (and the programs they built, keyed by the kernel
// variant) for the process, and the last render resolved with its renderer, taken again by a call whose
// key (the scene file, its modification time and the words without the outputs) is the same.
struct Kept {
  std::mutex mutex;  // one render at a time: the devices' queues and the kept session are shared
  DeviceCache devices;
  std::vector<std::string> key;
  std::unique_ptr<ResolvedRender> resolved;
  std::unique_ptr<RenderSession> session;
};

Kept& kept() {
  static Kept* k = new Kept;  // never destroyed: OpenCL objects must not be released after PoCL unloads at exit
  return *k;
}

// The equivalent command line, which every report names (report_header.hpp).
void name_command_line(const std::vector<std::string>& words, const char* command) {
  std::vector<const char*> argv = {"parashade", command};
  for (const std::string& w : words) argv.push_back(w.c_str());
  set_report_command_line(int(argv.size()), argv.data());
}

// The call resolved, or the kept one when its key matches (its notes said again, as each command says them).
void resolve_or_keep(Kept& k, const cli::RenderCall& call, const std::vector<std::string>& key) {
  CommandFiles files;
  call.outputs.declare(files);
  if (k.resolved && k.key == key) {
    files.check();
  } else {
    k.session.reset();
    k.resolved.reset();
    k.key.clear();
    k.resolved = std::make_unique<ResolvedRender>(cli::resolve_with_option_names(call.request, files, &k.devices));
    k.session = std::make_unique<RenderSession>(*k.resolved);
    k.key = key;
  }
  call.check_resolved(*k.resolved);
}

// The frames, the outputs written, the report's text.
std::string render_kept(Kept& k, const cli::RenderCall& call, RenderResult& result) {
  try {
    result = render(*k.resolved, *k.session);
  } catch (...) {
    k.session.reset(), k.resolved.reset(), k.key.clear();  // a failed device is not kept
    throw;
  }
  print_render_warnings(result, std::cerr);
  if (!call.outputs.image.empty()) call.outputs.write(result);
  const RenderReport report = render_report(result, call.outputs.image);
  return report_text(report.body, report.kind);
}

pybind11::array_t<std::uint8_t> rgba_array(const RenderedImage& image) {
  pybind11::array_t<std::uint8_t> a({image.height, image.width, 4});
  std::copy(image.rgba.begin(), image.rgba.end(), a.mutable_data());
  return a;
}

pybind11::object float_array(const RenderedImage& image) {
  if (image.rgb_float.empty()) return pybind11::none();
  pybind11::array_t<float> a({image.height, image.width, 3});
  std::copy(image.rgb_float.begin(), image.rgb_float.end(), a.mutable_data());
  return std::move(a);
}

}  // namespace

pybind11::dict render(const std::vector<std::string>& words, const std::vector<std::string>& kept_key) {
  RenderResult result;
  std::string report;
  {
    pybind11::gil_scoped_release unlocked;
    check_environment();  // a bad PARASHADE_* value, as the command refuses it
    const cli::RenderCall call = cli::parse_render_call(words);
    Kept& k = kept();
    const std::lock_guard<std::mutex> lock(k.mutex);
    name_command_line(words, "render");
    set_kernel_build_notices(!call.request.quiet);
    resolve_or_keep(k, call, kept_key);
    report = render_kept(k, call, result);
  }
  pybind11::dict out;
  out["rgba"] = rgba_array(result.image);
  out["rgb_float"] = float_array(result.image);
  out["report"] = report;
  return out;
}

std::unique_lock<std::mutex> hold_without_kept_render() {
  Kept& k = kept();
  std::unique_lock<std::mutex> lock(k.mutex);
  k.session.reset(), k.resolved.reset(), k.key.clear();
  return lock;
}

void clear_cache() {
  pybind11::gil_scoped_release unlocked;
  Kept& k = kept();
  const std::lock_guard<std::mutex> lock(k.mutex);
  k.session.reset(), k.resolved.reset(), k.key.clear();
  k.devices = DeviceCache();
}

}  // namespace parashade::python
