#pragma once
// Every file a command reads and writes, declared in one place before any work. check() refuses what
// would lose data: an output that is one of the inputs or another output (compared as files, through
// links), and a destination that exists but is not a regular file (a device such as /dev/full, a FIFO, a
// folder), which renaming a finished file into place would replace. Every command builds one.
#include <filesystem>
#include <string>
#include <vector>

namespace parashade {

// What an output holds, for the checks its format needs.
enum class OutputKind {
  text,          // a report, a cache, a table: any name
  image,         // an image: an extension OpenImageIO writes
  triangle_map,  // an ID buffer: a lossless 8-bit format (png, tif, ppm)
};

class CommandFiles {
 public:
  // A file the command reads; `what` names it in messages ("the scene", "--tune-cache"). Empty: none.
  void input(const std::string& what, const std::filesystem::path& path);
  // The files a scene was read from (load_scene's list: the scene file, then its meshes).
  void scene(const std::vector<std::filesystem::path>& read);
  // A file the command writes; `option` is how the command line named it ("-o", "--report"). Empty: the
  // option was not given.
  void output(const std::string& option, const std::filesystem::path& path, OutputKind kind = OutputKind::text);
  // A file read and then rewritten (tune's --cache): no other output may be it.
  void input_output(const std::string& option, const std::filesystem::path& path);

  // Throws UsageError (exit 2) for an output that is an input or another output, InputError (exit 3) for a
  // destination that is not a regular file, a folder that does not exist or an image format no writer
  // knows. Call after every input is known (a scene's meshes are read with the scene) and before the work.
  void check() const;
  // The cheap part of check(), for before a scene is loaded (which may take many seconds): no two outputs
  // are one file (UsageError), and every output's folder exists and is a folder (InputError naming the
  // option, the file and the folder).
  void check_folders() const;

 private:
  void check_apart() const;  // no output is another output
  struct File {
    std::string name;
    std::filesystem::path path;
    OutputKind kind = OutputKind::text;
  };
  std::vector<File> inputs_, outputs_;
};

}  // namespace parashade
