// Regression tests for the mesh-loader findings of the fuzzers (docs/robustness.md, F1-F4 and F6): each
// input crashed, hung, allocated gigabytes or read uninitialized memory before the fix, and must now be
// refused with an InputError that names the file, or load as the file says.
#include <gtest/gtest.h>

#include <string>

#include "parashade/errors.hpp"
#include "parashade/mesh.hpp"
#include "parashade/scene.hpp"
#include "temp_dir.hpp"

namespace parashade {
namespace {

using testing_support::TempDir;
using namespace std::string_literals;

// The message of the InputError that loading `text` as `name` throws ("" when it loads).
std::string refusal(const std::string& name, const std::string& text, std::string* path_out = nullptr) {
  TempDir dir;
  const std::filesystem::path p = dir.write(name, text);
  if (path_out) *path_out = p.string();
  try {
    load_mesh(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_refused(const std::string& name, const std::string& text, const std::string& says) {
  std::string path;
  const std::string message = refusal(name, text, &path);
  ASSERT_FALSE(message.empty()) << name << " loaded";
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find(says), std::string::npos) << message;
}

std::size_t triangles(const std::string& name, const std::string& text) {
  TempDir dir;
  return load_mesh(dir.write(name, text)).triangles.size();
}

// F1: strtod stopped at the NUL byte and the pre-scan took "0\0" for a number; OpenMesh skipped the vertex
// and then wrote a normal past the end of its 2-vertex array (heap overflow, abort in a release build).
TEST(FuzzFindingF1, NulByteInAnObjVertexIsRefused) {
  expect_refused("nul.obj", "v 0 0 0\nv 1 0 0\nv 0\0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"s,
                 ":3: contains a NUL byte");
  expect_refused("nul_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\0\n"s, ":4: contains a NUL byte");
}

// F2: OpenMesh's header parser appended a property to the last element of an empty list (SIGSEGV).
TEST(FuzzFindingF2, PlyPropertyBeforeAnyElementIsRefused) {
  expect_refused("f2.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", ":3: a property before any element");
}

// F13: OpenMesh's header parser reads the words after obj_info as header lines; "element aecf3" there
// (an element whose count is the next line's first word) made it loop forever writing errors.
TEST(FuzzFindingF13, PlyObjInfoWithAHeaderKeywordIsRefused) {
  const std::string body = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_refused("f13.ply", "ply\nformat ascii 1.0\n" + body + "obj_info element aecf3 \n" + face,
                 ":7: obj_info line holds the header keyword 'element'");
  expect_refused("f13b.ply", "ply\nformat ascii 1.0\n" + body + "obj_info property float w\n" + face, "'property'");
  // Free text after obj_info (as real files have it) still loads.
  EXPECT_EQ(triangles("f13c.ply", "ply\nformat ascii 1.0\nobj_info vtkPolyData points and polygons: vtk4.0\n" + body + face),
            1u);
}

// F14 (CI fuzzing run on 54e5908): OpenMesh's reader reads a list other than the face's vertex_indices as
// one value, and loops every face element over the last face element's count; either way a value ends up
// read as a face's list length, and a 237-byte file asked for gigabytes of vertex handles (libFuzzer OOM).
TEST(FuzzFindingF14, PlyListsOpenMeshWouldMisreadAreRefused) {
  const std::string vertices =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string data = "0 0 0\n1 0 0\n0 1 0\n";
  expect_refused("other_list.ply",
                 "ply\nformat ascii 1.0\n" + vertices + "element extra 1\nproperty list uchar int stuff\n"
                 "element face 1\nproperty list int int vertex_indices\nend_header\n" + data + "1 2000000000\n3 0 1 2\n",
                 "list property 'stuff' of element 'extra'");
  expect_refused("two_faces.ply",
                 "ply\nformat ascii 1.0\n" + vertices + "element face 1\nproperty list uchar int vertex_indices\n"
                 "element face 2\nproperty int foo\nend_header\n" + data + "3 0 1 2\n2000000000 5\n",
                 "a second 'face' element");
  expect_refused("float_indices.ply",
                 "ply\nformat ascii 1.0\n" + vertices + "element face 1\nproperty list uchar float vertex_indices\n"
                 "end_header\n" + data + "3 0 1.5 2\n",
                 "vertex index type 'float'");
  // Scalar face properties beside the vertex indices (colours, as real files have them) still load.
  EXPECT_EQ(triangles("face_colour.ply", "ply\nformat ascii 1.0\n" + vertices +
                                             "element face 1\nproperty list uchar int vertex_index\nproperty uchar red\n"
                                             "end_header\n" + data + "3 0 1 2 200\n"),
            1u);
}

// F3: without end_header OpenMesh's header parser looped forever at the end of the file, growing memory.
TEST(FuzzFindingF3, PlyWithoutEndHeaderIsRefused) {
  expect_refused("f3.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", "no end_header");
  expect_refused("f3_type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty floaty x\n",
                 ":4: unknown property type 'floaty'");
  expect_refused("f3_keyword.ply", "ply\nformat ascii 1.0\nelemnt vertex 3\nend_header\n", "unknown header line 'elemnt'");
}

// F4: a count in the header sized an allocation (8 GB for a 200-byte PLY). Now the count is compared
// with the bytes that follow the header, and the message names the count and the size it needs.
TEST(FuzzFindingF4, PlyCountsBeyondTheFileAreRefusedBeforeAllocating) {
  expect_refused("huge.ply",
                 "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n",
                 "2000000000 vertex records (at least 12000000000 bytes), but only 6 bytes follow");
  // Binary: 3 floats per vertex, 12 bytes each record; 2 records declared, one present.
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  binary.append(12, '\0');
  expect_refused("short.ply", binary, "2 vertex records (at least 24 bytes), but only 12 bytes follow");
  expect_refused("overflow.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999999999999\nproperty float x\nend_header\n",
                 "element count '99999999999999999999' is not an integer");
  expect_refused("empty_records.ply", "ply\nformat ascii 1.0\nelement vertex 1000000\nend_header\n",
                 "declares 1000000 records without properties");
}

TEST(FuzzFindingF4, OffCountsBeyondTheFileAreRefusedBeforeAllocating) {
  expect_refused("huge.off", "OFF\n2000000000 1 0\n0 0 0\n", "declares 2000000000 vertices and 1 faces (at least 12000000008 bytes)");
  // OpenMesh read binary OFF little-endian (the format is big-endian) and reserved what the counts said.
  expect_refused("binary.off", "OFF BINARY\n\0\0\0\3\0\0\0\1\0\0\0\0"s, "binary OFF is not supported");
}

// F11 (found by the first fuzzing run after F2-F4 were fixed): OpenMesh's PLY body readers trust list
// lengths and numbers; a length that does not fit its type, or one that reaches past the end of a binary
// file, looped for up to 2^32 items at the end of the file (a hang). The body is walked first now.
TEST(FuzzFindingF11, PlyListLengthsAndValuesAreCheckedBeforeOpenMeshReads) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  expect_refused("long_list.ply", header + vertices + "42949672950 0 1 2\n", "face record 0: list length 42949672950 out of range for uchar");
  expect_refused("list_256.ply", header + vertices + "256 0 1 2\n", "face record 0: list length 256 out of range for uchar");
  expect_refused("short_list.ply", header + vertices + "4 0 1 2\n", "face record 0: the file ends inside a list of 4");
  expect_refused("word.ply", header + "0 0 0\n1 y 0\n0 1 0\n3 0 1 2\n", "vertex record 1: cannot read 'y' as float");
  expect_refused("nan.ply", header + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "vertex record 1: non-finite value 'nan'");

  // Binary: a uint list length of 2^32 - 1 in a file that holds three indices.
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  binary.append(36, '\0');
  binary += "\xff\xff\xff\xff"s;
  binary.append(12, '\0');
  expect_refused("binary_long_list.ply", binary, "face record 0: the file ends early");
}

// F6: OpenMesh's text OFF reader took the counts from the line after the header and knew no comments, so
// these read uninitialized counts and indices. parashade reads OFF itself now.
TEST(FuzzFindingF6, OffCountsOnTheHeaderLineAndCommentsAreRead) {
  EXPECT_EQ(triangles("header_counts.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), 1u);
  EXPECT_EQ(triangles("comments.off", "OFF\n# made by hand\n3 1 0\n0 0 0\n# c\n1 0 0\n\n0 1 0\n3 0 1 2 # face\n"), 1u);
  EXPECT_EQ(triangles("colours.off", "COFF\n3 1\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 1 1 1\n"), 1u);
  expect_refused("no_data.off", "OFF 0 0 0", "no faces");
  expect_refused("twice.off", "OFFOFF BI BINARY\n", "unknown OFF header 'OFFOFF'");
  expect_refused("four.off", "4OFF\n1 0 0\n0 0 0 1\n", "4D and nD OFF files are not supported");
  expect_refused("word.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 x 2\n", ":6: cannot read 'x' as an integer");
  expect_refused("big_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4294967296 0 1 2\n", "face lists fewer than its 4294967296");
}

TEST(FuzzFindingF6, NoffNormalsAreRead) {
  TempDir dir;
  MeshLoadStats stats;
  const Mesh m = load_mesh(dir.write("n.off", "NOFF\n3 1 0\n0 0 0 0 0 2\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"), &stats);
  EXPECT_TRUE(stats.normals_from_file);
  EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
  expect_refused("nan_normal.off", "NOFF\n3 1 0\n0 0 0 nan 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n",
                 "a vertex normal is not finite");
}

// F12 (found by the same run): a mesh file of denormal extent (1e-40) gave its bare-mesh scene a camera
// whose view direction does not normalize (NaN image). Now refused, like the far too large (F8).
TEST(FuzzFindingF12, MeshTooSmallToFrameIsRefused) {
  TempDir dir;
  for (const auto& [name, text] : {std::make_pair("tiny.obj", "v 0 0 0\nv 1e-40 0 0\nv 0 1e-40 0\nf 1 2 3\n"),
                                   std::make_pair("far_and_tiny.obj", "v 1e6 0 0\nv 1000000.01 0 0\nv 1e6 0.01 0\nf 1 2 3\n")}) {
    const std::filesystem::path p = dir.write(name, text);
    try {
      load_scene(p);
      ADD_FAILURE() << name << " loaded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("too small to frame"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
    }
  }
  // Small but frameable: a millimetre-sized mesh a metre away loads.
  EXPECT_NO_THROW(load_scene(dir.write("small.obj", "v 1 0 0\nv 1.001 0 0\nv 1 0.001 0\nf 1 2 3\n")));
}

}  // namespace
}  // namespace parashade
