#pragma once
// Shared by the libFuzzer targets: a per-process scratch directory for the input file (the loaders take
// a path), the pass/fail rule, and checks of what a successful load returns.
//
// Pass: the loader returns, or throws parashade::InputError (the documented error for bad input).
// Fail ("finding"): a crash or sanitizer report (libFuzzer and ASan/UBSan see those), any other
// exception escaping (std::bad_alloc, std::length_error, an OpenMesh or nlohmann exception, another
// parashade::Error), or a successful load that breaks the documented guarantees (non-finite values,
// indices out of range, normals not of unit length, a camera that cannot be used). The output checks can
// be switched off with PARASHADE_FUZZ_CHECK_OUTPUT=0, to look for crashes past a known output finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "parashade/mesh.hpp"
#include "parashade/scene.hpp"

namespace parashade::fuzz {

// A directory of this process's own (under TMPDIR), created on first use and removed at normal exit.
const std::filesystem::path& work_dir();

// Writes the fuzzer's bytes to work_dir()/name, replacing the previous input, and returns the path.
std::filesystem::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size);

// Runs `load`; InputError is a pass, any other exception a finding.
void expect_input_errors_only(const char* what, const std::function<void()>& load);

// Prints "parashade fuzz finding: <what>" and aborts, so libFuzzer saves the input.
[[noreturn]] void finding(const std::string& what);

bool check_output();  // PARASHADE_FUZZ_CHECK_OUTPUT, default on

// The guarantees of mesh.hpp: triangles, indices in range, finite positions, unit normals, consistent stats.
void check_mesh(const Mesh& mesh, const std::string& what);
void check_mesh_stats(const Mesh& mesh, const MeshLoadStats& stats);
// The guarantees of scene.hpp and scenes/README.md for a scene load_scene returned.
void check_scene(const Scene& scene);

}  // namespace parashade::fuzz
