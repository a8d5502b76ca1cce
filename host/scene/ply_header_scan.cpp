// The PLY header check of mesh_file_scan.hpp: a header OpenMesh's parser can take, and counts the file
// can hold.
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "mesh_file_scan.hpp"
#include "parashade/errors.hpp"

namespace parashade::detail {

namespace {

// The scalar types OpenMesh's PLY reader knows, with their size in a binary file.
const std::map<std::string, int>& scalar_sizes() {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1}, {"int8", 1},   {"uint8", 1},  {"short", 2},   {"ushort", 2},
      {"int16", 2}, {"uint16", 2}, {"int", 4},   {"uint", 4},   {"int32", 4},   {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  return sizes;
}

bool is_integer_type(const std::string& type) {
  return type != "float" && type != "float32" && type != "double" && type != "float64";
}

// Far beyond any real file; they keep the size arithmetic below 2^64.
constexpr std::size_t kMaxElements = 1024;
constexpr std::uint64_t kMaxProperties = 4096;

struct Property {
  bool list = false;
  std::string length_type;  // list only
  std::string type;         // the scalar, or the list's item type
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_binary_bytes = 0;  // per record: the scalars, and each list's length field
  std::uint64_t properties = 0;
  std::vector<Property> layout;
};

// The largest value of an integer type (list lengths).
std::uint64_t type_max(const std::string& type) {
  const int bytes = scalar_sizes().at(type);
  const bool is_signed = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
  return (std::uint64_t(1) << (8 * bytes - (is_signed ? 1 : 0))) - 1;
}

class PlyHeaderChecker {
 public:
  explicit PlyHeaderChecker(const std::filesystem::path& path) : path_(path) {}

  void run() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw InputError(path_.string() + ": cannot open");
    std::string format;
    std::string line;
    bool ended = false;
    for (LineRead r; (r = read_line(in, line)) != LineRead::end;) {
      ++line_number_;
      if (r != LineRead::line) fail(r == LineRead::nul ? "a NUL byte in the header" : "a header line longer than 1 MiB");
      const std::vector<std::string> tokens = split(line);
      if (line_number_ == 1) {
        if (tokens.size() != 1 || tokens[0] != "ply") fail("no 'ply' magic line");
        continue;
      }
      if (tokens.empty()) fail("blank header line");
      const std::string& keyword = tokens[0];
      if (keyword == "comment") continue;
      if (keyword == "obj_info") {
        // OpenMesh's reader skips only the word obj_info and reads the words after it as header lines:
        // "obj_info element 5" made it loop forever (fuzz finding F13).
        for (std::size_t k = 1; k < tokens.size(); ++k)
          if (tokens[k] == "element" || tokens[k] == "property" || tokens[k] == "format" || tokens[k] == "end_header")
            fail("obj_info line holds the header keyword '" + tokens[k] +
                 "' (OpenMesh's reader would take it for a header line)");
        continue;
      }
      if (keyword == "end_header") {
        ended = true;
        break;
      }
      if (keyword == "format") {
        if (!format.empty()) fail("a second format line");
        if (tokens.size() != 3 || tokens[2] != "1.0" ||
            (tokens[1] != "ascii" && tokens[1] != "binary_little_endian" && tokens[1] != "binary_big_endian"))
          fail("unsupported format line '" + line + "'");
        format = tokens[1];
      } else if (format.empty()) {
        fail("'" + keyword + "' before the format line");
      } else if (keyword == "element") {
        if (tokens.size() != 3) fail("element line needs a name and a count");
        if (elements_.size() >= kMaxElements) fail("more than " + std::to_string(kMaxElements) + " elements");
        // OpenMesh's reader loops over the last face element's count for every face element (fuzz finding
        // F14): a second one shifts its reads, and a value taken for a list length reserved gigabytes.
        if (tokens[1] == "vertex" || tokens[1] == "face")
          for (const Element& e : elements_)
            if (e.name == tokens[1]) fail("a second '" + tokens[1] + "' element (OpenMesh's reader reads only one)");
        elements_.push_back({tokens[1], count(tokens[2]), 0, 0, {}});
      } else if (keyword == "property") {
        add_property(tokens);
      } else {
        fail("unknown header line '" + keyword + "'");
      }
    }
    if (!ended) fail("the header has no end_header line");
    if (format.empty()) fail("no format line");
    const auto header_end = in.tellg();
    if (header_end < 0) fail("cannot find the end of the header");
    body_start_ = static_cast<std::uintmax_t>(header_end);
    const std::uintmax_t body = std::filesystem::file_size(path_) - body_start_;
    check_sizes(format == "ascii", body);
    check_memory();
    // OpenMesh's body readers trust every list length and every number (a length it cannot read loops
    // 2^32 times at the end of the file): walk the body once to make sure it holds what the header says.
    if (format == "ascii") {
      check_ascii_body(in);
    } else {
      check_binary_body(in, format == "binary_big_endian", body);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(path_.string() + ":" + std::to_string(line_number_) + ": " + reason);
  }

