#pragma once
// Checks that OpenMesh's readers skip. Its OBJ reader silently ignores records it cannot parse (a vertex
// that does not parse shifts every later index; a face with two vertices vanishes), and its OFF reader
// goes on with stale values when a number does not parse or the file ends early (OFF is therefore read by
// parashade itself: off_reader.hpp), so OBJ files are checked line by line before OpenMesh reads them. Its STL reader drops facets with coincident
// corners before the importer sees them, so STL facets are counted here to report how many were dropped.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

namespace parashade::detail {

struct ObjSummary {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t triangles = 0;  // the faces fanned into triangles
};

// Lines of a text mesh file (OBJ, a PLY header) are read byte by byte up to this length and to their
// first NUL byte: a file of one endless line (a sparse file of NUL bytes) is refused at once instead of
// read into memory whole (issue 46, item 12).
constexpr std::size_t kMaxMeshLineBytes = 1 << 20;
enum class LineRead { line, end, nul, too_long };
// The next line without its '\n' into `line`; `end` at the end of the file, `nul` at a NUL byte,
// `too_long` past kMaxMeshLineBytes (the line then holds what was read).
LineRead read_line(std::istream& in, std::string& line);

// Throws InputError "<name>: T triangles and V vertices would take about X of host memory, more than the
// limit ..." (memory_budget.hpp): a mesh's counts, known from its scan or header, budgeted before the
// reader allocates anything for them.
void check_mesh_memory(const std::string& name, std::uint64_t triangles, std::uint64_t vertices);

// Throws InputError "<file>:<line>: <reason>" for a vertex or normal without three finite coordinates, a
// face with fewer than three vertices, or a vertex/normal/texture index that is zero, malformed or out
// of range.
ObjSummary check_obj(const std::filesystem::path& path);

// For a PLY file: checks the header before OpenMesh parses it (its parser crashes on a property before any
// element and loops forever without end_header: fuzzing findings F2, F3), and that the file can hold the
// records the header declares, so that a corrupt count fails here and not in an allocation sized by it
// (F4), and that the host memory limit can hold them (check_mesh_memory), before the body is walked.
// Throws InputError "<file>: <reason>" naming the count and the bytes it needs.
void check_ply(const std::filesystem::path& path);

// The whitespace-separated tokens of a line.
std::vector<std::string> split(const std::string& line);

// Facets in an STL file: from the header of a binary file, by counting "facet" records in a text file.
std::size_t count_stl_facets(const std::filesystem::path& path);

}  // namespace parashade::detail
