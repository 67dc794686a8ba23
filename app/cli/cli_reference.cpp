#include "app/cli/cli_reference.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli/completion_values.hpp"
#include "app/cli/help_format.hpp"
#include "common/error.hpp"

namespace app {
namespace {

bool visible(const CLI::App &command) { return !command.get_group().empty(); }

void collect(const CLI::App &command, const std::string &path, std::vector<CommandNode> &out) {
  out.push_back({path, &command});
  for (const CLI::App *sub : command.get_subcommands([](const CLI::App *) { return true; })) {
    if (!visible(*sub)) continue;
    collect(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), out);
  }
}

std::vector<const CLI::Option *> named_options(const CLI::App &command) {
  std::vector<const CLI::Option *> named;
  for (const CLI::Option *o : command.get_options()) {
    if (o->nonpositional() && !o->get_group().empty()) named.push_back(o);  // "": hidden (old spellings)
  }
  return named;
}

std::vector<const CLI::Option *> positionals(const CLI::App &command) {
  std::vector<const CLI::Option *> found;
  for (const CLI::Option *o : command.get_options()) {
    if (!o->nonpositional() && !o->get_group().empty()) found.push_back(o);
  }
  return found;
}

std::vector<const CLI::App *> subcommands(const CLI::App &command) {
  std::vector<const CLI::App *> found;
  for (const CLI::App *sub : command.get_subcommands([](const CLI::App *) { return true; })) {
    if (visible(*sub)) found.push_back(sub);
  }
  return found;
}

// The length of the description's "VALUE: " prefix (0 when it has none): the words before
// the first ": " are capitals, digits and punctuation, or the word "or".
std::size_t value_prefix_length(const std::string &description) {
  const std::size_t colon = description.find(": ");
  if (colon == std::string::npos || colon == 0 || colon > 32) return 0;
  std::istringstream words(description.substr(0, colon));
  for (std::string word; words >> word;) {
    if (word == "or" || word.find('|') != std::string::npos) continue;  // "NAME or FILE", "e|10"
    if (!std::isupper(static_cast<unsigned char>(word[0]))) return 0;
  }
  return colon + 2;
}

// The description without its "VALUE: " prefix.
std::string description_text(const CLI::Option &option) {
  return option.get_description().substr(value_prefix_length(option.get_description()));
}

// A short description for the completion menus: the first clause, at most 70 characters.
std::string short_text(std::string text) {
  for (const char *end : {"; ", " ("}) {
    const std::size_t at = text.find(end);
    if (at != std::string::npos && at > 10) text.resize(at);
  }
  if (text.size() > 70) text = text.substr(0, text.rfind(' ', 67)) + "...";
  return text;
}

std::string command_line(const CommandNode &node) {
  return node.path.empty() ? std::string("maze_mapper") : "maze_mapper " + node.path;
}

// --- roff -----------------------------------------------------------------------------------

std::string roff(const std::string &text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') {
      out += "\\e";
    } else if (c == '-') {
      out += "\\-";
    } else {
      out += c;
    }
  }
  // A line starting with . or ' would be a request.
  std::string escaped;
  bool line_start = true;
  for (const char c : out) {
    if (line_start && (c == '.' || c == '\'')) escaped += "\\&";
    escaped += c;
    line_start = c == '\n';
  }
  return escaped;
}

std::string usage_synopsis(const CommandNode &node) {
  std::string text = fmt::format("\\fB{}\\fR", roff(command_line(node)));
  for (const CLI::Option *p : positionals(*node.app)) {
    const std::string name = fmt::format("\\fI{}\\fR{}", roff(p->get_name()), p->get_items_expected_max() > 1 ? "..." : "");
    text += p->get_required() ? " " + name : " [" + name + "]";
  }
  if (!subcommands(*node.app).empty()) text += node.app->get_require_subcommand_min() > 0 ? " \\fICOMMAND\\fR" : " [\\fICOMMAND\\fR]";
  if (!named_options(*node.app).empty()) text += " [\\fIOPTIONS\\fR]";
  return text;
}

