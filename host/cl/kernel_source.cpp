#include <map>
#include <set>
#include <sstream>
#include <string>

#include "parashade/device.hpp"
#include "parashade/errors.hpp"

namespace parashade {

const std::map<std::string, std::string>& embedded_kernel_files();  // generated at build time

namespace {

// An include names a file relative to the including one (units/counter.h's "classic.h", units/classic.h's
// "../fixed_point.h"), or else one in kernels/: the C preprocessor's order (the including file's folder,
// then the include path), so that the host's compiler (which has the repository root, not kernels/, on
// its path) and the kernels resolve the same name to the same file.
std::string resolve(const std::string& from, const std::string& name) {
  const auto slash = from.rfind('/');
  if (slash == std::string::npos) return name;
  std::string sibling = from.substr(0, slash + 1) + name;
  for (auto up = sibling.find("/../"); up != std::string::npos; up = sibling.find("/../")) {
    const auto start = sibling.rfind('/', up == 0 ? 0 : up - 1);
    sibling.erase(start == std::string::npos ? 0 : start + 1, up + 4 - (start == std::string::npos ? 0 : start + 1));
  }
  return embedded_kernel_files().count(sibling) ? sibling : name;
}

// PoCL resolves a kernel's #include against its own cache directory, not kernels/, so the host expands
// includes itself. Each file is expanded once; the headers also carry include guards.
void expand(const std::string& file, std::set<std::string>& seen, std::string& out) {
  const auto& files = embedded_kernel_files();
  const auto it = files.find(file);
  if (it == files.end()) throw DeviceError("kernel source '" + file + "' is not embedded in this build");
  if (!seen.insert(file).second) return;
  std::istringstream in(it->second);
  std::string line;
  int line_no = 0;
  out += "#line 1 \"" + file + "\"\n";
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 9, "#include ") == 0) {
      const auto open = line.find('"'), close = line.rfind('"');
      if (open != std::string::npos && close > open) {
        expand(resolve(file, line.substr(open + 1, close - open - 1)), seen, out);
        out += "#line " + std::to_string(line_no + 1) + " \"" + file + "\"\n";
        continue;
      }
    }
    out += line;
    out += '\n';
  }
}

}  // namespace

std::string kernel_source(const std::vector<std::string>& files) {
  std::set<std::string> seen;
  std::string out;
  for (const std::string& file : files) expand(file, seen, out);
  return out;
}

}  // namespace parashade
