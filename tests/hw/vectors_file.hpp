#pragma once
// Reads a test vectors file (docs/hardware.md, "Test vectors"; written by `parashade vectors`). Plain
// C++ with no parashade code: the testbench knows the file, not the golden models that wrote it.
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hwtest {

struct Pixel {
  int x;
  std::int64_t value;  // the register, signed
  int level;
};

struct Span {
  int length = 0;
  std::int64_t start = 0, end = 0, step = 0, lane_step = 0;
  std::uint64_t modeled_clocks = 0;  // load clock + the unit's span clocks (the cost model)
  std::vector<std::vector<Pixel>> clocks;  // per output clock, its pixels in lane order
};

struct Vectors {
  std::map<std::string, std::string> header;  // unit, lanes, arith, int_bits, frac_bits, load_clocks, ...
  std::vector<Span> spans;
  int int_of(const std::string& key) const {
    const auto it = header.find(key);
    if (it == header.end()) throw std::runtime_error("vectors: no '" + key + "' in the header");
    return std::stoi(it->second);
  }
};

inline Vectors read_vectors(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read vectors file '" + path + "'");
  Vectors v;
  std::string line;
  int line_no = 0;
  bool ended = false;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(path + ":" + std::to_string(line_no) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string key;
    s >> key;
    if (key == "span") {
      Span sp;
      if (!(s >> sp.length >> sp.start >> sp.end >> sp.step >> sp.lane_step >> sp.modeled_clocks) || sp.length < 1)
        fail("bad span line");
      v.spans.push_back(sp);
    } else if (key == "clock") {
      if (v.spans.empty()) fail("clock line before any span");
      std::vector<Pixel> pixels;
      Pixel p;
      while (s >> p.x >> p.value >> p.level) pixels.push_back(p);
      if (pixels.empty() || !s.eof()) fail("bad clock line");
      v.spans.back().clocks.push_back(pixels);
    } else if (key == "end") {
      ended = true;
      break;
    } else {
      std::string value;
      std::getline(s >> std::ws, value);
      v.header[key] = value;
    }
  }
  if (!ended) throw std::runtime_error(path + ": no 'end' line (truncated?)");
  if (v.header["format"] != "parashade-vectors 1") throw std::runtime_error(path + ": not a parashade-vectors 1 file");
  if (std::size_t(v.int_of("spans")) != v.spans.size()) throw std::runtime_error(path + ": span count differs from the header");
  return v;
}

}  // namespace hwtest
