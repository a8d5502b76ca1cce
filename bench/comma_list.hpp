#pragma once
// The items of a comma-separated option value ("a,b,,c" -> a, b, c), for the bench tools' --scenes and --sizes
// lists.
#include <sstream>
#include <string>
#include <vector>

namespace parashade {

inline std::vector<std::string> comma_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace parashade
