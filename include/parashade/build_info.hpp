#pragma once
// Which build of parashade this is, as --version and every report say it: the project's version
// (CMake's project VERSION) and the git commit it was configured from ("unknown" outside a checkout).
// The one place that reads the compile definitions PARASHADE_VERSION and PARASHADE_GIT_HASH.
namespace parashade {

const char* parashade_version();
const char* parashade_git_hash();

}  // namespace parashade
