#include "parashade/device.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <sstream>
#include <tuple>

#include <CL/opencl.hpp>

#include "build_notice.hpp"
#include "captured_stderr.hpp"
#include "parashade/environment.hpp"
#include "parashade/errors.hpp"
#include "parashade/output_file.hpp"
#include "pocl_environment.hpp"

namespace parashade {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\0' || std::isspace(static_cast<unsigned char>(s.back())))) s.pop_back();
  return s;
}

std::string type_name(cl_device_type t) {
  if (t & CL_DEVICE_TYPE_GPU) return "gpu";
  if (t & CL_DEVICE_TYPE_CPU) return "cpu";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

struct Found {
  cl::Device device;
  DeviceInfo info;
};

std::vector<Found> enumerate() {
  // PoCL's pthread device lets the OS place its worker threads; on this project's 2-core machines both
  // workers sometimes stay on one core for a whole process, and every kernel then takes twice as long
  // (teapot Phong kernel 3.6 or 7.2 ms, per process at random, docs/pipeline.md). Pinning them
  // (POCL_AFFINITY=1, read when PoCL initializes) removes that; an explicit setting is left alone.
  ::setenv("POCL_AFFINITY", "1", 0);
  prepare_pocl_environment();
  std::vector<cl::Platform> platforms;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error& e) {
    platforms.clear();
  }
  if (platforms.empty())
    throw DeviceError(
        "no OpenCL platform found: install an OpenCL driver, e.g. 'apt-get install pocl-opencl-icd' "
        "(PoCL, the CPU device parashade is tested on)");
  std::vector<Found> found;
  for (const cl::Platform& p : platforms) {
    std::vector<cl::Device> devices;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue;  // a platform without devices (CL_DEVICE_NOT_FOUND)
    }
    for (const cl::Device& d : devices) {
      DeviceInfo i;
      i.index = int(found.size());
      i.platform = trim(p.getInfo<CL_PLATFORM_NAME>());
      i.name = trim(d.getInfo<CL_DEVICE_NAME>());
      i.vendor = trim(d.getInfo<CL_DEVICE_VENDOR>());
      i.version = trim(d.getInfo<CL_DEVICE_VERSION>());
      i.driver = trim(d.getInfo<CL_DRIVER_VERSION>());
      i.type = type_name(d.getInfo<CL_DEVICE_TYPE>());
      i.compute_units = int(d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>());
      i.global_memory = d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
      i.max_allocation = d.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
      i.constant_buffer = d.getInfo<CL_DEVICE_MAX_CONSTANT_BUFFER_SIZE>();
      i.max_work_group = d.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
      found.push_back({d, i});
    }
  }
  if (found.empty())
    throw DeviceError("OpenCL platforms were found but no device: install a driver such as pocl-opencl-icd");
  return found;
}

// " -D PARASHADE_FAIL_BUILD" when PARASHADE_FAIL_DEVICE is a substring of the device's name (any case):
// common.h then stops the build with #error, so a test can make one of several devices fail.
std::string injected_failure(const DeviceInfo& info) {
  const char* want = std::getenv("PARASHADE_FAIL_DEVICE");
  if (!want || !*want || lower(info.name).find(lower(want)) == std::string::npos) return "";
  return " -D PARASHADE_FAIL_BUILD";
}

// "#warning ..." ahead of the source when PARASHADE_WARN_DEVICE is a substring of the device's name (any
// case): a test can show that PARASHADE_KERNEL_WERROR=1 fails a build with a warning on each device.
std::string injected_warning(const DeviceInfo& info) {
  const char* want = std::getenv("PARASHADE_WARN_DEVICE");
  if (!want || !*want || lower(info.name).find(lower(want)) == std::string::npos) return "";
  return "#warning \"warning injected by PARASHADE_WARN_DEVICE\"\n";
}

// PARASHADE_KERNEL_WERROR=1 (the tests set it): kernel warnings are errors. Devices cannot be asked for
// that alike (PoCL 3.1 takes -Werror, but its own builtins then fail every build on "AVX vector argument
// of type 'int16' without 'avx512f' enabled changes the ABI", a note about its calling convention, not
// our source; Oclgrind 21.10 ignores -Werror), so the build keeps its warnings and the host reads the
// build log: every warning but that ABI note fails the build. Empty when there is none.
bool kernel_warnings_are_errors() { return kernel_werror_variable(); }

