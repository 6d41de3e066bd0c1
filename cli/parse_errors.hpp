#pragma once
// Command-line parse errors in splinefig's words: one line, "splinefig COMMAND: ...", naming
// what is wrong, with a suggestion for a near miss of a flag, command or name (docs/cli.md).
// main.cpp reports the first argument a command does not take (CLI11's remaining(), in the order
// typed) before any other error of the command.
#include <splinefig/spline/near_miss.hpp>
#include <splinefig/spline/points_csv.hpp>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace splinefig::cli {

// "-o/--output" for an option, "B" for a positional, as the messages name them.
inline std::string option_names(const CLI::Option& o) {
  if (o.get_positional()) {
    std::string n = o.get_name();
    for (char& c : n) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return n;
  }
  std::string s;
  for (const auto& n : o.get_snames()) s += (s.empty() ? "-" : "/-") + n;
  for (const auto& n : o.get_lnames()) s += (s.empty() ? "--" : "/--") + n;
  return s;
}

// The flags of `app` as typed: "--scale", "-o", "--output" (and --help); `hidden`: also those
// --help does not show (an empty group: --help-man, --completion), never suggested.
inline std::vector<std::string> flag_names(const CLI::App& app, bool hidden = false) {
  std::vector<std::string> out;
  for (const CLI::Option* o : app.get_options()) {
    if (!hidden && o->get_group().empty()) continue;
    for (const auto& n : o->get_lnames()) out.push_back("--" + n);
    for (const auto& n : o->get_snames()) out.push_back("-" + n);
  }
  return out;
}

// "splinefig render SPEC -o PATH [options]": positionals, then the required flags.
inline std::string usage(const CLI::App& app) {
  std::string s = "splinefig " + app.get_name();
  for (const CLI::Option* o : app.get_options())
    if (o->get_positional()) s += o->get_required() ? " " + option_names(*o) : " [" + option_names(*o) + "]";
  for (const CLI::Option* o : app.get_options())
    if (!o->get_positional() && o->get_required()) {
      const std::string first = o->get_snames().empty() ? "--" + o->get_lnames().front() : "-" + o->get_snames().front();
      s += " " + first + " " + o->get_type_name();
    }
  return s + " [options]";
}

// Near misses of a flag among `flags`, compared without their dashes: "--scal" -> "--scale".
// A one-letter flag near-misses the long flags it begins: "-v" -> "--version".
inline std::vector<std::string> near_flags(const std::string& flag, const std::vector<std::string>& flags) {
  const auto bare = [](const std::string& f) { return f.substr(f.find_first_not_of('-') == std::string::npos ? f.size() : f.find_first_not_of('-')); };
  std::vector<std::string> names;
  for (const auto& f : flags) names.push_back(bare(f));
  const std::string word = bare(flag);
  std::vector<std::string> out;
  if (word.size() == 1) {
    const auto low = [](char c) { return std::tolower(static_cast<unsigned char>(c)); };
    for (const auto& f : flags)
      if (f.size() == 2 && f != flag && low(f[1]) == low(word[0])) return {f};  // -o for -O
    for (const auto& f : flags)
      if (f.size() > 3 && f.rfind("--", 0) == 0 && low(f[2]) == low(word[0])) out.push_back(f);
    return out;
  }
  for (const auto& n : near_misses(word, names))
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == n && std::find(out.begin(), out.end(), flags[i]) == out.end()) out.push_back(flags[i]);
  return out;
}

