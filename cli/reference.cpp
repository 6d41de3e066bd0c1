// The man page and the bash and zsh completions of splinefig, from the App the parser uses
// (reference.hpp).
#include "reference.hpp"

#include <map>
#include <sstream>

namespace splinefig::cli {

namespace {

std::map<const CLI::Option*, std::vector<std::string>>& choice_table() {
  static std::map<const CLI::Option*, std::vector<std::string>> table;
  return table;
}

std::vector<const CLI::App*> commands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App* sub) { return !sub->get_group().empty(); });
}

std::vector<const CLI::Option*> options(const CLI::App& app) {
  return app.get_options([](const CLI::Option* o) { return shown(o) && !o->get_positional(); });
}

std::vector<const CLI::Option*> positionals(const CLI::App& app) {
  return app.get_options([](const CLI::Option* o) { return o->get_positional(); });
}

// A flag expects no value (CLI11: expected(0)).
bool takes_value(const CLI::Option* o) { return o->get_items_expected_max() > 0; }

// "-o", "--output": every name of an option as typed.
std::vector<std::string> names(const CLI::Option* o) {
  std::vector<std::string> out;
  for (const auto& n : o->get_snames()) out.push_back("-" + n);
  for (const auto& n : o->get_lnames()) out.push_back("--" + n);
  return out;
}

// A file or directory is the value (PATH), so the completions offer file names.
bool takes_path(const CLI::Option* o) { return o->get_type_name() == "PATH"; }

// The app's description without a leading "splinefig: ".
std::string summary(const CLI::App& app) {
  std::string d = app.get_description();
  const std::string lead = app.get_name() + ": ";
  if (d.rfind(lead, 0) == 0) d = d.substr(lead.size());
  return d;
}

// ---- roff ----

// Text for a man page line: backslashes and dashes escaped (\e, \-: an option typed from the
// page is the option), a control character at the line's start made text (\&).
std::string roff(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out.insert(0, "\\&");
  return out;
}

// A description as a sentence of the page: ending in a full stop.
std::string sentence(const std::string& text) { return text.empty() || text.back() == '.' ? text : text + "."; }

std::string bold(const std::string& s) { return "\\fB" + roff(s) + "\\fR"; }
std::string italic(const std::string& s) { return "\\fI" + roff(s) + "\\fR"; }

// What the option's value is: its choices (a|b|c) or its type.
std::string value_roff(const CLI::Option* o) {
  if (!takes_value(o)) return "";
  const auto& values = choices_of(o);
  if (values.empty()) return " " + italic(o->get_type_name());
  std::string s = " ";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? "|" : "") + italic(values[i]);
  return s;
}

// The paragraphs of a footer: "Example: ..." shown as a literal line, the rest filled.
void footer_roff(std::ostringstream& m, const std::string& footer) {
  std::istringstream in(footer);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::string example = "Example: ";
    if (line.rfind(example, 0) == 0) {
      m << ".PP\nExample:\n.RS\n.nf\n" << roff(line.substr(example.size())) << "\n.fi\n.RE\n";
    } else {
      m << ".PP\n" << roff(line) << "\n";
    }
  }
}

void options_roff(std::ostringstream& m, const CLI::App& app) {
  for (const CLI::Option* o : positionals(app)) {
    m << ".TP\n" << italic(o->get_name()) << "\n" << roff(sentence(o->get_description()));
    m << (o->get_required() ? " Required." : " Optional.") << "\n";
  }
  for (const CLI::Option* o : options(app)) {
    std::string head;
    for (const auto& n : names(o)) head += (head.empty() ? "" : ", ") + bold(n);
    m << ".TP\n" << head << value_roff(o) << "\n" << roff(sentence(o->get_description()));
    if (o->get_required()) m << " Required.";
    if (takes_value(o) && !o->get_default_str().empty()) m << " Default: " << roff(o->get_default_str()) << ".";
    m << "\n";
  }
}

std::string usage_roff(const CLI::App& sub, const std::string& program) {
  std::string s = bold(program + " " + sub.get_name()) + " [" + italic("OPTIONS") + "]";
  for (const CLI::Option* o : positionals(sub))
    s += o->get_required() ? " " + italic(o->get_name()) : " [" + italic(o->get_name()) + "]";
  return s;
}

