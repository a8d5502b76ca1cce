#include "mesh_file_scan.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "parashade/errors.hpp"
#include "parashade/memory_budget.hpp"

namespace parashade::detail {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

LineRead read_line(std::istream& in, std::string& line) {
  line.clear();
  std::streambuf* buf = in.rdbuf();
  using traits = std::char_traits<char>;
  int c = buf->sbumpc();
  if (c == traits::eof()) {
    in.setstate(std::ios::eofbit);
    return LineRead::end;
  }
  for (; c != traits::eof() && c != '\n'; c = buf->sbumpc()) {
    if (c == 0) return LineRead::nul;
    if (line.size() == kMaxMeshLineBytes) return LineRead::too_long;
    line += char(c);
  }
  return LineRead::line;
}

namespace {

class ObjChecker {
 public:
  explicit ObjChecker(const std::filesystem::path& path) : path_(path) {}

  ObjSummary run() {
    std::ifstream in(path_);
    if (!in) throw InputError(path_.string() + ": cannot open");
    std::string line;
    while (next_line(in, line)) {
      if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
      const std::vector<std::string> tokens = split(line);
      if (tokens.empty()) continue;
      const std::string& keyword = tokens[0];
      if (keyword == "v") {
        check_coordinates(tokens, "vertex");
        ++summary_.vertices;
      } else if (keyword == "vn") {
        check_coordinates(tokens, "normal");
        ++normals_;
      } else if (keyword == "vt") {
        ++texcoords_;
      } else if (keyword == "f") {
        check_face(tokens);
        ++summary_.faces;
        summary_.triangles += tokens.size() - 3;  // corners - 2
      }
      // Other records (o, g, s, usemtl, mtllib, l, p, ...) carry nothing the renderer uses.
    }
    if (in.bad()) throw InputError(path_.string() + ": read error");
    check_forward(max_vertex_, summary_.vertices, "vertex");
    check_forward(max_texcoord_, texcoords_, "texture coordinate");
    check_forward(max_normal_, normals_, "normal");
    return summary_;
  }

 private:
  // The next line, read byte by byte and bounded: a NUL byte is refused where it is read, so a file of one
  // endless line (a sparse file) is refused at once, not read into memory whole (issue 46, item 12).
  // OpenMesh's reader skips a record whose numbers stop at a NUL byte, shifting every later index
  // (fuzzing finding F1): refuse the byte rather than guess what it would do.
  bool next_line(std::istream& in, std::string& line) {
    const LineRead r = read_line(in, line);
    if (r == LineRead::end) return false;
    ++line_number_;
    if (r == LineRead::nul) fail(line_number_, "contains a NUL byte (not a text OBJ file?)");
    if (r == LineRead::too_long)
      fail(line_number_, "longer than " + std::to_string(kMaxMeshLineBytes) + " bytes (not a text OBJ file?)");
    return true;
  }

  // The largest positive index seen and its line: OpenMesh accepts faces before their vertices, so
  // positive indices are checked against the final counts.
  struct MaxIndex {
    long value = 0;
    std::size_t line = 0;
  };

  [[noreturn]] void fail(std::size_t line, const std::string& reason) const {
    throw InputError(path_.string() + ":" + std::to_string(line) + ": " + reason);
  }

  void check_coordinates(const std::vector<std::string>& tokens, const char* what) const {
    if (tokens.size() < 4) fail(line_number_, std::string(what) + " needs 3 coordinates");
    for (int i = 1; i <= 3; ++i) {
      const std::string& s = tokens[i];
      char* end = nullptr;
      const double value = std::strtod(s.c_str(), &end);
      if (end != s.c_str() + s.size() || s.empty()) fail(line_number_, "cannot read '" + s + "' as a number");
      if (!std::isfinite(value)) fail(line_number_, std::string(what) + " has a non-finite coordinate '" + s + "'");
    }
  }

  // One component of a face corner (v, vt or vn); an empty component is allowed only for vt and vn.
  void check_index(const std::string& s, std::size_t defined, MaxIndex& max, const char* what) {
    char* end = nullptr;
    const long value = std::strtol(s.c_str(), &end, 10);
    if (end != s.c_str() + s.size() || s.empty()) fail(line_number_, "cannot read '" + s + "' as a " + what + " index");
    if (value == 0) fail(line_number_, std::string(what) + " index 0 (OBJ indices start at 1)");
    if (value < 0) {  // relative to the records read so far; 0 - unsigned: -LONG_MIN would overflow
      if (std::size_t(0) - static_cast<std::size_t>(value) > defined)
        fail(line_number_, std::string(what) + " index " + s + " reaches before the first " + what);
    } else if (value > max.value) {
      max = {value, line_number_};
    }
  }

