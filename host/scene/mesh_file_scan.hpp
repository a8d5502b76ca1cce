#pragma once
// Checks that OpenMesh's readers skip. Its OBJ reader silently ignores records it cannot parse (a vertex
// that does not parse shifts every later index; a face with two vertices vanishes), and its OFF reader
// goes on with stale values when a number does not parse or the file ends early (OFF is therefore read by
// parashade itself: off_reader.hpp), so OBJ files are checked line by line before OpenMesh reads them. Its STL reader drops facets with coincident
// corners before the importer sees them, so STL facets are counted here to report how many were dropped.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace parashade::detail {

struct ObjSummary {
  std::size_t vertices = 0;
  std::size_t faces = 0;
};

// Throws InputError "<file>:<line>: <reason>" for a vertex or normal without three finite coordinates, a
// face with fewer than three vertices, or a vertex/normal/texture index that is zero, malformed or out
// of range.
ObjSummary check_obj(const std::filesystem::path& path);

// For a PLY file: checks the header before OpenMesh parses it (its parser crashes on a property before any
// element and loops forever without end_header: fuzzing findings F2, F3), and that the file can hold the
// records the header declares, so that a corrupt count fails here and not in an allocation sized by it
// (F4). Throws InputError "<file>: <reason>" naming the count and the bytes it needs.
void check_ply(const std::filesystem::path& path);

// The whitespace-separated tokens of a line.
std::vector<std::string> split(const std::string& line);

// Facets in an STL file: from the header of a binary file, by counting "facet" records in a text file.
std::size_t count_stl_facets(const std::filesystem::path& path);

}  // namespace parashade::detail