void man_command(const CommandNode &node, std::string &out) {
  out += fmt::format(".SS {}\n", node.path.empty() ? std::string("\"maze_mapper\"") : "\"" + roff(node.path) + "\"");
  out += usage_synopsis(node) + "\n.br\n";
  out += roff(node.app->get_description()) + "\n";
  for (const CLI::Option *p : positionals(*node.app)) {
    out += fmt::format(".TP\n\\fI{}\\fR\n{}\n", roff(p->get_name()), roff(p->get_description()));
  }
  // In --help's order of groups (app/cli/help_format.hpp), each group's options as registered.
  std::vector<const CLI::Option *> options = named_options(*node.app);
  const auto rank = [](const CLI::Option *o) {
    const std::vector<std::string> order{"Options", kWorldGroup, kRobotGroup, kExplorationGroup, kFaultsGroup, kOutputGroup};
    return static_cast<std::size_t>(std::find(order.begin(), order.end(), o->get_group()) - order.begin());
  };
  std::stable_sort(options.begin(), options.end(),
                   [&rank](const CLI::Option *a, const CLI::Option *b) { return rank(a) < rank(b); });
  std::string group;
  for (const CLI::Option *o : options) {
    if (o->get_group() != group && o->get_group() != "Options" && o->get_group() != "OPTIONS") {
      out += fmt::format(".PP\n\\fI{}:\\fR\n", roff(o->get_group()));
    }
    group = o->get_group();
    std::vector<std::string> names;
    for (const std::string &name : option_names(*o)) names.push_back(fmt::format("\\fB{}\\fR", roff(name)));
    const std::string value = value_name(*o);
    out += fmt::format(".TP\n{}{}\n{}\n", fmt::join(names, ", "), value.empty() ? "" : " \\fI" + roff(value) + "\\fR",
                       roff(description_text(*o)));
  }
  const std::vector<const CLI::App *> subs = subcommands(*node.app);
  if (!subs.empty()) {
    std::vector<std::string> names;
    for (const CLI::App *sub : subs) names.push_back("\\fB" + roff(sub->get_name()) + "\\fR");
    out += fmt::format(".PP\nCommands: {} (each below).\n", fmt::join(names, ", "));
  }
}

// --- shells ---------------------------------------------------------------------------------

// One line of words a command's completion offers: its options, the options taking a value,
// its subcommands.
struct CompletionWords {
  std::vector<std::string> options;
  std::vector<std::string> taking_value;
  std::vector<std::string> commands;
};

CompletionWords completion_words(const CLI::App &command) {
  CompletionWords words;
  for (const CLI::Option *o : named_options(command)) {
    for (const std::string &name : option_names(*o)) {
      words.options.push_back(name);
      if (takes_value(*o)) words.taking_value.push_back(name);
    }
  }
  for (const CLI::App *sub : subcommands(command)) words.commands.push_back(sub->get_name());
  return words;
}

// The path as the scripts spell it: "/run", "/demo/1d", "" for the program.
std::string slash_path(const std::string &path) {
  std::string out = path.empty() ? "" : "/" + path;
  for (char &c : out) {
    if (c == ' ') c = '/';
  }
  return out;
}

// A shell word in single quotes.
std::string quoted(const std::string &text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

// What bash's and zsh's completions open with: the command path ("/batch/merge") read from the
// words before the cursor (`loop` counts them, `word` is one), then a case on it of `branches`.
std::string walk_to_command(std::string_view loop, std::string_view word, const std::string &paths,
                            const std::string &branches) {
  return fmt::format(R"(    for (({loop})); do
        word=${{{word}}}
        case "$cmdpath/$word" in
            {paths}) cmdpath="$cmdpath/$word" ;;
        esac
    done
    case "$cmdpath" in
{branches}    esac
)",
                     fmt::arg("loop", loop), fmt::arg("word", word), fmt::arg("paths", paths), fmt::arg("branches", branches));
}

// Whether the command takes a world (a positional WORLD), where the shipped worlds' names complete.
bool takes_world(const CLI::App &command) {
  const std::vector<const CLI::Option *> found = positionals(command);
  return std::any_of(found.begin(), found.end(), [](const CLI::Option *o) { return o->get_name() == "WORLD"; });
}

