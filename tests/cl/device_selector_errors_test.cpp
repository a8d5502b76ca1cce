// A device selector the library cannot read is a usage error naming the selector, not a flag (the CLI
// adds its --device); both are refused before any device is opened.
#include <string>

#include <gtest/gtest.h>

#include "parashade/errors.hpp"
#include "parashade/split_renderer.hpp"
#include "parashade/sub_devices.hpp"

namespace parashade {
namespace {

TEST(DeviceSelectorErrors, NameTheSelectorNotACommandLineFlag) {
  for (const std::string selector : {"pthread,,pthread", "sub:pthread:0", "sub:pthread:1+x", "sub::2"}) {
    try {
      if (is_sub_device_selector(selector)) open_sub_devices(selector, SubDeviceContext::own);
      else open_devices(selector);
      ADD_FAILURE() << "'" << selector << "' was accepted";
    } catch (const UsageError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(selector), std::string::npos) << what;
      EXPECT_EQ(what.find("--"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace parashade