  std::uint64_t count(const std::string& s) const {
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(s.c_str(), &end, 10);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE || value < 0 || value > INT32_MAX)
      fail("element count '" + s + "' is not an integer from 0 to 2147483647");
    return static_cast<std::uint64_t>(value);
  }

  int scalar(const std::string& type) const {
    const auto it = scalar_sizes().find(type);
    if (it == scalar_sizes().end()) fail("unknown property type '" + type + "'");
    return it->second;
  }

  void add_property(const std::vector<std::string>& tokens) {
    if (elements_.empty()) fail("a property before any element");
    Element& e = elements_.back();
    if (e.properties >= kMaxProperties) fail("more than " + std::to_string(kMaxProperties) + " properties");
    if (tokens.size() == 5 && tokens[1] == "list") {
      const int length_bytes = scalar(tokens[2]);
      scalar(tokens[3]);
      if (!is_integer_type(tokens[2])) fail("list length type '" + tokens[2] + "' is not an integer type");
      // OpenMesh reads any other list as one value (F14): the values after it would be read out of place.
      const bool vertex_indices = e.name == "face" && (tokens[4] == "vertex_indices" || tokens[4] == "vertex_index");
      if (!vertex_indices)
        fail("list property '" + tokens[4] + "' of element '" + e.name +
             "' (OpenMesh's reader reads only the face element's vertex_indices as a list)");
      if (!is_integer_type(tokens[3])) fail("vertex index type '" + tokens[3] + "' is not an integer type");
      e.min_binary_bytes += static_cast<std::uint64_t>(length_bytes);
      e.layout.push_back({true, tokens[2], tokens[3]});
    } else if (tokens.size() == 3) {
      e.min_binary_bytes += static_cast<std::uint64_t>(scalar(tokens[1]));
      e.layout.push_back({false, "", tokens[1]});
    } else {
      fail("property line needs a type and a name");
    }
    ++e.properties;
  }

  // A binary record takes at least min_binary_bytes; an ASCII one at least one character and a separator
  // per property (the last record may lack its final separator).
  void check_sizes(bool ascii, std::uintmax_t body) const {
    std::uint64_t needed = 0;
    for (const Element& e : elements_) {
      if (e.count == 0) continue;
      if (e.properties == 0)
        throw InputError(path_.string() + ": element '" + e.name + "' declares " + std::to_string(e.count) +
                         " records without properties");
      const std::uint64_t per_record = ascii ? 2 * e.properties : e.min_binary_bytes;
      const std::uint64_t bytes = e.count * per_record;  // < 2^31 * 2^31: no overflow
      needed += bytes;
      if (needed > body + (ascii ? 1 : 0))
        throw InputError(path_.string() + ": the header declares " + std::to_string(e.count) + " " + e.name +
                         " records (at least " + std::to_string(bytes) + " bytes), but only " +
                         std::to_string(body) + " bytes follow the header: corrupt or truncated");
    }
  }