// The case branches offering each word-valued option's words: `offer` formats one ({0} the
// flag, {1} its words joined by spaces).
std::string value_branches(std::string_view offer) {
  std::string out;
  for (const std::string_view flag : kWordValuedFlags) {
    out += fmt::format(fmt::runtime(offer), flag, fmt::join(option_value_words(flag), " "));
  }
  return out;
}

}  // namespace

std::vector<CommandNode> visible_commands(const CLI::App &root) {
  std::vector<CommandNode> nodes;
  collect(root, "", nodes);
  return nodes;
}

std::vector<std::string> option_names(const CLI::Option &option) {
  std::vector<std::string> names;
  for (const std::string &l : option.get_lnames()) names.push_back("--" + l);
  for (const std::string &s : option.get_snames()) names.push_back("-" + s);
  return names;
}

bool takes_value(const CLI::Option &option) { return option.get_items_expected_max() > 0; }

std::string value_name(const CLI::Option &option) {
  if (!takes_value(option)) return "";
  const std::size_t prefix = value_prefix_length(option.get_description());
  if (prefix > 0) return option.get_description().substr(0, prefix - 2);
  // CLI11's type names, as a reader says them: --max-steps N, --noise X.
  const std::string type = option.get_type_name();
  if (type == "INT" || type == "UINT") return "N";
  if (type == "FLOAT") return "X";
  return "NAME";
}

std::string man_page(const CLI::App &root, const std::string &version) {
  std::string out = fmt::format(".TH MAZE_MAPPER 1 \"\" \"maze_mapper {}\" \"User Commands\"\n", roff(version));
  out += fmt::format(".SH NAME\nmaze_mapper \\- {}\n", roff(root.get_description().substr(root.get_description().find(": ") + 2)));
  out += ".SH SYNOPSIS\n\\fBmaze_mapper\\fR\n.br\n\\fBmaze_mapper\\fR \\fICOMMAND\\fR [\\fIOPTIONS\\fR]\n";
  out += ".SH DESCRIPTION\n"
         "Without arguments, \\fBmaze_mapper\\fR is \\fBmaze_mapper run\\fR on its default world, "
         "lab4x4.txt: a simulated robot explores the maze cell by cell and maps it into an occupancy "
         "grid of log\\-odds values, printed as text as it goes, then a summary.\n"
         ".PP\n\\fBmaze_mapper\\fR \\fICOMMAND\\fR \\fB\\-\\-help\\fR prints a command's options.\n";
  out += ".SH COMMANDS\n";
  for (const CommandNode &node : visible_commands(root)) {
    if (!node.path.empty()) man_command(node, out);
  }
  out += ".SH OPTIONS\n";
  for (const CLI::Option *o : named_options(root)) {
    std::vector<std::string> names;
    for (const std::string &name : option_names(*o)) names.push_back(fmt::format("\\fB{}\\fR", roff(name)));
    out += fmt::format(".TP\n{}\n{}\n", fmt::join(names, ", "), roff(description_text(*o)));
  }
  out += ".SH ENVIRONMENT\n"
         ".TP\n\\fBMAZE_MAPPER_WORLDS\\fR\n"
         "The folder of the shipped worlds, where the default world lab4x4.txt is looked up.\n"
         ".TP\n\\fBNO_COLOR\\fR\nWhen set and not empty, no colours (as \\fB\\-\\-color never\\fR).\n"
         ".TP\n\\fBCOLUMNS\\fR\nThe width \\fB\\-\\-help\\fR wraps its text to.\n";
  out += ".SH FILES\n"
         ".TP\n\\fI../share/maze_mapper/worlds/\\fR (beside the program: \\fI/usr/share/maze_mapper/worlds/\\fR)\n"
         "The shipped worlds, used when \\fBMAZE_MAPPER_WORLDS\\fR is not set and the working directory "
         "has no \\fIworlds/lab4x4.txt\\fR. A \\fIWORLD\\fR given on the command line is a path, relative to "
         "the working directory, or, when nothing is there, a shipped world's name with or without its extension "
         "(\\fBmaze_mapper run maze8x8\\fR); \\fBmaze_mapper worlds\\fR lists them.\n";
  out += ".SH EXIT STATUS\n"
         ".TP\n\\fB0\\fR\nThe command did what was asked.\n"
         ".TP\n\\fB1\\fR\nA run did not map its maze, or did not deliver what was asked besides (a path, a "
         "speed run); in \\fBbatch\\fR, some worlds failed; in \\fBmms\\fR, the algorithm failed or the robot "
         "did not reach the goal.\n"
         ".TP\n\\fB2\\fR\nBad input or usage: one \\fBerror:\\fR line on standard error.\n"
         ".TP\n\\fB4\\fR\nAn output could not be written for lack of space (the summary is still printed).\n"
         ".TP\n\\fB129\\fR\nStopped by SIGHUP (the terminal closed).\n"
         ".TP\n\\fB130\\fR\nStopped by SIGINT (Ctrl\\-C).\n"
         ".TP\n\\fB143\\fR\nStopped by SIGTERM (kill, timeout).\n";
  out += ".SH SEE ALSO\n/usr/share/doc/maze-mapper/README.md and the docs/ folder beside it.\n";
  return out;
}


