#pragma once
// Drives one Verilated unit (hw/) with a vectors file's spans and checks every clock's outputs bit for
// bit against the golden model's, and the simulated clocks against the modeled ones.
//
// Protocol (docs/hardware.md): the testbench offers the next span (load high, its registers on the
// inputs) every clock; the unit takes it in a clock where `ready` is high. Each clock the valid lanes,
// in lane order, must be the vectors' next output clock: x, register and level. Clocks per span: from
// the previous span's last output clock (the first span: from the clock before its load) to this span's
// last output clock; the model's are its load clock plus the unit's span clocks. A pipelined unit fills
// its pipeline once (`fill` clocks more for the first span).
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>

#include <verilated.h>

#include "vectors_file.hpp"

namespace hwtest {

// Bits [lo, lo + n) of a Verilated port (an integer up to 64 bits, or a VlWide of 32-bit words).
template <typename T>
std::uint64_t port_bits(const T& port, int lo, int n) {
  std::uint64_t out = 0;
  if constexpr (std::is_integral_v<T>) {
    out = std::uint64_t(port) >> lo;
  } else {
    for (int b = 0; b < n; ++b) out |= std::uint64_t((port[std::size_t((lo + b) / 32)] >> ((lo + b) % 32)) & 1u) << b;
  }
  return n >= 64 ? out : out & ((std::uint64_t(1) << n) - 1);
}

inline std::int64_t sign_extend(std::uint64_t v, int width) {
  return std::int64_t(v << (64 - width)) >> (64 - width);
}

struct Outcome {
  std::uint64_t spans = 0, pixels = 0, sim_clocks = 0, modeled_clocks = 0, output_clocks = 0;
  std::uint64_t span_clock_mismatches = 0;
  std::string first_error;  // empty: bit-exact and clocks as modeled
};

constexpr int kLengthBits = 13;  // hw/'s LEN parameter default

template <typename Model>
Outcome check_rtl(const Vectors& v, int lanes, int width, int fill) {
  Outcome o;
  auto ctx = std::make_unique<VerilatedContext>();
  auto m = std::make_unique<Model>(ctx.get());
  const std::uint64_t in_mask = width == 32 ? 0xffffffffull : (std::uint64_t(1) << width) - 1;
  // During reset the testbench already offers the first span: `ready` must stay low (the unit ignores `load`
  // in reset, so a span taken on a high `ready` would be lost). The span is offered again after reset.
  m->load = v.spans.empty() ? 0 : 1;
  if (!v.spans.empty()) {
    m->s_in = std::uint32_t(std::uint64_t(v.spans[0].start) & in_mask);
    m->step_in = std::uint32_t(std::uint64_t(v.spans[0].step) & in_mask);
    m->length_in = std::uint32_t(v.spans[0].length);
  }
  m->rst = 1;
  for (int clock = 0; clock < 2; ++clock) {
    m->clk = 0;
    m->eval();
    if (m->ready && o.first_error.empty())
      o.first_error = "reset clock " + std::to_string(clock) + ": ready is high while rst is (a span offered now is dropped)";
    m->clk = 1;
    m->eval();
  }
  m->rst = 0;
  m->load = 0;

  std::size_t next_span = 0;          // next span to offer
  std::size_t span = 0, clock = 0;    // next expected output: span, its output clock
  std::uint64_t cycle = 1, first_load = 0, previous_end = 0;
  bool loaded_any = false;
  std::uint64_t limit = 16;
  for (const Span& s : v.spans) limit += 4 * s.modeled_clocks + 8;
  auto error = [&](const std::string& what) {
    if (o.first_error.empty())
      o.first_error = "span " + std::to_string(span) + " output clock " + std::to_string(clock) + " (cycle " +
                      std::to_string(cycle) + "): " + what;
  };
  while (span < v.spans.size() && o.first_error.empty()) {
    if (cycle > limit) {
      error("the unit stopped producing pixels");
      break;
    }
    if (next_span < v.spans.size()) {
      const Span& s = v.spans[next_span];
      m->load = 1;
      m->s_in = std::uint32_t(std::uint64_t(s.start) & in_mask);
      m->e_in = std::uint32_t(std::uint64_t(s.end) & in_mask);
      m->step_in = std::uint32_t(std::uint64_t(s.step) & in_mask);
      m->lane_step_in = std::uint32_t(std::uint64_t(s.lane_step) & in_mask);
      m->length_in = std::uint32_t(s.length);
    } else {
      m->load = 0;
    }
    m->clk = 0;
    m->eval();  // this clock's outputs and ready, from the state after the last edge
    std::vector<Pixel> got;
    for (int lane = 0; lane < lanes; ++lane) {
      if (!port_bits(m->valid, lane, 1)) continue;
      got.push_back({int(port_bits(m->x, lane * kLengthBits, kLengthBits)),
                     sign_extend(port_bits(m->value, lane * width, width), width),
                     int(port_bits(m->level, lane * 8, 8))});
    }
    if (!got.empty()) {
      const std::vector<Pixel>& want = v.spans[span].clocks[clock];
      std::string diff;
      if (got.size() != want.size()) diff = "lanes " + std::to_string(got.size()) + " valid, expected " + std::to_string(want.size());
      for (std::size_t k = 0; diff.empty() && k < got.size(); ++k) {
        if (got[k].x != want[k].x || got[k].value != want[k].value || got[k].level != want[k].level) {
          char buf[200];
          std::snprintf(buf, sizeof buf, "lane %zu: x %d register %lld level %d, expected x %d register %lld level %d", k,
                        got[k].x, (long long)got[k].value, got[k].level, want[k].x, (long long)want[k].value,
                        want[k].level);
          diff = buf;
        }
      }
      if (!diff.empty()) {
        error(diff);
        break;
      }
      o.pixels += got.size();
      ++o.output_clocks;
      if (++clock == v.spans[span].clocks.size()) {  // the span's last output clock
        const std::uint64_t sim = cycle - previous_end;
        const std::uint64_t modeled = v.spans[span].modeled_clocks + (span == 0 ? std::uint64_t(fill) : 0);
        if (sim != modeled) {
          ++o.span_clock_mismatches;
          if (o.span_clock_mismatches == 1)
            std::fprintf(stderr, "span %zu (%d pixels): %llu clocks simulated, %llu modeled\n", span,
                         v.spans[span].length, (unsigned long long)sim, (unsigned long long)modeled);
        }
        previous_end = cycle;
        o.modeled_clocks += v.spans[span].modeled_clocks;
        ++span;
        clock = 0;
      }
    }
    const bool accepted = m->load && m->ready;
    m->clk = 1;
    m->eval();
    if (accepted) {
      if (!loaded_any) {
        first_load = cycle;
        previous_end = cycle - 1;  // the first span's clocks count from its load clock
        loaded_any = true;
      }
      ++next_span;
    }
    ++cycle;
  }
  // Then the unit must fall silent.
  for (int idle = 0; idle < 4 && o.first_error.empty(); ++idle, ++cycle) {
    m->load = 0;
    m->clk = 0;
    m->eval();
    if (port_bits(m->valid, 0, lanes) != 0) error("a pixel after the last span's");
    m->clk = 1;
    m->eval();
  }
  o.spans = span;
  o.sim_clocks = previous_end - (first_load - 1);
  m->final();
  return o;
}

}  // namespace hwtest