  // The counts the file can hold, against the host memory limit, before the body is walked or read: a
  // sparse file can hold hundreds of millions of vertices (issue 46, item 12). Faces as triangles.
  void check_memory() const {
    std::uint64_t vertices = 0, faces = 0;
    for (const Element& e : elements_) {
      if (e.name == "vertex") vertices = e.count;
      if (e.name == "face") faces = e.count;
    }
    check_mesh_memory(path_.string(), faces, vertices);
  }

  [[noreturn]] void fail_record(const Element& e, std::uint64_t record, const std::string& reason) const {
    throw InputError(path_.string() + ": " + e.name + " record " + std::to_string(record) + ": " + reason);
  }

  // Every value a token that reads whole as its type (integers as integers, floats finite), every list
  // length within its type; the file may end with whitespace only.
  void check_ascii_body(std::ifstream& in) const {
    std::string token;
    for (const Element& e : elements_) {
      for (std::uint64_t r = 0; r < e.count; ++r) {
        for (const Property& p : e.layout) {
          if (!(in >> token)) fail_record(e, r, "the file ends early");
          if (p.list) {
            const long long n = ascii_integer(e, r, token, p.length_type);
            if (n < 0 || std::uint64_t(n) > type_max(p.length_type))
              fail_record(e, r, "list length " + token + " out of range for " + p.length_type);
            for (long long k = 0; k < n; ++k) {
              if (!(in >> token)) fail_record(e, r, "the file ends inside a list of " + std::to_string(n));
              ascii_value(e, r, token, p.type);
            }
          } else {
            ascii_value(e, r, token, p.type);
          }
        }
      }
    }
  }

  long long ascii_integer(const Element& e, std::uint64_t r, const std::string& token, const std::string& type) const {
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(token.c_str(), &end, 10);
    if (end != token.c_str() + token.size() || errno == ERANGE)
      fail_record(e, r, "cannot read '" + token + "' as " + type);
    return v;
  }

  void ascii_value(const Element& e, std::uint64_t r, const std::string& token, const std::string& type) const {
    if (is_integer_type(type)) {
      ascii_integer(e, r, token, type);
      return;
    }
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size()) fail_record(e, r, "cannot read '" + token + "' as " + type);
    if (!std::isfinite(v)) fail_record(e, r, "non-finite value '" + token + "'");
  }

  // Walks the records: fixed-size scalars skipped, each list's length read (in the file's byte order)
  // and its items skipped, never past the end of the file.
  void check_binary_body(std::ifstream& in, bool big_endian, std::uintmax_t body) const {
    std::uintmax_t offset = 0;
    for (const Element& e : elements_) {
      for (std::uint64_t r = 0; r < e.count; ++r) {
        for (const Property& p : e.layout) {
          std::uint64_t bytes = static_cast<std::uint64_t>(scalar_sizes().at(p.type));
          if (p.list) {
            const int length_bytes = scalar_sizes().at(p.length_type);
            if (offset + length_bytes > body) fail_record(e, r, "the file ends early");
            unsigned char raw[8] = {};
            in.seekg(static_cast<std::streamoff>(body_start_ + offset));
            in.read(reinterpret_cast<char*>(raw), length_bytes);
            std::uint64_t n = 0;
            for (int k = 0; k < length_bytes; ++k) {
              const unsigned char byte = raw[big_endian ? k : length_bytes - 1 - k];
              n = (n << 8) | byte;
            }
            const bool negative = type_max(p.length_type) < (std::uint64_t(1) << (8 * length_bytes)) - 1 &&
                                  (n >> (8 * length_bytes - 1)) != 0;
            if (negative) fail_record(e, r, "negative list length");
            offset += static_cast<std::uint64_t>(length_bytes);
            bytes *= n;  // n < 2^32, item size <= 8: no overflow
          }
          if (bytes > body - offset) fail_record(e, r, "the file ends early");
          offset += bytes;
        }
      }
    }
  }

  std::filesystem::path path_;
  std::size_t line_number_ = 0;
  std::vector<Element> elements_;
  std::uintmax_t body_start_ = 0;
};

}  // namespace

void check_ply(const std::filesystem::path& path) { PlyHeaderChecker(path).run(); }

}  // namespace parashade::detail
