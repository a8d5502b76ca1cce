#include "off_reader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "mesh_file_scan.hpp"
#include "parashade/errors.hpp"

namespace parashade::detail {

namespace {

// The shortest text a record can take: "0 0 0\n" for a vertex, "3 0 1 2\n" for a face.
constexpr std::uintmax_t kMinVertexBytes = 6;
constexpr std::uintmax_t kMinFaceBytes = 8;

class OffReader {
 public:
  OffReader(const std::filesystem::path& path, OpenMesh::IO::BaseImporter& importer)
      : path_(path), in_(path, std::ios::binary), importer_(importer) {}

  std::size_t run() {
    if (!in_) throw InputError(path_.string() + ": cannot open");
    std::vector<std::string> tokens = next_record();
    if (tokens.empty()) fail("no OFF header");
    const bool normals = read_header_keyword(tokens[0]);
    if (tokens.size() > 1 && tokens[1] == "BINARY")
      fail("binary OFF is not supported (convert it to text OFF, PLY or OBJ)");
    tokens.erase(tokens.begin());
    if (tokens.empty()) tokens = next_record();  // the counts may follow on the header line
    if (tokens.size() < 2 || tokens.size() > 3) fail("expected the counts 'vertices faces [edges]'");
    const long vertices = count(tokens[0]), faces = count(tokens[1]);
    check_counts_fit(vertices, faces);
    check_mesh_memory(path_.string(), std::uint64_t(faces), std::uint64_t(vertices));

    std::vector<OpenMesh::VertexHandle> handles;
    handles.reserve(static_cast<std::size_t>(vertices));
    for (long v = 0; v < vertices; ++v) {
      tokens = next_record();
      if (tokens.empty()) fail("the file ends after " + std::to_string(v) + " of " + std::to_string(vertices) + " vertices");
      const std::size_t needed = normals ? 6 : 3;
      if (tokens.size() < needed) fail(normals ? "NOFF vertex needs 3 coordinates and 3 normal components" : "vertex needs 3 coordinates");
      const OpenMesh::Vec3f p(number(tokens[0], "coordinate"), number(tokens[1], "coordinate"), number(tokens[2], "coordinate"));
      handles.push_back(importer_.add_vertex(p));
      if (normals)  // non-finite normals are the importer's to refuse, as for the other formats
        importer_.set_normal(handles.back(), OpenMesh::Vec3f(value(tokens[3]), value(tokens[4]), value(tokens[5])));
    }
    OpenMesh::IO::BaseImporter::VHandles corners;
    for (long f = 0; f < faces; ++f) {
      tokens = next_record();
      if (tokens.empty()) fail("the file ends after " + std::to_string(f) + " of " + std::to_string(faces) + " faces");
      const long n = integer(tokens[0]);
      if (n < 3) fail("face has " + tokens[0] + " vertices (needs at least 3)");
      if (tokens.size() < std::size_t(n) + 1) fail("face lists fewer than its " + tokens[0] + " vertices");
      corners.clear();
      for (long k = 1; k <= n; ++k) {
        const long index = integer(tokens[k]);
        if (index < 0 || index >= vertices)
          fail("vertex index " + tokens[k] + " out of range (the file has " + std::to_string(vertices) + ")");
        corners.push_back(handles[static_cast<std::size_t>(index)]);
      }
      importer_.add_face(corners);  // anything after the indices is a colour: ignored
    }
    return static_cast<std::size_t>(faces);
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(path_.string() + ":" + std::to_string(line_number_) + ": " + reason);
  }

  // [ST][C][N]OFF; returns whether vertices carry normals.
  bool read_header_keyword(const std::string& keyword) const {
    const std::size_t off = keyword.rfind("OFF");
    if (off == std::string::npos || off + 3 != keyword.size()) fail("no OFF header ('" + keyword + "')");
    std::string prefix = keyword.substr(0, off);
    if (prefix.find_first_of("4n") != std::string::npos) fail("4D and nD OFF files are not supported");
    if (prefix.rfind("ST", 0) == 0) prefix.erase(0, 2);
    if (!prefix.empty() && prefix[0] == 'C') prefix.erase(0, 1);
    const bool normals = !prefix.empty() && prefix[0] == 'N';
    if (normals) prefix.erase(0, 1);
    if (!prefix.empty()) fail("unknown OFF header '" + keyword + "'");
    return normals;
  }

  // Counts beyond what the file could hold fail before anything is reserved for them (finding F4).
  void check_counts_fit(long vertices, long faces) const {
    const std::uintmax_t size = std::filesystem::file_size(path_);
    const std::uintmax_t needed =
        static_cast<std::uintmax_t>(vertices) * kMinVertexBytes + static_cast<std::uintmax_t>(faces) * kMinFaceBytes;
    if (needed > size + 1)  // the last record may lack its newline
      fail("the header declares " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
           " faces (at least " + std::to_string(needed) + " bytes), but the file has " + std::to_string(size) +
           " bytes: corrupt or truncated");
  }

  long integer(const std::string& s) const {
    errno = 0;
    char* end = nullptr;
    const long value = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE) fail("cannot read '" + s + "' as an integer");
    return value;
  }

  long count(const std::string& s) const {
    const long value = integer(s);
    if (value < 0 || value > INT32_MAX) fail("count '" + s + "' is not from 0 to 2147483647");
    return value;
  }

  double value(const std::string& s) const {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size()) fail("cannot read '" + s + "' as a number");
    return v;
  }

  float number(const std::string& s, const char* what) const {
    const double v = value(s);
    if (!std::isfinite(v)) fail(std::string("vertex has a non-finite ") + what + " '" + s + "'");
    return static_cast<float>(v);
  }

  // The tokens of the next line that is not blank or a comment; empty at the end of the file.
  std::vector<std::string> next_record() {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_number_;
      if (line.find('\0') != std::string::npos) fail("contains a NUL byte (not a text OFF file?)");
      if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
      std::vector<std::string> tokens = split(line);
      if (!tokens.empty()) return tokens;
    }
    if (in_.bad()) fail("read error");
    return {};
  }

  std::filesystem::path path_;
  std::ifstream in_;
  OpenMesh::IO::BaseImporter& importer_;
  std::size_t line_number_ = 0;
};

}  // namespace

std::size_t read_off(const std::filesystem::path& path, OpenMesh::IO::BaseImporter& importer) {
  return OffReader(path, importer).run();
}

}  // namespace parashade::detail
