#pragma once
// A bench tool's --json file. Its temporary file is created when the tool starts, so a path that cannot be
// written fails before the measurement rather than after it; write() then puts the whole JSON in place
// (output_file.hpp: a failure or SIGINT/SIGTERM leaves no partial file and an existing one untouched).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "parashade/output_file.hpp"

namespace parashade {

class JsonOutput {
 public:
  // An empty path: no file, and write() does nothing. Throws InputError naming a path it cannot write.
  explicit JsonOutput(const std::string& path) {
    if (path.empty()) return;
    install_signal_cleanup();
    file_.emplace(path);
    file_->open_fd();
  }

  void write(const nlohmann::json& j) {
    if (!file_) return;
    const std::string text = j.dump(1) + "\n";
    file_->pwrite_all(text.data(), text.size(), 0);
    file_->close_fd();
    file_->commit();  // throws InputError naming the path if a write failed
  }

 private:
  std::optional<StagedFile> file_;
};

}  // namespace parashade
