// "did you mean ...?" for a misspelt name: the one place that decides which known name a
// typo was meant to be (CLI options, --set attributes, --start-rule rules, symbols).
#pragma once

#include <string>
#include <vector>

namespace fgsg::frontend {

// Edits that turn `a` into `b`: insertions, deletions, substitutions and swaps of two
// neighbouring characters each count 1 (optimal string alignment distance).
size_t editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `word` when it is near enough to be a typo of it: at most one
// edit per three characters of `word` (at least one), ignoring case. "" when none is, or
// when `word` is itself a candidate. Ties go to the first candidate.
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace fgsg::frontend
