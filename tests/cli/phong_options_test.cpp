// --normalize and --specular (docs/phong-methods.md): bad values and combinations are usage errors
// naming the culprit, with nothing written; phong-study writes its JSON claims and Markdown.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_fixture.hpp"

namespace parashade {
namespace {

using namespace testing_support;

class CliPhongOptions : public CliTest {
 protected:
  std::filesystem::path scene_ = input("ball.json", sphere_scene());
};

TEST_F(CliPhongOptions, UnknownNormalizeOrSpecularIsNamed) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "phong", "--normalize", "fastest"}), kUsage, {"--normalize", "fastest"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "phong", "--specular", "cosk:taylor:3"}), kUsage,
                         {"--specular", "cosk:taylor:3"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliPhongOptions, OptionsNeedPhong) {
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "gouraud", "--specular", "quadratic"}), kUsage, {"--specular", "phong"}));
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "flat", "--normalize", "slerp"}), kUsage, {"--normalize", "phong"}));
  // Sequential methods are host-library only.
  EXPECT_TRUE(fails_with(render(scene_, {"--method", "phong", "--normalize", "recurrence"}), kUsage, {"recurrence", "phong-study"}));
  EXPECT_TRUE(nothing_written());
}

TEST_F(CliPhongOptions, StudyWritesClaims) {
  const auto json = out_dir() / "study.json", md = out_dir() / "study.md";
  const RunResult r = run_parashade({"phong-study", "--json", json.string(), "-o", md.string()});
  ASSERT_TRUE(succeeds(r)) << r;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_GE(j["claims"].size(), 8u);
  for (const auto& c : j["claims"])
    for (const char* key : {"id", "source", "source_figure", "measured", "verdict"}) EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_EQ(j["nonfinite_spans"], 0);
  EXPECT_TRUE(std::filesystem::file_size(md) > 1000);
}

}  // namespace
}  // namespace parashade
