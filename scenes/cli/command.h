#pragma once
// How a command is added, declared once. A command file holds an options
// struct, a function that adds its options to the parser (add_options) and
// the function that runs it (run); add_command ties them together with one
// options object shared by the parser and the run.

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

namespace railjoint::cli {

template <class Options>
CLI::App* add_command(CLI::App& parent, const std::string& name, const std::string& description,
                      void (*add_options)(CLI::App&, Options&), void (*run)(const Options&)) {
  auto options = std::make_shared<Options>();
  CLI::App* cmd = parent.add_subcommand(name, description);
  add_options(*cmd, *options);
  cmd->callback([options, run] { run(*options); });
  return cmd;
}

}  // namespace railjoint::cli
