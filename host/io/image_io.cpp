// Writing and reading images through OpenImageIO (image.hpp). A write goes to a temporary file in
// the destination directory (output_file.hpp), every write of OIIO's plugins checked, and is renamed into
// place, so readers never see a partial image and a failed write never replaces a good one.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "../scene/input_file.hpp"
#include "parashade/errors.hpp"
#include "parashade/image.hpp"
#include "parashade/memory_budget.hpp"
#include "parashade/output_file.hpp"

namespace parashade {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// OIIO keeps errors per thread until read; read them so they neither leak into later messages nor
// get printed at exit.
std::string take_global_oiio_error() { return OIIO::geterror(); }

// OIIO's plugins write through this proxy into the staged file: a failed write (ENOSPC, EFBIG, EIO) is
// kept in the StagedFile even where a plugin ignores the short count (PNG, BMP and TGA did). Consecutive
// writes are gathered before they reach the file: OIIO's PNM writer hands over one byte at a time (a
// 1920x1080 PPM was 6.2 M pwrite calls, 2.3 s; PNG took 0.4 s). flush() before the file is closed.
class StagedProxy : public OIIO::Filesystem::IOProxy {
 public:
  explicit StagedProxy(StagedFile& file) : IOProxy(file.temporary().string(), Write), file_(file) {}
  const char* proxytype() const override { return "parashade-staged"; }
  size_t write(const void* buf, size_t size) override {
    const size_t n = pwrite(buf, size, m_pos);
    m_pos += int64_t(n);
    return n;
  }
  size_t pwrite(const void* buf, size_t size, int64_t offset) override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (offset < 0) return 0;
    const std::size_t at = std::size_t(offset);
    if (at != gathered_at_ + gathered_.size() || gathered_.size() + size > kGather) {
      if (!flush_locked()) return 0;
      gathered_at_ = at;
    }
    if (size > kGather) {
      if (!file_.pwrite_all(buf, size, at)) return 0;
    } else {
      const auto* bytes = static_cast<const std::uint8_t*>(buf);
      gathered_.insert(gathered_.end(), bytes, bytes + size);
    }
    size_ = std::max(size_, at + size);
    return size;
  }
  size_t read(void* buf, size_t size) override {
    const size_t n = pread(buf, size, m_pos);
    m_pos += int64_t(n);
    return n;
  }
  size_t pread(void* buf, size_t size, int64_t offset) override {  // TIFF reads back what it wrote
    std::lock_guard<std::mutex> lock(mutex_);
    if (!flush_locked()) return 0;
    const ssize_t n = ::pread(fd_, buf, size, off_t(offset));
    return n < 0 ? 0 : size_t(n);
  }
  size_t size() const override { return size_; }
  // The gathered bytes to the file; false (and the StagedFile's error set) when the write failed.
  bool flush() {
    std::lock_guard<std::mutex> lock(mutex_);
    return flush_locked();
  }

  int fd_ = -1;

 private:
  static constexpr std::size_t kGather = std::size_t(1) << 20;
  bool flush_locked() {
    const bool ok = gathered_.empty() || file_.pwrite_all(gathered_.data(), gathered_.size(), gathered_at_);
    gathered_at_ += gathered_.size();
    gathered_.clear();
    return ok;
  }
  StagedFile& file_;
  std::size_t size_ = 0;
  std::vector<std::uint8_t> gathered_;
  std::size_t gathered_at_ = 0;
  std::mutex mutex_;
};

// No time stamp in the file (TIFF's DateTime, EXR's capDate), so identical runs give identical bytes.
OIIO::ImageSpec spec_without_time(int width, int height, int channels, OIIO::TypeDesc type) {
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.attribute("DateTime", "");
  return spec;
}

// Pixel data as the file stores it: 3 channels, float levels/255 for EXR, else 8-bit; or one float channel
// of values (stage_values).
struct Pixels {
  OIIO::TypeDesc type;
  int channels = 3;
  std::vector<std::uint8_t> u8;
  std::vector<float> f32;
  const void* data() const {
    return type == OIIO::TypeDesc::FLOAT ? static_cast<const void*>(f32.data()) : u8.data();
  }
};

