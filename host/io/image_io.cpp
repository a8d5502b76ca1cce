// Writing and reading images through OpenImageIO (image.hpp). A write goes to a temporary file in
// the destination directory and is renamed into place, so readers never see a partial image.
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdint>
#include <string>
#include <system_error>
#include <vector>

#include "parashade/errors.hpp"
#include "parashade/image.hpp"

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

// ".name.tmp-<pid>-<n>.ext" beside the destination: same file system (rename is atomic) and the same
// extension (OIIO chooses the format by it).
fs::path temporary_beside(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  const std::string name = "." + path.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                           std::to_string(counter++) + path.extension().string();
  return path.parent_path() / name;
}

// Pixel data as the file stores it: 3 channels, float levels/255 for EXR, else 8-bit.
struct Pixels {
  OIIO::TypeDesc type;
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

// Writes the file at `file` (the temporary); returns an empty string or the reason it failed.
std::string write_file(const fs::path& file, const RenderedImage& image, bool as_float) {
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) {
    const std::string why = take_global_oiio_error();
    return why.empty() ? "unknown image format" : why;
  }
  const Pixels px = pixels_for(image, as_float);
  const OIIO::ImageSpec spec(image.width, image.height, 3, px.type);
  if (!out->open(file.string(), spec)) return out->geterror();
  const bool written = out->write_image(px.type, px.data());
  const std::string write_error = written ? std::string() : out->geterror();
  if (!out->close() && written) return out->geterror();
  return write_error;
}

}  // namespace

void check_image_destination(const fs::path& path) {
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError("cannot write " + path.string() + ": directory '" + dir.string() + "' does not exist");
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
  const std::size_t n = std::size_t(std::max(image.width, 0)) * std::size_t(std::max(image.height, 0));
  if (image.width < 1 || image.height < 1 || image.rgba.size() != 4 * n)
    throw InputError("cannot write " + path.string() + ": the image is empty or inconsistent");
  check_image_destination(path);  // before touching the file system

  const std::string ext = lower_extension(path);
  const fs::path tmp = temporary_beside(path);
  std::string why = write_file(tmp, image, ext == ".exr");
  if (why.empty()) {
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) why = ec.message();
  }
  if (!why.empty()) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw InputError("cannot write " + path.string() + ": " + why);
  }
}

RenderedImage read_image(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    const std::string why = take_global_oiio_error();
    throw InputError("cannot read " + path.string() + ": " + (why.empty() ? "unreadable image" : why));
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  if (spec.width < 1 || spec.height < 1 || channels < 1)
    throw InputError("cannot read " + path.string() + ": empty image");

  RenderedImage image;
  image.width = spec.width;
  image.height = spec.height;
  const std::size_t n = std::size_t(spec.width) * std::size_t(spec.height);
  std::vector<std::uint8_t> u8(n * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, u8.data()))
    throw InputError("cannot read " + path.string() + ": " + in->geterror());

  // 1 channel: grey; 2: grey + alpha; 3: RGB; 4 or more: RGBA (extra channels ignored).
  image.rgba.resize(4 * n);
  for (std::size_t p = 0; p < n; ++p) {
    const std::uint8_t* s = &u8[p * channels];
    const bool grey = channels < 3;
    for (int c = 0; c < 3; ++c) image.rgba[4 * p + c] = grey ? s[0] : s[c];
    image.rgba[4 * p + 3] = channels == 2 ? s[1] : channels >= 4 ? s[3] : 255;
  }

  // Float files keep their unquantized values, in levels.
  const OIIO::TypeDesc::BASETYPE base = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
  if (base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE) {
    std::vector<float> f(n * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, f.data()))
      throw InputError("cannot read " + path.string() + ": " + in->geterror());
    image.rgb_float.resize(3 * n);
    for (std::size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c)
        image.rgb_float[3 * p + c] = 255.0f * f[p * channels + (channels < 3 ? 0 : c)];
  }
  return image;
}

}  // namespace parashade
