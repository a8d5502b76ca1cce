// A kernel that does not compile (here: a broken -D option, as a bad build flag or an edited kernel
// would give) is a DeviceError that names the file, the options, the OpenCL error and carries the
// compiler's build log, so the user sees the compiler's own words.
#include <string>

#include <gtest/gtest.h>

#include <CL/opencl.hpp>

#include "cl_fixture.hpp"
#include "parashade/errors.hpp"

namespace parashade {
namespace {

using testing_support::test_device;

TEST(KernelBuildFailure, ReportsTheBuildLog) {
  // TILE must be an integer constant: coverage_count.cl sizes loops and arrays by it.
  const std::string options = "-D TILE=not_a_number";
  try {
    test_device().program({"coverage_count.cl"}, options);
    FAIL() << "the program built";
  } catch (const DeviceError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("coverage_count.cl"), std::string::npos) << message;
    EXPECT_NE(message.find(options), std::string::npos) << message;
    EXPECT_NE(message.find("CL_BUILD_PROGRAM_FAILURE"), std::string::npos) << message;
    const std::size_t log_start = message.find("--- build log ---");
    ASSERT_NE(log_start, std::string::npos) << message;
    // The compiler's diagnostic names the undeclared identifier the macro expanded to.
    const std::string log = message.substr(log_start);
    EXPECT_NE(log.find("error"), std::string::npos) << message;
    EXPECT_NE(log.find("not_a_number"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace parashade
