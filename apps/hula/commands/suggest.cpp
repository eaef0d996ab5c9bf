// SPDX-License-Identifier: MIT
// "did you mean": the nearest command or option name (optimal string
// alignment distance: insertions, deletions, substitutions and swaps of
// neighbours) to a misspelt word of the command line, from the names
// registered with CLI11.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "commands/common.hpp"

namespace hula::cli {

namespace {

// Optimal string alignment distance between a and b.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The candidate nearest to `word`, if near enough to be a slip (at most a third of its letters, at least 2).
std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t distance = edit_distance(word, c);
    if (distance < best_distance) {
      best_distance = distance;
      best = c;
    }
  }
  return best;
}

// The named subcommands of `app`.
std::vector<const CLI::App*> named_subcommands(const CLI::App& app) {
  std::vector<const CLI::App*> out;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (!sub->get_name().empty()) out.push_back(sub);
  return out;
}

// The long option names of `app` and of its option groups (nameless subcommands), with "--"; those
// that take a value also in `valued`.
void long_names(const CLI::App& app, std::vector<std::string>& out, std::vector<std::string>& valued) {
  for (const CLI::Option* o : app.get_options())
    for (const std::string& name : o->get_lnames()) {
      out.push_back("--" + name);
      if (o->get_items_expected_min() > 0) valued.push_back("--" + name);
    }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name().empty()) long_names(*sub, out, valued);
}

}  // namespace

std::string did_you_mean(const CLI::App& root, int argc, char** argv) {
  std::vector<std::string> options;
  std::vector<std::string> valued;
  long_names(root, options, valued);
  const CLI::App* command = &root;
  std::string path = "hula";
  bool command_word_seen = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word.starts_with("--")) {
      const std::string_view name = word.substr(0, word.find('='));
      if (std::find(options.begin(), options.end(), name) != options.end()) {
        // A known option's value is not a command word.
        if (name.size() == word.size() && std::find(valued.begin(), valued.end(), name) != valued.end()) ++i;
        continue;
      }
      const std::string guess = nearest(name, options);
      if (!guess.empty()) return "; did you mean " + guess + "?";
      continue;
    }
    if (word.starts_with("-") || command_word_seen) continue;
    // The first plain word after a command with subcommands names one of them.
    const std::vector<const CLI::App*> subs = named_subcommands(*command);
    if (subs.empty()) {
      command_word_seen = true;
      continue;
    }
    std::vector<std::string> names;
    for (const CLI::App* sub : subs) names.push_back(sub->get_name());
    const auto found = std::find(names.begin(), names.end(), word);
    if (found == names.end()) {
      const std::string guess = nearest(word, names);
      return guess.empty() ? std::string() : "; did you mean `" + path + " " + guess + "`?";
    }
    command = subs[static_cast<std::size_t>(found - names.begin())];
    path += " " + std::string(word);
    long_names(*command, options, valued);
  }
  return {};
}

}  // namespace hula::cli