std::string bash_completion(const CLI::App &root) {
  const std::vector<CommandNode> nodes = visible_commands(root);
  std::string paths;
  std::string branches;
  for (const CommandNode &node : nodes) {
    const std::string path = slash_path(node.path);
    if (!path.empty()) paths += (paths.empty() ? "" : "|") + path;
    const CompletionWords words = completion_words(*node.app);
    branches += fmt::format("    \"{}\") commands=\"{}\"; options=\" {} \"; taking_value=\" {} \"; worlds=\"{}\" ;;\n",
                            path, fmt::join(words.commands, " "), fmt::join(words.options, " "),
                            fmt::join(words.taking_value, " "), takes_world(*node.app) ? "$shipped" : "");
  }
  return fmt::format(R"(# bash completion for maze_mapper, generated from its command definitions
# (maze_mapper {ref} bash).
_maze_mapper() {{
    local cur=${{COMP_WORDS[COMP_CWORD]}} prev=${{COMP_WORDS[COMP_CWORD-1]}}
    local cmdpath="" word i commands options taking_value worlds shipped="{shipped}"
{walk}    if [[ "$prev" == -* && "$taking_value" == *" $prev "* ]]; then
        case "$prev" in
{values}            *) COMPREPLY=($(compgen -f -- "$cur")) ;;
        esac
    elif [[ "$cur" == -* ]]; then
        COMPREPLY=($(compgen -W "$options" -- "$cur"))
    else
        COMPREPLY=($(compgen -W "$commands $worlds" -- "$cur") $(compgen -f -- "$cur"))
    fi
}}
complete -o filenames -F _maze_mapper maze_mapper
)",
                     fmt::arg("ref", kReferenceCommand), fmt::arg("shipped", fmt::join(shipped_world_names(), " ")),
                     fmt::arg("values", value_branches("            {}) COMPREPLY=($(compgen -W \"{}\" -- \"$cur\")) ;;\n")),
                     fmt::arg("walk", walk_to_command("i = 1; i < COMP_CWORD; i++", "COMP_WORDS[i]", paths, branches)));
}

