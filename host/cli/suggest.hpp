#pragma once
// "Did you mean ...?" for a mistyped command or option: the closest of the words the command line knows,
// by edit distance, offered only when it is close.
#include <cstddef>
#include <string>
#include <vector>

namespace parashade::cli {

// Damerau-Levenshtein distance (the optimal string alignment form): insertions, deletions, substitutions
// and swaps of two neighbouring characters, one edit each ("rendr" -> "render": 1, "szie" -> "size": 1).
std::size_t edit_distance(const std::string& a, const std::string& b);

// The candidates nearest to `word`, when near enough to be a typo of it: at most one edit in four
// characters (at least 1, at most 3), or `word` begins exactly one candidate. Leading dashes do not count;
// a word of fewer than 3 characters gets no suggestion (any letter is one edit from "-q").
// Several at the same distance are all given, in the candidates' order; none when nothing is close.
std::vector<std::string> closest_words(const std::string& word, const std::vector<std::string>& candidates);

// "; did you mean 'x'?" (or "'x' or 'y'"), or "" when no candidate is close.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace parashade::cli
