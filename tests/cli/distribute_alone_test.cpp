// Issue 47: `render --distribute` started without mpirun is one MPI rank, the distributed path for
// nothing and several times slower (34x on the scene), and it ran without a word. It is warned of
// on stderr (docs/distributed.md, "Outside mpirun"); the image is still the one-process render's.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliDistributeAlone : public CliTest {};

TEST_F(CliDistributeAlone, OneRankOutsideMpirunIsWarnedOf) {
  for (const char* launcher : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(launcher)) GTEST_SKIP() << "running under an MPI launcher (" << launcher << ")";
  const RunResult r = render(input("ball.json", sphere_scene()), {"--no-tuned", "--distribute", "sort-last"});
  if (r.exit_code == kUsage && r.err.find("built without it") != std::string::npos)
    GTEST_SKIP() << "parashade was built without MPI (--distribute is refused):" << r;
  ASSERT_TRUE(succeeds(r));
  EXPECT_NE(r.err.find("parashade: warning: not started by mpirun"), std::string::npos) << r;
  EXPECT_NE(r.err.find("single MPI rank"), std::string::npos) << r;
  EXPECT_NE(r.err.find("mpirun -np N"), std::string::npos) << r;
  EXPECT_TRUE(std::filesystem::exists(image()));
}

}  // namespace
}  // namespace parashade
