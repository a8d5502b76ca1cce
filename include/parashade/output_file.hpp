#pragma once
// Output files that appear whole or not at all: written under a hidden temporary name beside the
// destination, checked write by write, and renamed into place only when every write and the close
// succeeded. A failure removes the temporary file and leaves an existing destination untouched; so does
// SIGINT or SIGTERM (install_signal_cleanup). A replaced file keeps its permission bits; a destination
// that is a symbolic link is written through (its target is replaced, the link stays).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace parashade {

class StagedFile {
 public:
  // Picks ".NAME.tmp-PID-N.EXT" beside `destination` (same file system; same extension, which image
  // writers read the format from) and registers it for removal on a signal. Creates nothing yet.
  explicit StagedFile(std::filesystem::path destination);
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;
  StagedFile(const StagedFile&) = delete;
  ~StagedFile();  // removes the temporary file unless committed

  const std::filesystem::path& destination() const { return destination_; }
  const std::filesystem::path& temporary() const { return temporary_; }

  // Opens the temporary file for writing (mode 0666 less the umask); throws InputError.
  int open_fd();
  // Writes all of `size` bytes at `offset` of the open file; false (errno kept in error()) on failure.
  bool pwrite_all(const void* data, std::size_t size, std::size_t offset);
  // Closes the file; false with error() on failure (a deferred write error shows here).
  bool close_fd();
  // The first failure's text ("No space left on device"), empty when none.
  const std::string& error() const { return error_; }
  void fail(const std::string& why);

  // Renames the temporary file over the destination, after giving it the destination's permission bits
  // when the destination exists. Throws InputError naming the destination if anything failed before.
  void commit();

 private:
  void discard() noexcept;
  std::filesystem::path destination_, temporary_;
  int fd_ = -1;
  int slot_ = -1;  // the signal handler's registry slot
  bool committed_ = false;
  std::string error_;
};

// Throws InputError "<option>: cannot write PATH: directory 'DIR' does not exist" (or "'DIR' is not a
// folder", or the system's reason) unless the folder `path` goes into is a folder. `option` may be empty.
void check_output_folder(const std::string& option, const std::filesystem::path& path);

struct RenderedImage;  // image.hpp

// write_image (image.hpp) without the final rename: the image is in the returned file's temporary()
// until commit(), so that several outputs can be written first and replace their destinations only when
// all of them were written. Every write of OpenImageIO's plugins is checked; TIFF and EXR get no time
// stamp, so identical runs write identical bytes. Throws InputError (the temporary file removed).
StagedFile stage_image(const std::filesystem::path& path, const RenderedImage& image);

// One float channel ("Y") of `values` (width x height, row 0 at the top; NaN kept) as an OpenEXR file, staged
// like stage_image: the per-pixel error maps' values (render --error-map, compare --error-map, --flip-map).
// Throws InputError for a size mismatch, a path that is not .exr or an unwritable one.
StagedFile stage_values(const std::filesystem::path& path, const std::vector<float>& values, int width, int height);

// True when `path` names an OpenEXR file (.exr, any case): the float format, where maps hold values.
bool is_exr(const std::filesystem::path& path);

// Writes `text` into a staged file (not yet renamed; commit() it). Throws InputError naming the path and
// the system's error.
StagedFile stage_text(const std::filesystem::path& path, const std::string& text);

// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1 and SIGUSR2 remove every staged temporary file and end the
// process with 128 + the signal (only unlink and _exit in the handler); one ignored when the process
// started stays ignored. Call once, early in main.
void install_signal_cleanup();
// Takes SIGQUIT and SIGUSR1 back from a library that replaced the handler (LLVM, inside PoCL, does when it
// first compiles or links a kernel, and then swallows both). Cheap: called after kernel builds, after each
// frame and whenever a staged file is created.
void reclaim_signal_cleanup();

}  // namespace parashade