  void check_face(const std::vector<std::string>& tokens) {
    const std::size_t corners = tokens.size() - 1;
    if (corners < 3) fail(line_number_, "face has " + std::to_string(corners) + " vertices (needs at least 3)");
    for (std::size_t i = 1; i < tokens.size(); ++i) {
      const std::string& corner = tokens[i];
      const std::size_t slash1 = corner.find('/');
      check_index(corner.substr(0, slash1), summary_.vertices, max_vertex_, "vertex");
      if (slash1 == std::string::npos) continue;
      const std::size_t slash2 = corner.find('/', slash1 + 1);
      const std::string vt = corner.substr(slash1 + 1, slash2 == std::string::npos ? std::string::npos : slash2 - slash1 - 1);
      if (!vt.empty()) check_index(vt, texcoords_, max_texcoord_, "texture coordinate");
      if (slash2 == std::string::npos) continue;
      const std::string vn = corner.substr(slash2 + 1);
      if (!vn.empty()) check_index(vn, normals_, max_normal_, "normal");
    }
  }

  void check_forward(const MaxIndex& max, std::size_t defined, const char* what) const {
    if (static_cast<std::size_t>(max.value) > defined)
      fail(max.line, std::string(what) + " index " + std::to_string(max.value) + " out of range (the file has " +
                         std::to_string(defined) + ")");
  }

  std::filesystem::path path_;
  std::size_t line_number_ = 0;
  ObjSummary summary_;
  std::size_t normals_ = 0, texcoords_ = 0;
  MaxIndex max_vertex_, max_texcoord_, max_normal_;
};

}  // namespace

ObjSummary check_obj(const std::filesystem::path& path) { return ObjChecker(path).run(); }

void check_mesh_memory(const std::string& name, std::uint64_t triangles, std::uint64_t vertices) {
  check_host_bytes(name, estimate_host_bytes({{name, triangles, vertices}}, 0, 0),
                   std::to_string(triangles) + " triangles and " + std::to_string(vertices) + " vertices");
}

std::size_t count_stl_facets(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open");
  // Binary STL: 80-byte header, uint32 facet count, 50 bytes per facet. A text file that happens to have
  // exactly that size is not a concern in practice (it would have to match to the byte).
  // A file that does not start with "solid" is binary: its count must fit its size, and every vertex must
  // be finite (OpenMesh drops such facets silently, which ended in a misleading "no faces").
  const std::uintmax_t size = std::filesystem::file_size(path);
  if (size >= 84) {
    char header[84];
    in.read(header, sizeof header);
    std::uint32_t count = 0;
    std::memcpy(&count, header + 80, sizeof count);  // little-endian on every platform we target
    const std::uintmax_t expected = 84 + 50 * std::uintmax_t(count);
    const bool text = std::string(header, 5) == "solid";
    if (size == expected) {
      char facet[50];
      for (std::uint32_t f = 0; f < count && in.read(facet, sizeof facet); ++f) {
        float xyz[9];
        std::memcpy(xyz, facet + 12, sizeof xyz);  // after the facet normal: three vertices
        for (int k = 0; k < 9; ++k)
          if (!std::isfinite(xyz[k]))
            throw InputError(path.string() + ": binary STL facet " + std::to_string(f) + ", vertex " +
                             std::to_string(k / 3) + ": a coordinate is " + (std::isnan(xyz[k]) ? "NaN" : "infinite"));
      }
      return count;
    }
    if (!text)
      throw InputError(path.string() + ": binary STL whose header says " + std::to_string(count) + " facets (" +
                       std::to_string(expected) + " bytes) but the file has " + std::to_string(size) +
                       " bytes: truncated or a wrong count");
    in.seekg(0);
  }
  std::size_t facets = 0;
  std::string line;
  while (std::getline(in, line)) {
    const std::vector<std::string> tokens = split(line);
    if (!tokens.empty() && tokens[0] == "facet") ++facets;
  }
  return facets;
}

}  // namespace parashade::detail