std::string zsh_completion(const CLI::App &root) {
  const std::vector<CommandNode> nodes = visible_commands(root);
  std::string paths;
  std::string branches;
  for (const CommandNode &node : nodes) {
    const std::string path = slash_path(node.path);
    if (!path.empty()) paths += (paths.empty() ? "" : "|") + path;
    std::vector<std::string> commands;
    for (const CLI::App *sub : subcommands(*node.app)) {
      commands.push_back(quoted(sub->get_name() + ":" + short_text(sub->get_description())));
    }
    std::vector<std::string> options;
    std::vector<std::string> taking_value;
    for (const CLI::Option *o : named_options(*node.app)) {
      for (const std::string &name : option_names(*o)) {
        options.push_back(quoted(name + ":" + short_text(description_text(*o))));
        if (takes_value(*o)) taking_value.push_back(name);
      }
    }
    branches += fmt::format("    \"{}\") subs=({}); opts=({}); valued=({}); worlds={} ;;\n", path,
                            fmt::join(commands, " "), fmt::join(options, " "), fmt::join(taking_value, " "),
                            takes_world(*node.app) ? 1 : 0);
  }
  return fmt::format(R"(#compdef maze_mapper
# zsh completion for maze_mapper, generated from its command definitions
# (maze_mapper {ref} zsh).
_maze_mapper() {{
    local cmdpath="" word i worlds=0
    # Not commands, options: zsh's own (zsh/parameter) parameters.
    local -a subs opts valued
{walk}    if (( ${{valued[(Ie)${{words[CURRENT-1]}}]}} )); then
        case ${{words[CURRENT-1]}} in
{values}            *) _files ;;
        esac
    elif [[ $PREFIX == -* ]]; then
        _describe -t options option opts
    else
        (( ${{#subs}} )) && _describe -t commands command subs
        (( worlds )) && compadd -X 'shipped worlds' -- {shipped}
        _files
    fi
}}
_maze_mapper "$@"
)",
                     fmt::arg("ref", kReferenceCommand), fmt::arg("shipped", fmt::join(shipped_world_names(), " ")),
                     fmt::arg("values", value_branches("            {}) compadd -- {} ;;\n")),
                     fmt::arg("walk", walk_to_command("i = 2; i < CURRENT; i++", "words[i]", paths, branches)));
}

std::string fish_completion(const CLI::App &root) {
  std::string out = fmt::format(
      "# fish completion for maze_mapper, generated from its command definitions\n# (maze_mapper {} fish).\n",
      kReferenceCommand);
  for (const CommandNode &node : visible_commands(root)) {
    // Where the completion applies: every word of the path seen, and none of its subcommands.
    std::vector<std::string> conditions;
    std::istringstream words(node.path);
    for (std::string word; words >> word;) conditions.push_back("__fish_seen_subcommand_from " + word);
    const std::vector<const CLI::App *> subs = subcommands(*node.app);
    std::vector<std::string> sub_names;
    for (const CLI::App *sub : subs) sub_names.push_back(sub->get_name());
    if (node.path.empty()) {
      conditions.push_back("__fish_use_subcommand");
    } else if (!sub_names.empty()) {
      conditions.push_back(fmt::format("not __fish_seen_subcommand_from {}", fmt::join(sub_names, " ")));
    }
    const std::string condition = quoted(fmt::format("{}", fmt::join(conditions, "; and ")));
    for (const CLI::App *sub : subs) {
      out += fmt::format("complete -c maze_mapper -n {} -a {} -d {}\n", condition, sub->get_name(),
                         quoted(short_text(sub->get_description())));
    }
    if (takes_world(*node.app)) {
      out += fmt::format("complete -c maze_mapper -n {} -a {} -d 'shipped world'\n", condition,
                         quoted(fmt::format("{}", fmt::join(shipped_world_names(), " "))));
    }
    for (const CLI::Option *o : named_options(*node.app)) {
      std::string names;
      for (const std::string &l : o->get_lnames()) names += " -l " + l;
      for (const std::string &s : o->get_snames()) names += " -s " + s;
      const std::vector<std::string> values = o->get_lnames().empty() ? std::vector<std::string>{}
                                                                     : option_value_words("--" + o->get_lnames()[0]);
      const std::string taking = values.empty() ? (takes_value(*o) ? " -r" : "")
                                                : fmt::format(" -x -a {}", quoted(fmt::format("{}", fmt::join(values, " "))));
      out += fmt::format("complete -c maze_mapper -n {}{}{} -d {}\n", condition, names, taking,
                         quoted(short_text(description_text(*o))));
    }
  }
  return out;
}

void add_reference_command(CLI::App &root) {
  CLI::App *reference = root.add_subcommand(kReferenceCommand, "print the man page or a shell completion script");
  reference->group("");  // hidden: the build's tool, not the user's
  auto format = std::make_shared<std::string>();
  reference->add_option("FORMAT", *format, "man, bash, zsh or fish")->required();
  reference->callback([&root, format] {
    if (*format == "man") {
      std::cout << man_page(root, MAZE_MAPPER_VERSION);
    } else if (*format == "bash") {
      std::cout << bash_completion(root);
    } else if (*format == "zsh") {
      std::cout << zsh_completion(root);
    } else if (*format == "fish") {
      std::cout << fish_completion(root);
    } else {
      throw common::InputError(fmt::format("{}: unknown format '{}' (choose man, bash, zsh or fish)",
                                           kReferenceCommand, *format));
    }
  });
}

}  // namespace app