std::string kernel_warnings(const std::string& log) {
  std::istringstream in(log);
  std::string line, found;
  while (std::getline(in, line))
    if (line.find("warning:") != std::string::npos && line.find("changes the ABI") == std::string::npos)
      found += line + "\n";
  return found;
}

std::string device_list(const std::vector<Found>& found) {
  std::ostringstream s;
  for (const Found& f : found) s << "\n  " << f.info.index << ": " << f.info.platform << " / " << f.info.name;
  return s.str();
}

bool is_pocl(const DeviceInfo& d) { return lower(d.platform) == "portable computing language"; }

// PoCL's multi-threaded CPU device: "pthread-<cpu>" (PoCL 3), "cpu-<cpu>" (PoCL 4 and later).
bool is_pocl_threaded(const DeviceInfo& d) {
  const std::string name = lower(d.name);
  return is_pocl(d) && (name.rfind("pthread-", 0) == 0 || name.rfind("cpu-", 0) == 0);
}

bool is_pocl_basic(const DeviceInfo& d) { return is_pocl(d) && lower(d.name).rfind("basic-", 0) == 0; }

// Whether `a` is a better default than `b` (default_device's order).
bool better_default(const DeviceInfo& a, const DeviceInfo& b, bool threaded_pocl) {
  const auto rank = [threaded_pocl](const DeviceInfo& d) {
    return std::make_tuple(!is_simulator(d), !(threaded_pocl && is_pocl_basic(d)), d.compute_units, is_pocl_threaded(d));
  };
  if (rank(a) != rank(b)) return rank(a) > rank(b);
  return std::tie(a.platform, a.name, a.index) < std::tie(b.platform, b.name, b.index);
}

}  // namespace

std::string device_build_options(const DeviceInfo& info) { return info.type == "cpu" ? " -D CPU_DEVICE=1" : ""; }

bool is_simulator(const DeviceInfo& d) {
  return lower(d.platform).find("oclgrind") != std::string::npos || lower(d.name).find("oclgrind") != std::string::npos;
}

int default_device(const std::vector<DeviceInfo>& devices) {
  const bool threaded_pocl = std::any_of(devices.begin(), devices.end(), is_pocl_threaded);
  int best = -1;
  for (std::size_t i = 0; i < devices.size(); ++i)
    if (best < 0 || better_default(devices[i], devices[std::size_t(best)], threaded_pocl)) best = int(i);
  return best;
}

std::string left_out_of_all(const DeviceInfo& d, const std::vector<DeviceInfo>& devices) {
  if (is_simulator(d) && std::any_of(devices.begin(), devices.end(), [](const DeviceInfo& o) { return !is_simulator(o); }))
    return "a simulator, beside real devices";
  if (is_pocl_basic(d) && std::any_of(devices.begin(), devices.end(), is_pocl_threaded))
    return "PoCL's one-thread device, on the cores of its threaded one";
  return "";
}

std::string default_device_note(const DeviceInfo& d) {
  return "device: " + d.name + " (" + d.platform + ", " + std::to_string(d.compute_units) +
         " compute unit" + (d.compute_units == 1 ? "" : "s") + "; the default: --device to choose)";
}

bool takes_default_device(const std::string& selector) {
  const char* variable = std::getenv("PARASHADE_DEVICE");
  return selector.empty() && !(variable && *variable);
}

std::vector<DeviceInfo> list_devices() {
  try {
    std::vector<DeviceInfo> out;
    for (const Found& f : enumerate()) out.push_back(f.info);
    return out;
  } catch (const cl::Error&) {
    rethrow_cl_error("listing OpenCL devices");
  }
}

struct Device::Handles {
  cl::Device device;
  cl::Context context;
  cl::CommandQueue queue;
  std::map<std::pair<std::vector<std::string>, std::string>, cl::Program> programs;
};

Device::Device(cl::Device device, DeviceInfo info) : Device(device, std::move(info), cl::Context()) {}

Device::Device(cl::Device device, DeviceInfo info, cl::Context context)
    : info_(std::move(info)), cl_(new Handles{device, std::move(context), {}, {}}) {
  try {
    if (!cl_->context()) cl_->context = cl::Context(cl_->device);
    cl_->queue = cl::CommandQueue(cl_->context, cl_->device, CL_QUEUE_PROFILING_ENABLE);
  } catch (const cl::Error&) {
    rethrow_cl_error("opening device '" + info_.name + "'");
  }
}

Device::~Device() = default;
cl::Context& Device::context() { return cl_->context; }
cl::CommandQueue& Device::queue() { return cl_->queue; }
cl::Device& Device::device() { return cl_->device; }

