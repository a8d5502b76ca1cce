// Issue 47: every environment variable that tunes the host is checked (docs/environment.md): a bad value
// is a usage error (exit 2) naming the variable and what it takes, before any work. Before:
// PARASHADE_HOST_THREADS=abc (or 0) and PARASHADE_HOST_SPIN_US=-5 were ignored, PARASHADE_KERNEL_WERROR=yes
// counted as off, PARASHADE_MEMORY_LIMIT=lots was exit 3.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliEnvironmentValues : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

struct BadValue {
  const char* variable;
  const char* value;
  const char* accepted;  // what the message says the variable takes
};

TEST_F(CliEnvironmentValues, ABadVariableIsAUsageErrorNamingWhatItTakes) {
  for (const BadValue& b : {BadValue{"PARASHADE_HOST_THREADS", "abc", "from 1 to 1024"},
                            BadValue{"PARASHADE_HOST_THREADS", "0", "from 1 to 1024"},
                            BadValue{"PARASHADE_HOST_SPIN_US", "-5", "from 0 to 1000000"},
                            BadValue{"PARASHADE_KERNEL_WERROR", "yes", "1 (kernel build warnings are errors) or 0"},
                            BadValue{"PARASHADE_MEMORY_LIMIT", "lots", "K, M, G or T"}}) {
    SCOPED_TRACE(std::string(b.variable) + "=" + b.value);
    const ScopedEnv bad(b.variable, b.value);
    EXPECT_TRUE(fails_with(render(scene_), kUsage, {std::string(b.variable) + "='" + b.value + "'", b.accepted}));
  }
  EXPECT_TRUE(nothing_written());
  const ScopedEnv threads("PARASHADE_HOST_THREADS", "1"), spin("PARASHADE_HOST_SPIN_US", "0"),
      werror("PARASHADE_KERNEL_WERROR", "0");
  EXPECT_TRUE(succeeds(render(scene_)));
}

}  // namespace
}  // namespace parashade
