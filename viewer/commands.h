// The cetview subcommands, described without the command-line library: each returns its name, help,
// options (each bound to a field of the command's own settings) and the function that runs it, which
// returns the exit code: 0 success, 1 a runtime failure, 2 bad input or usage. main.cpp alone turns
// them into CLI11 options, so CLI11's header-only parser is compiled once, not once per command.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace cetview {

struct CommandOption {
  // Where the parsed value goes; a bool is a flag (no value).
  using Target = std::variant<std::string*, std::vector<std::string>*, unsigned*, int*, bool*>;
  std::string names;  // "-o,--output", "--json", or a bare name for a positional argument
  Target target;
  std::string help;
  bool required = false;
  bool showDefault = false;  // print the field's initial value in --help
};

struct Command {
  Command(std::string commandName, std::string commandDescription)
      : name(std::move(commandName)), description(std::move(commandDescription)) {}

  std::string name;
  std::string description;
  std::vector<CommandOption> options;
  std::function<int()> run;

  Command& option(std::string names, CommandOption::Target target, std::string help) {
    options.push_back({std::move(names), target, std::move(help), false, false});
    return *this;
  }
  Command& required(std::string names, CommandOption::Target target, std::string help) {
    options.push_back({std::move(names), target, std::move(help), true, false});
    return *this;
  }
  Command& withDefault(std::string names, CommandOption::Target target, std::string help) {
    options.push_back({std::move(names), target, std::move(help), false, true});
    return *this;
  }
};

Command cdtCommand();
Command exportCommand();
Command benchCommand();
Command renderCommand();
Command viewCommand();

}  // namespace cetview