// ---- shell words ----

std::string join(const std::vector<std::string>& words, const std::string& sep = " ") {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : sep) + w;
  return s;
}

// A word in single quotes for sh and zsh.
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::vector<std::string> option_words(const CLI::App& app) {
  std::vector<std::string> words;
  for (const CLI::Option* o : options(app))
    for (const auto& n : names(o)) words.push_back(n);
  return words;
}

// An _arguments explanation: [ ] and \ escaped, one line (its messages are type names, without colons).
std::string zsh_text(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '[' || c == ']' || c == '\\') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out;
}

}  // namespace

CLI::Option* choices(CLI::Option* option, std::vector<std::string> values) {
  choice_table()[option] = std::move(values);
  return option;
}

const std::vector<std::string>& choices_of(const CLI::Option* option) {
  static const std::vector<std::string> none;
  const auto it = choice_table().find(option);
  return it == choice_table().end() ? none : it->second;
}

std::string man_page(const CLI::App& app, const std::string& version) {
  const std::string program = app.get_name();
  std::ostringstream m;
  m << ".\\\" Generated by `" << program << " --help-man` from the command's option tables; do not edit.\n";
  m << ".TH SPLINEFIG 1 \"\" \"" << roff(program + " " + version) << "\" \"User Commands\"\n";
  m << ".nh\n.ad l\n";
  m << ".SH NAME\n" << roff(program) << " \\- " << roff(summary(app)) << "\n";
  m << ".SH SYNOPSIS\n" << bold(program) << " " << italic("COMMAND") << " [" << italic("OPTIONS") << "]\n.br\n";
  for (const CLI::Option* o : options(app)) m << bold(program) << " " << bold(names(o).back()) << "\n.br\n";
  m << ".SH DESCRIPTION\n"
    << roff(program + " COMMAND --help shows a command's options with their types and defaults. "
            "The commands share their conventions (basis specs, the kernel, pixel coordinates, colours, CSV, "
            "error lines): see the documentation, docs/cli.md and docs/conventions.md under share/doc/splinefig.")
    << "\n";
  m << ".SH OPTIONS\n";
  options_roff(m, app);
  m << ".SH COMMANDS\n";
  for (const CLI::App* sub : commands(app)) {
    m << ".SS " << roff(program + " " + sub->get_name()) << "\n";
    m << usage_roff(*sub, program) << "\n.PP\n" << roff(sentence(sub->get_description())) << "\n";
    options_roff(m, *sub);
    footer_roff(m, sub->get_footer());
  }
  m << ".SH EXIT STATUS\n"
    << roff("0 on success; 2 for a bad flag or value, bad input or an output that cannot be written, with one "
            "line on standard error naming what and where. diff keeps idiff's codes: 0 match, 1 warning, "
            "2 failure, 4 a file that cannot be read or written.")
    << "\n";
  m << ".SH SEE ALSO\n" << roff("docs/cli.md, docs/spec.md and docs/resample.md in share/doc/splinefig; idiff(1).") << "\n";
  return m.str();
}

