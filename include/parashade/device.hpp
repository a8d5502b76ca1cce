#pragma once
// OpenCL platforms and devices: listing, choosing one, building (and caching) programs from the
// embedded kernel sources, and turning OpenCL errors into messages with the call and the error name.
// No OpenCL header here: a program that uses Device's OpenCL handles includes <CL/opencl.hpp> itself.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cl {  // the OpenCL C++ bindings' classes (<CL/opencl.hpp>), named but not needed here
class CommandQueue;
class Context;
class Device;
class Program;
}  // namespace cl

namespace parashade {

struct DeviceInfo {
  int index = 0;               // position in list_devices()
  std::string platform;
  std::string name;
  std::string vendor;
  std::string version;         // OpenCL version string of the device
  std::string driver;
  std::string type;            // cpu, gpu, accelerator, other
  int compute_units = 0;
  std::uint64_t global_memory = 0;
  std::uint64_t max_allocation = 0;
  std::uint64_t constant_buffer = 0;
  std::size_t max_work_group = 0;
};

// Every device of every platform. Throws DeviceError naming the package to install when there is no
// OpenCL platform at all.
std::vector<DeviceInfo> list_devices();

// The -D options that follow from the device itself rather than from a render option, appended to every
// program built on it: " -D CPU_DEVICE=1" where the kernels are compiled for the CPU that runs them (PoCL's
// CPU devices, Intel's CPU runtime), so they may prefetch with the compiler's own intrinsic; empty elsewhere
// (Oclgrind, which reports a GPU, refuses that intrinsic).
std::string device_build_options(const DeviceInfo& info);

// An open device: context, in-order profiling queue, and a cache of built programs. Its OpenCL handles
// (context(), queue(), device(), program()) are for code that includes <CL/opencl.hpp>.
class Device {
 public:
  Device(cl::Device device, DeviceInfo info);
  // A device of a context it shares with other devices (a parent and its sub-devices: sub_devices.hpp);
  // its own queue, its own program cache.
  Device(cl::Device device, DeviceInfo info, cl::Context context);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  const DeviceInfo& info() const { return info_; }
  cl::Context& context();
  cl::CommandQueue& queue();
  cl::Device& device();
  // Builds the concatenation of `files` of kernels/ (their #include "..." lines resolved from the
  // embedded sources) with -cl-std=CL1.2 and `options`, once per (files, options). Throws DeviceError
  // with the device name and the build log. Fault injection for tests: when the environment variable
  // PARASHADE_FAIL_DEVICE is a substring of this device's name (any case), every build fails there
  // (kernels/common.h stops it with #error), through the same path as a real build failure.
  // PARASHADE_KERNEL_WERROR=1 (the tests): a build whose log has a warning fails (DeviceError);
  // PARASHADE_WARN_DEVICE=NAME-substring puts a #warning ahead of the source on matching devices.
  cl::Program& program(const std::vector<std::string>& files, const std::string& options);

 private:
  struct Handles;  // the OpenCL objects and the built programs (device.cpp)
  DeviceInfo info_;
  std::unique_ptr<Handles> cl_;
};

// Whether `d` is a simulator rather than hardware: Oclgrind (platform "Oclgrind", device "Oclgrind
// Simulator"), known by name since it reports itself as a GPU.
bool is_simulator(const DeviceInfo& d);

// The device taken when none is named (open_device(""), PARASHADE_DEVICE unset; docs/environment.md), as
// an index into `devices` (list_devices()' order), -1 when it is empty. The real device with the most
// compute units: a simulator only when there is nothing else, PoCL's one-thread `basic` only when PoCL
// has no threaded device (`pthread`, PoCL 4+'s `cpu`). Among equals PoCL's threaded device first (the
// reference: the project's figures and tests are measured on it), then by platform and device name, so
// the choice does not depend on the order the ICD loader lists the platforms in.
int default_device(const std::vector<DeviceInfo>& devices);

// Why `--device all` leaves `d` out of `devices` (list_devices()), or "" when it takes it: a simulator where a
// real device exists (Oclgrind: a frame of 160x90 takes it most of a second, and the first split frame gives it
// an equal band), PoCL's one-thread `basic` where PoCL has a threaded device (its thread competes with the
// threaded device's for the same cores). The devices default_device never takes while others exist.
std::string left_out_of_all(const DeviceInfo& d, const std::vector<DeviceInfo>& devices);

// "device: NAME (PLATFORM, N compute units; the default: --device to choose)": the note (notes.hpp) every
// command that opens a device (render, tune, scaling, render --distribute's rank 0) prints when it took the
// default device, that is when takes_default_device(its selector).
std::string default_device_note(const DeviceInfo& d);
// Whether open_device(selector) takes the default device: no selector and no PARASHADE_DEVICE.
bool takes_default_device(const std::string& selector);

// Opens the device chosen by `selector`: empty = the PARASHADE_DEVICE environment variable's selector when
// it is set (its errors name it), else the default device (default_device); a number = index in
// list_devices(); otherwise a case-insensitive substring of "platform / device name" (PoCL names its
// devices "pthread-..." and "basic-..."). Throws DeviceError listing the devices when nothing matches.
std::unique_ptr<Device> open_device(const std::string& selector);

// The files of kernels/ concatenated, #include "..." lines expanded (each file once).
std::string kernel_source(const std::vector<std::string>& files);

// "CL_OUT_OF_RESOURCES (-5)" for an OpenCL error code.
std::string cl_error_name(int code);
// Rethrows a cl::Error (or passes any other exception through) as DeviceError "<call> failed: <name>"
// prefixed with `context`.
[[noreturn]] void rethrow_cl_error(const std::string& context);

}  // namespace parashade
