#pragma once
// Checks that OpenMesh's readers skip. Its OBJ reader silently ignores records it cannot parse (a vertex
// that does not parse shifts every later index; a face with two vertices vanishes), and its OFF reader
// goes on with stale values when a number does not parse or the file ends early, so OBJ and text OFF
// files are checked line by line before OpenMesh reads them. Its STL reader drops facets with coincident
// corners before the importer sees them, so STL facets are counted here to report how many were dropped.
#include <cstddef>
#include <filesystem>

namespace parashade::detail {

struct ObjSummary {
  std::size_t vertices = 0;
  std::size_t faces = 0;
};

// Throws InputError "<file>:<line>: <reason>" for a vertex or normal without three finite coordinates, a
// face with fewer than three vertices, or a vertex/normal/texture index that is zero, malformed or out
// of range.
ObjSummary check_obj(const std::filesystem::path& path);

// For a text OFF file (OFF, COFF, NOFF, CNOFF, STOFF... in one vertex or face per line): throws
// InputError "<file>:<line>: <reason>" for a malformed header, a vertex without three finite
// coordinates, a face with fewer than three vertices or an index out of range, or a file that ends
// early. Returns the face count. Binary and 4D/nD OFF files are left to OpenMesh (returns 0).
std::size_t check_off(const std::filesystem::path& path);

// Facets in an STL file: from the header of a binary file, by counting "facet" records in a text file.
std::size_t count_stl_facets(const std::filesystem::path& path);

}  // namespace parashade::detail
