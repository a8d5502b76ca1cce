#pragma once
// One frame split across several OpenCL devices (--device all, or a comma list): each device shades a
// horizontal band of tile rows, sized in proportion to the device's measured speed on the previous
// frame's kernel time (equal bands for the first, calibration frame); the bands are copied into one image. Every
// device runs the whole tile kernel on its band, so the image is the single-device image.
#include <memory>
#include <string>
#include <vector>

#include "parashade/device.hpp"
#include "parashade/renderer.hpp"

namespace parashade {

// True for "all" or a comma-separated list of device selectors.
bool is_device_list(const std::string& selector);
// Opens every device the list names (each as open_device() would), in list order, no device twice. "all":
// every device but those left_out_of_all (device.hpp), which are added to `left_out` with the reason.
std::vector<std::unique_ptr<Device>> open_devices(const std::string& selector,
                                                  std::vector<std::string>* left_out = nullptr);

class SplitRenderer {
 public:
  struct Share {
    std::string device;
    int first_row = 0, rows = 0;  // tile rows
    double frame_ms = 0;          // the device's frame for its band (host clock)
    bool failed = false;  // dropped after failing (--keep-going): error says why
    std::string error;
  };
  // keep_going: a device that fails is reported on `warn` and dropped, the frame redone on the others;
  // otherwise its DeviceError (naming it) ends the run.
  // The devices stay the caller's and must outlive the renderer.
  SplitRenderer(std::vector<Device*> devices, RenderOptions options, bool keep_going);
  const Frame& render(const Scene& scene, std::string* warning = nullptr);
  const std::vector<Share>& shares() const { return shares_; }

 private:
  std::vector<Device*> devices_;
  // One renderer per device, kept across frames (its band moved by set_band): a new one each frame would
  // allocate and map its buffers again.
  std::vector<std::unique_ptr<Renderer>> renderers_;
  RenderOptions options_;
  bool keep_going_;
  std::vector<double> speed_;  // tile rows per kernel ms in the last frame; 0: not measured yet
  std::vector<std::string> dropped_;  // why a device was dropped (--keep-going); empty: it renders
  std::vector<Share> shares_;
  Frame frame_;
};

}  // namespace parashade
