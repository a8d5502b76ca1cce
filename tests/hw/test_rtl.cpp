// test_rtl MODEL VECTORS: checks one Verilated unit of hw/ (MODEL, a name of rtl_models.hpp, generated
// by tests/hw/CMakeLists.txt) against a vectors file written by `parashade vectors` for the same unit
// and format (docs/hardware.md). Exit 0 when every pixel of every clock is bit-exact and every span's
// simulated clocks equal the modeled ones; 1 otherwise, with the first difference.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "rtl_check.hpp"
#include "rtl_models.hpp"  // kModels: name, unit spec, arith, lanes, width, fill clocks, checker

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: test_rtl MODEL VECTORS_FILE\n");
    return 2;
  }
  const hwtest::ModelEntry* model = nullptr;
  for (const hwtest::ModelEntry& e : hwtest::kModels)
    if (std::strcmp(e.name, argv[1]) == 0) model = &e;
  if (!model) {
    std::fprintf(stderr, "test_rtl: no model '%s' (tests/hw/CMakeLists.txt lists them)\n", argv[1]);
    return 2;
  }
  try {
    const hwtest::Vectors v = hwtest::read_vectors(argv[2]);
    if (v.header.at("unit") != model->unit || v.header.at("arith") != model->arith ||
        v.int_of("lanes") != model->lanes || v.int_of("int_bits") + v.int_of("frac_bits") != model->width) {
      std::fprintf(stderr, "test_rtl: %s holds %s %s, the model is %s %s\n", argv[2], v.header.at("unit").c_str(),
                   v.header.at("arith").c_str(), model->unit, model->arith);
      return 2;
    }
    const hwtest::Outcome o = model->check(v, model->lanes, model->width, model->fill);
    std::printf("%s (%s %s): %llu spans, %llu pixels in %llu output clocks; %llu clocks simulated, %llu modeled"
                " + %d fill; %llu spans whose clocks differ\n",
                model->name, model->unit, model->arith, (unsigned long long)o.spans, (unsigned long long)o.pixels,
                (unsigned long long)o.output_clocks, (unsigned long long)o.sim_clocks,
                (unsigned long long)o.modeled_clocks, model->fill, (unsigned long long)o.span_clock_mismatches);
    if (!o.first_error.empty()) {
      std::printf("FAIL: not bit-exact with the golden model: %s\n", o.first_error.c_str());
      return 1;
    }
    if (o.spans != v.spans.size() || o.span_clock_mismatches != 0 ||
        o.sim_clocks != o.modeled_clocks + std::uint64_t(model->fill)) {
      std::printf("FAIL: simulated clocks differ from the modeled ones\n");
      return 1;
    }
    std::printf("bit-exact; clocks as modeled\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "test_rtl: %s\n", e.what());
    return 2;
  }
}
