// The library knows no command line: a parser's usage error names the value at fault (and what kind of
// value it is), never a flag. The CLI puts its option in front (tests/cli).
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/combined.hpp"
#include "parashade/errors.hpp"
#include "parashade/normalization.hpp"
#include "parashade/specular_models.hpp"
#include "parashade/units.hpp"

namespace parashade {
namespace {

struct BadValue {
  const char* text;
  std::function<void(const std::string&)> parse;
};

TEST(LibraryErrors, NameTheValueNotACommandLineFlag) {
  const auto units = [](const std::string& s) { parse_units(s); };
  const auto arith = [](const std::string& s) { parse_arith(s); };
  const auto division = [](const std::string& s) { parse_division(s); };
  const auto normalize = [](const std::string& s) { parse_normalize(s); };
  const auto specular = [](const std::string& s) { parse_specular(s); };
  const auto choice = [](const std::string& s) {
    CombinedConfig c;
    parse_triangle_rule(s, c);
  };
  const std::vector<BadValue> bad = {
      {"zigzag", units},          {"interleave:17", units},        {"segment:3", units},
      {"sierpinski:4", units},    {"double", arith},                {"fixed:8.8", arith},
      {"fixed:12.0", arith},      {"fixed:20.13", arith},           {"divide", division},
      {"shiftadd:31", division},  {"fastest", normalize},           {"dichotomy:linear:7", normalize},
      {"recurrence:1", normalize}, {"cosk:taylor:3", specular},     {"7n16:9", specular},
      {"best", choice},           {"bound:1,1,1", choice},
  };
  for (const BadValue& b : bad) {
    try {
      b.parse(b.text);
      ADD_FAILURE() << "'" << b.text << "' was accepted";
    } catch (const UsageError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(b.text), std::string::npos) << what;
      EXPECT_EQ(what.find("--"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace parashade
