// Issue 46, item 7 and a message: the environment PoCL reads when it starts. An empty POCL_CACHE_DIR made
// PoCL abort on an assertion (rc 134); without PATH (env -i) a cold kernel cache could not be filled (PoCL's
// compiler found no `ld`) and the process aborted; an unusable XDG_CACHE_HOME (PoCL's cache is under it)
// was reported as a missing driver. Each now renders or ends with exit 4 naming the variable.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;
namespace fs = std::filesystem;

class CliPoclEnvironment : public CliTest {
 protected:
  fs::path scene_ = input("ball.json", sphere_scene());
  // A kernel cache of the test's own: empty, so PoCL compiles (and links) every kernel.
  fs::path cold_cache() const {
    const fs::path p = dir_.path() / "cold-cache";
    fs::create_directories(p);
    return p;
  }
};

// Empty is taken as unset: PoCL's default cache folder, here under XDG_CACHE_HOME.
TEST_F(CliPoclEnvironment, AnEmptyPoclCacheDirRenders) {
  const ScopedEnv cache("POCL_CACHE_DIR", "");
  const ScopedEnv xdg("XDG_CACHE_HOME", cold_cache().string());
  const RunResult r = render(scene_, {}, ErrorFigures::skip);
  EXPECT_TRUE(succeeds(r));
  EXPECT_TRUE(fs::exists(image()));
}

// env -i HOME=...: no PATH. PoCL's compiler runs `ld` by name to link a kernel it compiled.
TEST_F(CliPoclEnvironment, NoPathWithAColdKernelCacheRenders) {
  const ScopedEnv path("PATH", nullptr);
  const ScopedEnv cache("POCL_CACHE_DIR", cold_cache().string());
  const RunResult r = render(scene_, {}, ErrorFigures::skip);
  EXPECT_TRUE(succeeds(r));
  EXPECT_TRUE(fs::exists(image()));
}

// PoCL keeps its cache in $XDG_CACHE_HOME/pocl when POCL_CACHE_DIR is unset: a file there is named, not
// "install an OpenCL driver".
TEST_F(CliPoclEnvironment, AnUnusableXdgCacheHomeIsNamed) {
  const fs::path file = input("plain-file", "not a folder");
  const ScopedEnv cache("POCL_CACHE_DIR", nullptr);
  const ScopedEnv xdg("XDG_CACHE_HOME", file.string());
  const RunResult r = render(scene_, {"--no-tuned"});
  EXPECT_TRUE(fails_with(r, kDeviceFailure, {"XDG_CACHE_HOME", "plain-file", "is not a folder"}));
  EXPECT_EQ(r.err.find("install"), std::string::npos) << r;
  EXPECT_TRUE(nothing_written());
}

}  // namespace
}  // namespace parashade