Pixels pixels_for(const RenderedImage& image, bool as_float) {
  const std::size_t n = std::size_t(image.width) * std::size_t(image.height);
  Pixels px;
  if (as_float) {
    px.type = OIIO::TypeDesc::FLOAT;
    px.f32.resize(3 * n);
    const bool have_float = image.rgb_float.size() == 3 * n;
    for (std::size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c)
        px.f32[3 * p + c] = (have_float ? image.rgb_float[3 * p + c] : float(image.rgba[4 * p + c])) / 255.0f;
  } else {
    px.type = OIIO::TypeDesc::UINT8;
    px.u8.resize(3 * n);
    for (std::size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c) px.u8[3 * p + c] = image.rgba[4 * p + c];
  }
  return px;
}

// Writes the staged file; a failure is recorded in `file` (its error()).
void write_file(StagedFile& file, int width, int height, const Pixels& px) {
  const std::string name = file.temporary().string();
  StagedProxy proxy(file);  // declared first: it must outlive `out`, whose destructor may still use it
  auto out = OIIO::ImageOutput::create(name);
  if (!out) {
    const std::string why = take_global_oiio_error();
    return file.fail(why.empty() ? "unknown image format" : why);
  }
  // Every format parashade documents takes a proxy; one that does not is written by OIIO itself (its
  // own write errors only).
  if (out->supports("ioproxy")) {
    proxy.fd_ = file.open_fd();
    out->set_ioproxy(&proxy);
  }
  OIIO::ImageSpec spec = spec_without_time(width, height, px.channels, px.type);
  if (px.channels == 1) spec.channelnames = {"Y"};
  if (!out->open(name, spec)) return file.fail(out->geterror());
  const bool written = out->write_image(px.type, px.data());
  if (!written) file.fail(out->geterror());
  if (!out->close()) file.fail(out->geterror());
  out.reset();
  proxy.flush();  // a failed write is kept in `file`
  file.close_fd();
}

// Why OpenImageIO could not read the pixels: its own error, else the global one, else what it means
// (a truncated PPM gave "cannot read X: " with nothing after the colon).
std::string read_failure(OIIO::ImageInput& in) {
  std::string why = in.geterror();
  if (why.empty()) why = take_global_oiio_error();
  return why.empty() ? "the pixels cannot be read (the file is truncated or corrupt)" : why;
}

// Host memory reading a file takes: its 8-bit channels and RGBA copy, and for float files the float
// channels and the RGB levels.
std::uint64_t image_read_bytes(const OIIO::ImageSpec& spec) {
  const std::uint64_t n = std::uint64_t(spec.width) * std::uint64_t(spec.height), c = std::uint64_t(spec.nchannels);
  return n * (c + 4 + (spec.format.basetype == OIIO::TypeDesc::UINT8 ? 0 : 4 * c + 12));
}

// The pixels of an opened file: 1 channel grey; 2 grey + alpha; 3 RGB; 4 or more RGBA (extra channels
// ignored). Float files keep their unquantized values, in levels.
RenderedImage read_pixels(OIIO::ImageInput& in, const std::string& name) {
  const OIIO::ImageSpec& spec = in.spec();
  const int channels = spec.nchannels;
  RenderedImage image;
  image.width = spec.width;
  image.height = spec.height;
  const std::size_t n = std::size_t(spec.width) * std::size_t(spec.height);
  std::vector<std::uint8_t> u8(n * channels);
  if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, u8.data())) throw InputError(name + ": " + read_failure(in));
  image.rgba.resize(4 * n);
  for (std::size_t p = 0; p < n; ++p) {
    const std::uint8_t* s = &u8[p * channels];
    const bool grey = channels < 3;
    for (int c = 0; c < 3; ++c) image.rgba[4 * p + c] = grey ? s[0] : s[c];
    image.rgba[4 * p + 3] = channels == 2 ? s[1] : channels >= 4 ? s[3] : 255;
  }
  const OIIO::TypeDesc::BASETYPE base = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
  if (base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE) {
    std::vector<float> f(n * channels);
    if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, f.data())) throw InputError(name + ": " + read_failure(in));
    image.rgb_float.resize(3 * n);
    for (std::size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c) image.rgb_float[3 * p + c] = 255.0f * f[p * channels + (channels < 3 ? 0 : c)];
  }
  return image;
}

