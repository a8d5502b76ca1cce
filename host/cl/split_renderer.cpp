#include "parashade/split_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <set>
#include <thread>

#include "parashade/errors.hpp"
#include "parashade/sub_devices.hpp"

namespace parashade {
namespace {

// --keep-going with no device left: each named with its error (the warnings that named them as they were
// dropped are not printed when the run fails).
DeviceError every_device_failed(const std::vector<Device*>& devices, const std::vector<std::string>& dropped) {
  std::string each;
  for (std::size_t i = 0; i < devices.size(); ++i) each += (i ? "; '" : "'") + devices[i]->info().name + "': " + dropped[i];
  return DeviceError("every device of the list failed (--keep-going has none left): " + each);
}

}  // namespace

bool is_device_list(const std::string& selector) {
  return selector == "all" || selector.find(',') != std::string::npos || is_sub_device_selector(selector);
}

std::vector<std::unique_ptr<Device>> open_devices(const std::string& selector, std::vector<std::string>* left_out) {
  if (is_sub_device_selector(selector)) return open_sub_devices(selector, SubDeviceContext::own).subs;
  std::vector<std::string> names;
  if (selector == "all") {
    const std::vector<DeviceInfo> devices = list_devices();
    for (const DeviceInfo& d : devices) {
      const std::string why = left_out_of_all(d, devices);
      if (why.empty()) names.push_back(std::to_string(d.index));
      else if (left_out) left_out->push_back(d.name + " (" + why + ")");
    }
  } else {
    std::size_t from = 0;
    while (from <= selector.size()) {
      const std::size_t comma = std::min(selector.find(',', from), selector.size());
      const std::string name = selector.substr(from, comma - from);
      if (name.empty()) throw UsageError("device list '" + selector + "' has an empty entry");
      names.push_back(name);
      from = comma + 1;
    }
  }
  std::vector<std::unique_ptr<Device>> out;
  std::set<int> seen;
  for (const std::string& n : names) {
    auto d = open_device(n);
    if (!seen.insert(d->info().index).second)
      throw UsageError("device list '" + selector + "' names device '" + d->info().name + "' twice");
    out.push_back(std::move(d));
  }
  return out;
}

SplitRenderer::SplitRenderer(std::vector<Device*> devices, RenderOptions options, bool keep_going)
    : devices_(std::move(devices)), options_(options), keep_going_(keep_going) {
  if (devices_.empty()) throw UsageError("no device to render on");
  if (options_.float_output) throw UsageError("float read-back does not combine with a device list yet");
  speed_.assign(devices_.size(), 0.0);
  dropped_.assign(devices_.size(), "");
  renderers_.resize(devices_.size());
}

const Frame& SplitRenderer::render(const Scene& scene, std::string* warning) {
  const auto started = std::chrono::steady_clock::now();
  const int tile = options_.tile_size;
  const int tile_rows = (scene.height + tile - 1) / tile;
  std::vector<std::size_t> active;
  for (std::size_t i = 0; i < devices_.size(); ++i)
    if (dropped_[i].empty()) active.push_back(i);
  if (active.empty()) throw every_device_failed(devices_, dropped_);
  // Band sizes in proportion to the measured speeds (equal until every active device was measured).
  const bool measured = std::all_of(active.begin(), active.end(), [&](std::size_t i) { return speed_[i] > 0; });
  double total = 0;
  for (std::size_t i : active) total += measured ? speed_[i] : 1.0;
  shares_.assign(devices_.size(), Share{});
  int row = 0;
  double acc = 0;
  for (std::size_t k = 0; k < active.size(); ++k) {
    const std::size_t i = active[k];
    acc += (measured ? speed_[i] : 1.0) / total;
    // At least one row each while there are rows enough, so every device stays measured.
    const int left = int(active.size() - k - 1);
    int end = k + 1 == active.size() ? tile_rows : int(std::lround(acc * tile_rows));
    if (tile_rows >= int(active.size())) end = std::clamp(end, row + 1, tile_rows - left);
    shares_[i].first_row = row;
    shares_[i].rows = std::max(0, end - row);
    row = std::max(row, end);
  }
  for (std::size_t i = 0; i < devices_.size(); ++i) {
    shares_[i].device = devices_[i]->info().name;
    shares_[i].failed = !dropped_[i].empty();
    shares_[i].error = dropped_[i];
  }

  RenderedImage& img = frame_.image;
  img.width = scene.width;
  img.height = scene.height;
  img.rgba.assign(std::size_t(scene.width) * scene.height * 4, 0);
  img.rgb_float.clear();
  frame_.stats = FrameStats{};
  std::vector<std::exception_ptr> errors(devices_.size());
  std::vector<ModeledClocks> clocks(devices_.size());
  std::vector<double> kernel_ms(devices_.size(), 0.0);
  std::vector<std::thread> threads;
  for (std::size_t i : active) {
    if (shares_[i].rows == 0) continue;
    threads.emplace_back([&, i] {
      try {
        const auto t0 = std::chrono::steady_clock::now();
        std::unique_ptr<Renderer>& r = renderers_[i];
        if (r) {
          r->set_band(shares_[i].first_row, shares_[i].rows);
        } else {
          RenderOptions o = options_;
          o.band_first = shares_[i].first_row;
          o.band_rows = shares_[i].rows;
          r = std::make_unique<Renderer>(*devices_[i], o);
        }
        const Frame& f = r->render(scene);
        const int y0 = shares_[i].first_row * tile, y1 = std::min(scene.height, (shares_[i].first_row + shares_[i].rows) * tile);
        const std::size_t pitch = std::size_t(scene.width) * 4;
        std::memcpy(&img.rgba[std::size_t(y0) * pitch], &f.image.rgba[std::size_t(y0) * pitch], std::size_t(y1 - y0) * pitch);
        clocks[i] = f.stats.clocks;
        kernel_ms[i] = f.timings.kernel_ms;
        shares_[i].frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      } catch (...) {
        errors[i] = std::current_exception();
      }
    });
  }
  for (auto& t : threads) t.join();
  bool failed = false;
  for (std::size_t i : active) {
    if (!errors[i]) continue;
    try {
      std::rethrow_exception(errors[i]);
    } catch (const std::exception& e) {
      if (!keep_going_) throw DeviceError("device '" + devices_[i]->info().name + "' failed: " + e.what());
      if (warning) *warning += "device '" + devices_[i]->info().name + "' failed (" + e.what() + "); continuing on the others\n";
      dropped_[i] = *e.what() ? e.what() : "failed";
      renderers_[i].reset();
      failed = true;
    }
  }
  if (failed) return render(scene, warning);  // the frame again on the devices left
  for (std::size_t i : active) {
    // Speed by the shading kernel's time: the host stages are the whole frame's on every device.
    if (shares_[i].rows > 0 && kernel_ms[i] > 0) speed_[i] = shares_[i].rows / kernel_ms[i];
    frame_.stats.clocks.spans += clocks[i].spans;
    frame_.stats.clocks.pixels += clocks[i].pixels;
    frame_.stats.clocks.clocks += clocks[i].clocks;
  }
  frame_.timings = FrameTimings{};
  frame_.timings.total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return frame_;
}

}  // namespace parashade