std::string bash_completion(const CLI::App& app) {
  const std::string fn = "_" + app.get_name();
  std::ostringstream b;
  b << "# bash completion for " << app.get_name() << ": generated by `" << app.get_name()
    << " --completion bash` from the command's option tables; do not edit.\n";
  b << fn << "_files() {\n"
    << "  compopt -o filenames 2>/dev/null\n"
    << "  mapfile -t COMPREPLY < <(compgen -f -- \"$cur\")\n"
    << "}\n";
  b << fn << "_words() {\n"
    << "  mapfile -t COMPREPLY < <(compgen -W \"$1\" -- \"$cur\")\n"
    << "}\n";
  b << fn << "() {\n"
    << "  local cur=${COMP_WORDS[COMP_CWORD]} prev='' cmd='' i\n"
    << "  (( COMP_CWORD > 0 )) && prev=${COMP_WORDS[COMP_CWORD-1]}\n"
    << "  COMPREPLY=()\n"
    << "  for (( i = 1; i < COMP_CWORD; i++ )); do\n"
    << "    case ${COMP_WORDS[i]} in\n"
    << "      -*) ;;\n"
    << "      *) cmd=${COMP_WORDS[i]}; break ;;\n"
    << "    esac\n"
    << "  done\n"
    << "  case $cmd in\n";
  std::vector<std::string> top;
  for (const CLI::App* sub : commands(app)) top.push_back(sub->get_name());
  for (const auto& w : option_words(app)) top.push_back(w);
  b << "    '') " << fn << "_words " << quoted(join(top)) << " ;;\n";
  for (const CLI::App* sub : commands(app)) {
    b << "    " << quoted(sub->get_name()) << ")\n";
    b << "      case $prev in\n";
    for (const CLI::Option* o : options(*sub)) {
      if (!takes_value(o)) continue;
      b << "        " << join(names(o), "|") << ") ";
      if (!choices_of(o).empty())
        b << fn << "_words " << quoted(join(choices_of(o))) << "; ";
      else if (takes_path(o))
        b << fn << "_files; ";
      b << "return 0 ;;\n";
    }
    b << "      esac\n";
    const std::string words = fn + "_words " + quoted(join(option_words(*sub)));
    if (positionals(*sub).empty())
      b << "      " << words << " ;;\n";
    else
      b << "      if [[ $cur == -* ]]; then " << words << "; else " << fn << "_files; fi ;;\n";
  }
  b << "  esac\n"
    << "  return 0\n"
    << "}\n"
    << "complete -F " << fn << " " << app.get_name() << "\n";
  return b.str();
}

std::string zsh_completion(const CLI::App& app) {
  const std::string fn = "_" + app.get_name();
  std::ostringstream z;
  z << "#compdef " << app.get_name() << "\n";
  z << "# zsh completion for " << app.get_name() << ": generated by `" << app.get_name()
    << " --completion zsh` from the command's option tables; do not edit.\n";
  // One _arguments spec per option: its names as alternatives, the explanation, the value.
  const auto specs = [](const CLI::App& a) {
    std::vector<std::string> out;
    for (const CLI::Option* o : options(a)) {
      const auto ns = names(o);
      const std::string excl = ns.size() > 1 ? "(" + join(ns) + ")" : "";
      std::string value;
      if (takes_value(o)) {
        const std::string type = zsh_text(o->get_type_name().empty() ? "VALUE" : o->get_type_name());
        if (!choices_of(o).empty())
          value = ":" + type + ":(" + join(choices_of(o)) + ")";
        else if (takes_path(o))
          value = ":" + type + ":_files";
        else
          value = ":" + type + ": ";
      }
      const std::string body = "[" + zsh_text(o->get_description()) + "]" + value;
      if (ns.size() > 1)
        out.push_back(quoted(excl) + "{" + join(ns, ",") + "}" + quoted(body));
      else
        out.push_back(quoted(ns.front() + body));
    }
    int n = 0;
    for (const CLI::Option* o : positionals(a)) {
      ++n;
      const std::string what = zsh_text(o->get_name());
      out.push_back(quoted((o->get_required() ? std::to_string(n) + ":" : std::to_string(n) + "::") + what + ":_files"));
    }
    return out;
  };
  z << fn << "() {\n"
    << "  local curcontext=$curcontext state line ret=1\n"
    << "  local -a commands\n"
    << "  commands=(\n";
  for (const CLI::App* sub : commands(app))
    z << "    " << quoted(sub->get_name() + ":" + sub->get_description()) << "\n";
  z << "  )\n"
    << "  _arguments -C \\\n";
  for (const auto& s : specs(app)) z << "    " << s << " \\\n";
  z << "    '1: :->command' \\\n"
    << "    '*:: :->args' && ret=0\n"
    << "  case $state in\n"
    << "    command) _describe -t commands " << quoted(app.get_name() + " command") << " commands && ret=0 ;;\n"
    << "    args)\n"
    << "      case $words[1] in\n";
  for (const CLI::App* sub : commands(app)) {
    z << "        " << quoted(sub->get_name()) << ")\n"
      << "          _arguments \\\n";
    for (const auto& s : specs(*sub)) z << "            " << s << " \\\n";
    z << "            && ret=0 ;;\n";
  }
  z << "      esac ;;\n"
    << "  esac\n"
    << "  return ret\n"
    << "}\n"
    << fn << " \"$@\"\n";
  return z.str();
}

}  // namespace splinefig::cli