// `px` staged at `path` (a destination checked before: check_image_destination); an InputError naming the file
// when it cannot be written. stage_image's and stage_values' writing.
StagedFile stage_pixels(const fs::path& path, int width, int height, const Pixels& px) {
  StagedFile file(path);
  write_file(file, width, height, px);
  take_global_oiio_error();
  if (!file.error().empty()) throw InputError("cannot write " + path.string() + ": " + file.error());
  return file;
}

}  // namespace

void check_image_destination(const fs::path& path) {
  check_output_folder("", path);
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError("cannot write " + path.string() + ": it is a directory");
  const std::string ext = lower_extension(path);
  if (ext.empty())
    throw InputError("cannot write " + path.string() + ": no extension to choose the image format");
  // OIIO knows the format by the extension; asking creates nothing on disk.
  auto probe = OIIO::ImageOutput::create(path.string());
  if (!probe) {
    take_global_oiio_error();
    throw InputError("cannot write " + path.string() + ": unknown image format '" + ext + "'");
  }
}

void write_image(const fs::path& path, const RenderedImage& image) {
  stage_image(path, image).commit();
}

StagedFile stage_image(const fs::path& path, const RenderedImage& image) {
  const std::size_t n = std::size_t(std::max(image.width, 0)) * std::size_t(std::max(image.height, 0));
  if (image.width < 1 || image.height < 1 || image.rgba.size() != 4 * n)
    throw InputError("cannot write " + path.string() + ": the image is empty or inconsistent");
  check_image_destination(path);  // before touching the file system
  return stage_pixels(path, image.width, image.height, pixels_for(image, lower_extension(path) == ".exr"));
}

StagedFile stage_values(const fs::path& path, const std::vector<float>& values, int width, int height) {
  if (width < 1 || height < 1 || values.size() != std::size_t(width) * std::size_t(height))
    throw InputError("cannot write " + path.string() + ": the values are empty or inconsistent");
  check_image_destination(path);
  if (lower_extension(path) != ".exr")
    throw InputError("cannot write " + path.string() + ": values are written as OpenEXR only (.exr)");
  Pixels px;
  px.type = OIIO::TypeDesc::FLOAT;
  px.channels = 1;
  px.f32 = values;
  return stage_pixels(path, width, height, px);
}

bool is_exr(const fs::path& path) { return lower_extension(path) == ".exr"; }

RenderedImage read_image(const fs::path& path, int* channels_out) {
  const std::string name = "cannot read " + path.string();
  // OpenImageIO says only "Could not open file": the system's reason first. A FIFO would block the open,
  // /dev/zero would be read without end (issue 46, item 8): a regular file only.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputError(name + ": " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputError(name + ": it is a directory");
  detail::check_input_file(path, name, detail::kMaxImageFileBytes, "raster image");
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    std::fclose(f);
  } else {
    throw InputError(name + ": " + std::strerror(errno));
  }
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    const std::string why = take_global_oiio_error();
    throw InputError(name + ": " + (why.empty() ? "unreadable image" : why));
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) throw InputError(name + ": empty image");
  check_host_bytes(name, image_read_bytes(spec),
                   "a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image of " +
                       std::to_string(spec.nchannels) + " channels");
  if (channels_out) *channels_out = spec.nchannels;
  try {
    return read_pixels(*in, name);
  } catch (const std::bad_alloc&) {
    throw InputError(name + ": out of host memory for a " + std::to_string(spec.width) + "x" +
                     std::to_string(spec.height) + " image");
  }
}

}  // namespace parashade
