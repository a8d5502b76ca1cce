// Every OpenCL error reaches the user as a DeviceError naming what parashade was doing, the OpenCL call
// and the error's name (not a number alone).
#include <string>

#include <gtest/gtest.h>

#include <CL/opencl.hpp>

#include "parashade/device.hpp"
#include "parashade/errors.hpp"

namespace parashade {
namespace {

TEST(ClErrorMessage, NamesContextCallAndError) {
  try {
    try {
      throw cl::Error(CL_OUT_OF_RESOURCES, "clEnqueueNDRangeKernel");
    } catch (const cl::Error&) {
      rethrow_cl_error("rendering on 'test device'");
    }
  } catch (const DeviceError& e) {
    EXPECT_STREQ(e.what(), "rendering on 'test device': clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (-5)");
    return;
  }
  FAIL() << "no DeviceError";
}

// Every code of the OpenCL 1.2 headers has its name; an unknown code still shows its number.
TEST(ClErrorMessage, EveryStandardCodeHasAName) {
  for (int code = -1; code >= -68; --code) {
    if (code <= -20 && code >= -29) continue;  // unassigned in OpenCL 1.2
    const std::string name = cl_error_name(code);
    EXPECT_EQ(name.rfind("CL_", 0), 0u) << code << ": " << name;
    EXPECT_NE(name.find("(" + std::to_string(code) + ")"), std::string::npos) << name;
  }
  EXPECT_EQ(cl_error_name(-1001), "CL_PLATFORM_NOT_FOUND_KHR (-1001)");
  EXPECT_EQ(cl_error_name(-9999), "unknown OpenCL error (-9999)");
}

}  // namespace
}  // namespace parashade
