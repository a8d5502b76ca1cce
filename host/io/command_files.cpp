// A command's files, checked before the work (command_files.hpp).
#include "parashade/command_files.hpp"

#include <sys/stat.h>

#include "parashade/errors.hpp"
#include "parashade/image.hpp"
#include "parashade/output_file.hpp"

namespace parashade {
namespace {

namespace fs = std::filesystem;

// The same file: std::filesystem::equivalent where both exist, else the absolute paths with symbolic links
// resolved (an output not yet written may still be named through a link to an input's folder).
bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec_a, ec_b;
  if (fs::exists(a, ec_a) && fs::exists(b, ec_b)) {
    std::error_code ec;
    return fs::equivalent(a, b, ec);
  }
  std::error_code ec;
  return fs::weakly_canonical(fs::absolute(a, ec), ec) == fs::weakly_canonical(fs::absolute(b, ec), ec);
}

// What an existing destination is when it is not a regular file ("" when it is one or is absent). stat
// follows links: a link to a regular file is written through (StagedFile replaces its target).
std::string not_regular(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return "";
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISCHR(st.st_mode)) return "a character device";
  if (S_ISBLK(st.st_mode)) return "a block device";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

void check_destination(const std::string& option, const fs::path& path, OutputKind kind) {
  if (const std::string what = not_regular(path); !what.empty())
    throw InputError(option + ": cannot write " + path.string() + ": it is " + what +
                     ", not a regular file (an output is written beside it and renamed over it)");
  check_output_folder(option, path);
  if (kind == OutputKind::image) check_image_destination(path);
  if (kind == OutputKind::triangle_map) check_triangle_map_destination(path);
}

}  // namespace

void CommandFiles::input(const std::string& what, const fs::path& path) {
  if (!path.empty()) inputs_.push_back({what, path});
}

void CommandFiles::scene(const std::vector<fs::path>& read) {
  for (std::size_t i = 0; i < read.size(); ++i) input(i == 0 ? "the scene" : "a mesh of the scene", read[i]);
}

void CommandFiles::output(const std::string& option, const fs::path& path, OutputKind kind) {
  if (!path.empty()) outputs_.push_back({option, path, kind});
}

void CommandFiles::input_output(const std::string& option, const fs::path& path) {
  if (!path.empty()) outputs_.push_back({option, path, OutputKind::text});
}

void CommandFiles::check_apart() const {
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(outputs_[j].path, outputs_[i].path))
        throw UsageError(outputs_[j].name + " '" + outputs_[j].path.string() + "' and " + outputs_[i].name + " '" +
                         outputs_[i].path.string() + "' are the same file: one would overwrite the other");
}

void CommandFiles::check_folders() const {
  check_apart();
  for (const File& out : outputs_) check_output_folder(out.name, out.path);
}

void CommandFiles::check() const {
  check_apart();
  for (const File& out : outputs_)
    for (const File& in : inputs_)
      if (same_file(in.path, out.path))
        throw UsageError(out.name + " '" + out.path.string() + "' is the input file '" + in.path.string() + "' (" +
                         in.name + "): writing it would destroy the input");
  for (const File& out : outputs_) check_destination(out.name, out.path, out.kind);
}

}  // namespace parashade
