#include "suggest.hpp"

#include <algorithm>

namespace parashade::cli {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  // d[i][j]: the distance between a's first i and b's first j characters.
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::vector<std::string> closest_words(const std::string& word, const std::vector<std::string>& candidates) {
  // Leading dashes are part of the spelling, not of the distance ("--sizee" is one edit from "--size").
  const auto bare = [](const std::string& w) { return w.substr(std::min(w.find_first_not_of('-'), w.size())); };
  const std::string typed = bare(word);
  if (typed.size() < 3) return {};  // "-x" is one edit from every one-letter option: no guess
  const std::size_t limit = std::clamp<std::size_t>(typed.size() / 4, 1, 3);
  std::size_t best = limit + 1;
  std::vector<std::string> out;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(typed, bare(c));
    if (d < best) out.clear(), best = d;
    if (d == best) out.push_back(c);
  }
  if (!out.empty()) return out;
  for (const std::string& c : candidates)
    if (bare(c).compare(0, typed.size(), typed) == 0) out.push_back(c);
  if (out.size() > 1) out.clear();
  return out;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::vector<std::string> near = closest_words(word, candidates);
  if (near.empty()) return "";
  std::string text = "; did you mean ";
  for (std::size_t i = 0; i < near.size(); ++i)
    text += (i == 0 ? "" : i + 1 == near.size() ? " or " : ", ") + ("'" + near[i] + "'");
  return text + "?";
}

}  // namespace parashade::cli
