// "did you mean" hints for misspelt names: commands, options, suite keys.
#pragma once

#include <string>
#include <vector>

namespace urdfsnap {

// The Levenshtein distance between two strings (insertions, deletions and substitutions).
size_t EditDistance(const std::string& a, const std::string& b);

// "did you mean 'X'? " for the candidate nearest to `word` when it is a likely misspelling (at
// most 2 edits, and fewer than half of the word's letters), else "". Ties go to the first.
std::string DidYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace urdfsnap
