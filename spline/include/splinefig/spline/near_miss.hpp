#pragma once
// Near misses of a name among the known ones, for "did you mean ...?" in messages: a filter or
// basis name, a command-line flag or command.
//
// A known name is a near miss of `word` when, ignoring ASCII case, it is within a few edits of
// it (insertions, deletions, substitutions and swaps of adjacent characters: 0 for a word of
// up to 2 characters, 1 up to 5, 2 up to 8, else 3): "scal" -> "scale", "Version" -> "version",
// "catmul-rom" -> "catmull-rom"; only the nearest are returned, in the order given. When none
// is, the names `word` (3 characters or more) begins: "mitchel" -> "mitchell-netravali".
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig {

// Optimal string alignment distance (Levenshtein with adjacent transpositions), ASCII case ignored.
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  const auto low = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = low(a[i - 1]) == low(b[j - 1]) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1]))
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    prev2.swap(prev);
    prev.swap(cur);
  }
  return prev[m];
}

inline std::vector<std::string> near_misses(std::string_view word, const std::vector<std::string>& known) {
  const std::size_t n = word.size();
  const std::size_t allowed = n <= 2 ? 0 : n <= 5 ? 1 : n <= 8 ? 2 : 3;
  std::size_t best = allowed + 1;
  std::vector<std::string> out, begun;
  for (const auto& k : known) {
    const std::size_t d = edit_distance(word, k);
    if (d > allowed && n >= 3 && k.size() > n && edit_distance(std::string_view(k).substr(0, n), word) == 0 &&
        std::find(begun.begin(), begun.end(), k) == begun.end())
      begun.push_back(k);
    if (d > allowed || d > best) continue;
    if (d < best) out.clear(), best = d;
    if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out.empty() ? begun : out;  // a name the word begins only when none is within the edits
}

// " or " between the near misses: "did you mean " + or_list(near_misses(...)) + "?".
inline std::string or_list(const std::vector<std::string>& words) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) s += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return s;
}

// "a, b, c" -> {"a", "b", "c"}: a list of names as messages print them.
inline std::vector<std::string> split_names(std::string_view list) {
  std::vector<std::string> out;
  while (!list.empty()) {
    const auto comma = list.find(',');
    std::string_view item = list.substr(0, comma);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (!item.empty()) out.emplace_back(item);
    list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
  }
  return out;
}

}  // namespace splinefig
