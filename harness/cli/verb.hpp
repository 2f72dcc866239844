// A verb of the command line (`rotbench VERB ...`): one file each under harness/cli/, which
// registers itself, adds its options to its own subcommand and runs. main() only dispatches
// (harness/cli/cli.cpp).
#pragma once

#include "schemes/registry.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rotbench {

// What every verb may need of the invocation.
struct Invocation {
    std::vector<std::string> arguments;  // as given, without the program name (kept for --resume)
    std::string command_line;            // "rotbench " and the arguments, for reports
    std::ostream& out;
    std::ostream& err;
    std::optional<std::filesystem::path> resuming;  // the directory of an interrupted run being finished
    std::function<void()> load_plugins;             // the --plugin libraries, loaded when called
};

class Verb {
public:
    virtual ~Verb() = default;
    virtual void add_options(CLI::App& command) = 0;
    // Returns the exit status: 0 done, 1 a check failed (gate), 2 bad input (InputError).
    virtual int run(const Invocation& invocation) = 0;
    // True when this invocation loads the plug-ins itself, later (run --resume: they are
    // among the interrupted run's own arguments). Otherwise they are loaded before run().
    virtual bool defers_plugins() const { return false; }
    // True for a verb that journals its runs, and so may be finished by `run --resume`: no
    // other verb is ever run from the arguments an output folder holds.
    virtual bool resumable() const { return false; }
};

using VerbRegistry = Registry<Verb>;

// A verb whose name starts with "__" is rotbench's own (the isolated run's worker): hidden
// from help and error messages, and quiet on stderr, which its parent reads.
inline bool internal_verb(const std::string& name) { return name.rfind("__", 0) == 0; }

// The verbs a user may give, in the registry's order.
inline std::vector<std::string> user_verbs() {
    std::vector<std::string> names;
    for (const auto& name : VerbRegistry::instance().ids())
        if (!internal_verb(name)) names.push_back(name);
    return names;
}

template <class V>
struct RegisterVerb {
    RegisterVerb(std::string name, std::string summary) {
        VerbRegistry::instance().add({std::move(name), std::move(summary), "", "", [] { return std::make_unique<V>(); }});
    }
};

// The command line given as arguments (without the program name); `resuming` as above. The
// run verb calls it again for --resume, with the interrupted run's arguments.
int run_cli_arguments(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err,
                      const std::optional<std::filesystem::path>& resuming);

}  // namespace rotbench
