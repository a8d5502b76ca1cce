#pragma once
// parashade's own reader for text OFF files. OpenMesh's reader takes the counts from the line after the
// header (skipping counts on the header line), knows no comments, never checks that a number parsed or
// that the file has not ended, and reserves memory for whatever count it read: fuzzing findings F4 and
// F6 (uninitialized counts and indices, allocations of gigabytes, face loops of 2^32 iterations).
#include <cstddef>
#include <filesystem>

#include <OpenMesh/Core/IO/importer/BaseImporter.hh>

namespace parashade::detail {

// Reads [ST][C][N]OFF in text form: the counts "vertices faces [edges]" on the header line or the next
// one, then one vertex per line (x y z, then nx ny nz for NOFF; colours and texture coordinates are
// ignored), then one face per line (n i1 ... in, an optional colour ignored). Comments (#) and blank
// lines are allowed anywhere. Vertices, normals and faces go to `importer`. Returns the number of faces.
// Throws InputError "<file>:<line>: <reason>" for a malformed header, a count the file is too small to
// hold, a vertex without three finite coordinates, a face with fewer than three vertices or an index out
// of range, a file that ends early, and for binary, 4D and nD OFF (not supported).
std::size_t read_off(const std::filesystem::path& path, OpenMesh::IO::BaseImporter& importer);

}  // namespace parashade::detail