cl::Program& Device::program(const std::vector<std::string>& files, const std::string& given) {
  const auto key = std::make_pair(files, given);
  const std::string options = given + device_build_options(info_) + injected_failure(info_);
  const auto it = cl_->programs.find(key);
  if (it != cl_->programs.end()) return it->second;
  const std::string source = injected_warning(info_) + kernel_source(files);
  cl::Program program;
  try {
    program = cl::Program(cl_->context, source);
  } catch (const cl::Error&) {
    rethrow_cl_error("creating program on '" + info_.name + "'");
  }
  const bool strict = kernel_warnings_are_errors();
  SlowBuildNotice notice(info_.name, is_pocl(info_));  // said while a build that is not cached compiles
  CapturedStderr compiler_output;  // PoCL's compiler writes to stderr directly
  try {
    // -w: PoCL 3.1's compiler prints a bare "N warnings generated." to stderr on every fresh build
    // (the warnings themselves are not shown, and clang-14 finds none in our sources); errors still
    // fail the build and their log is reported below. Under PARASHADE_KERNEL_WERROR=1 the warnings are
    // kept and checked below instead.
    program.build(cl_->device, ("-cl-std=CL1.2 " + std::string(strict ? "" : "-w ") + options).c_str());
  } catch (const cl::Error& e) {
    std::string log;
    try {
      log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(cl_->device);
    } catch (const cl::Error&) {
    }
    const std::string printed = trim(compiler_output.take());
    if (trim(log).empty()) log = printed.empty() ? "(no build log)" : "";
    if (!printed.empty()) log = trim(log) + (trim(log).empty() ? "" : "\n") + "--- the compiler's own output ---\n" + printed;
    throw DeviceError("building kernels (" + files.back() + ", options '" + options + "') failed on '" + info_.name +
                      "': " + cl_error_name(e.err()) + "\n--- build log ---\n" + trim(log));
  }
  notice.stop();
  compiler_output.take();  // a successful build's stray lines ("N warnings generated.") are dropped
  reclaim_signal_cleanup();  // LLVM's handlers swallow SIGQUIT and SIGUSR1 (output_file.hpp)
  if (strict) {
    std::string log;
    try {
      log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(cl_->device);
    } catch (const cl::Error&) {
    }
    // PoCL's kernel cache skips the compiler, and so the log, for a program it built before: a warning
    // shows on the build that first compiles the source with these options (CI starts without a cache).
    const std::string warnings = kernel_warnings(log);
    if (!warnings.empty())
      throw DeviceError("building kernels (" + files.back() + ", options '" + options + "') on '" + info_.name +
                        "' gave warnings, errors under PARASHADE_KERNEL_WERROR=1:\n" + warnings + "--- build log ---\n" +
                        trim(log));
  }
  return cl_->programs.emplace(key, std::move(program)).first->second;
}

std::unique_ptr<Device> open_device(const std::string& selector) {
  if (const char* value = std::getenv("PARASHADE_DEVICE"); selector.empty() && value && *value) {
    try {
      return open_device(value);
    } catch (const Error& e) {
      throw Error(e.code(), "PARASHADE_DEVICE='" + std::string(value) + "' (the device when none is given): " + e.what());
    }
  }
  std::vector<Found> found;
  try {
    found = enumerate();
  } catch (const cl::Error&) {
    rethrow_cl_error("listing OpenCL devices");
  }
  if (selector.empty()) {
    std::vector<DeviceInfo> infos;
    for (const Found& f : found) infos.push_back(f.info);
    const Found& chosen = found[std::size_t(default_device(infos))];
    return std::make_unique<Device>(chosen.device, chosen.info);
  }
  const bool numeric = std::all_of(selector.begin(), selector.end(), [](char c) { return std::isdigit(c); });
  if (numeric) {
    const std::size_t index = std::stoul(selector);
    if (index < found.size()) return std::make_unique<Device>(found[index].device, found[index].info);
    throw DeviceError("no OpenCL device with index " + selector + "; devices:" + device_list(found));
  }
  const std::string want = lower(selector);
  for (const Found& f : found) {
    if (lower(f.info.platform + " / " + f.info.name).find(want) != std::string::npos)
      return std::make_unique<Device>(f.device, f.info);
  }
  throw DeviceError("no OpenCL device matches '" + selector + "'; devices:" + device_list(found));
}

}  // namespace parashade