// An argument `sub` does not take (the first it kept, as typed): "unknown option --scal (did you
// mean --scale?)", "--filter is an option of resample, not of render", "unexpected argument 'c'".
inline std::string extra_argument_message(const CLI::App& top, const CLI::App& sub, const std::string& arg) {
  const bool option = arg.size() > 1 && arg[0] == '-' && !(std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.');
  if (!option)
    return "unexpected argument '" + printable(arg) + "' (usage: " + usage(sub) + "; see splinefig " + sub.get_name() +
           " --help)";
  const std::string flag = arg.substr(0, arg.find('='));
  std::string msg = "unknown option " + printable(flag);
  const auto near = near_flags(flag, flag_names(sub));
  if (!near.empty()) return msg + " (did you mean " + or_list(near) + "?)";
  std::vector<std::string> owners;
  for (const CLI::App* other : top.get_subcommands([](const CLI::App*) { return true; })) {
    const auto names = flag_names(*other);
    if (other != &sub && std::find(names.begin(), names.end(), flag) != names.end()) owners.push_back(other->get_name());
  }
  if (!owners.empty()) return msg + " (" + flag + " is an option of " + or_list(owners) + ", not of " + sub.get_name() + ")";
  const auto own = flag_names(top);
  if (std::find(own.begin(), own.end(), flag) != own.end())
    return msg + " (" + flag + " is an option of splinefig itself: splinefig " + flag + ")";
  return msg + " (see splinefig " + sub.get_name() + " --help)";
}

// The required arguments `sub` was not given, in words: "missing B, the second (actual) image".
inline std::string missing_message(const CLI::App& sub) {
  std::vector<std::string> missing;
  for (const CLI::Option* o : sub.get_options()) {
    if (!o->get_required() || o->count() > 0) continue;
    // The description's first clause: "Figure spec (TOML, see docs/spec.md); - reads it from stdin"
    // is named "SPEC, the figure spec (TOML, see docs/spec.md)" in a list of what is missing.
    std::string d = o->get_description().substr(0, o->get_description().find(';'));
    if (!d.empty()) d[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(d[0])));
    missing.push_back(o->get_positional() && !d.empty() ? option_names(*o) + ", the " + d
                                                        : option_names(*o) + " " + o->get_type_name());
  }
  std::string list;
  for (std::size_t i = 0; i < missing.size(); ++i)
    list += (i == 0 ? "" : i + 1 == missing.size() ? (missing.size() > 2 ? ", and " : " and ") : ", ") + missing[i];
  return "missing " + list + "; usage: " + usage(sub);
}

// A flag's value that CLI11 could not take, from its error text (CLI11 2.1 gives no more).
inline std::string value_message(const CLI::App& sub, const CLI::ParseError& e) {
  std::string msg = e.what();
  for (char& c : msg)
    if (c == '\n') c = ' ';
  const auto named = [&](const std::string& name) -> const CLI::Option* {
    try {
      return sub.get_option(name);
    } catch (const CLI::Error&) {
      return nullptr;
    }
  };
  const auto kind = [](const CLI::Option* o) -> std::string {
    const std::string t = o ? o->get_type_name() : "";
    if (t == "INT") return "an integer";
    if (t == "UINT") return "a whole number >= 0";
    if (t == "FLOAT" || t == "NUMBER") return "a number";
    return t.empty() ? "a value" : t;
  };
  const std::string convert = "Could not convert: ";
  if (msg.rfind(convert, 0) == 0) {
    const auto eq = msg.find(" = ", convert.size());
    if (eq != std::string::npos) {
      const std::string name = msg.substr(convert.size(), eq - convert.size());
      return name + " " + printable(msg.substr(eq + 3)) + ": not " + kind(named(name));
    }
  }
  const auto colon = msg.find(": ");
  if (colon != std::string::npos) {
    const std::string name = msg.substr(0, colon), rest = msg.substr(colon + 2);
    if (const CLI::Option* o = named(name)) {
      if (rest.find(" required ") != std::string::npos && rest.size() > 8 && rest.substr(rest.size() - 8) == " missing")
        return option_names(*o) + " needs a value (" + kind(o) + ")";
      if (rest.rfind("At Most ", 0) == 0) return option_names(*o) + " is given more than once";
      if (rest.find("too many inputs for a flag") != std::string::npos) return option_names(*o) + " takes no value";
    }
  }
  return printable(msg) + " (see splinefig " + sub.get_name() + " --help)";
}

}  // namespace splinefig::cli
