#include "harness/cli/cli.hpp"

#include "reports/escape.hpp"

#include "harness/cli/verb.hpp"
#include "harness/exec/machine.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/client.hpp"
#include "harness/store/plugin.hpp"
#include "harness/store/reference_cache.hpp"

#include "build_info.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <memory>

namespace rotbench {
namespace {

// An option given with an empty value ("--scenes ''", often an unset shell variable) is bad
// input, never a silent "the default".
void refuse_empty_values(const CLI::App& app) {
    for (const auto* option : app.get_options())
        for (const auto& value : option->results())
            if (value.empty()) throw InputError(option->get_name() + ": the value is empty; give one or leave the option out");
    for (const auto* sub : app.get_subcommands()) refuse_empty_values(*sub);
}

std::string version_text() {
    return fmt::format("rotbench {} (commit {})\ncompiler {}, {} build\nflags {}\n", build_info::version, build_info::commit,
                       build_info::compiler, build_info::build_type, build_info::flags);
}

// The exception being handled, as the exit status and the one line a user reads: 0 for help,
// 2 for bad input (nothing was started), 3 for what stopped the work once started (a full disk,
// memory), 4 for a bug of rotbench's. Called from a catch block only.
int exit_status(const CLI::App& app, std::ostream& out, std::ostream& err) {
    try {
        throw;
    } catch (const CLI::CallForHelp&) {
        out << app.help();
        return 0;
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            out << app.help();
            return 0;
        }
        err << "rotbench: " << terminal_line(e.what()) << " (see rotbench --help)\n";
        return 2;
    } catch (const InputError& e) {
        err << "rotbench: " << terminal_line(e.what()) << "\n";
        return 2;
    } catch (const std::filesystem::filesystem_error& e) {  // an output path that is not a writable directory
        err << "rotbench: " << terminal_line(e.what()) << "\n";
        return 2;
    } catch (const OutputError& e) {  // a full disk once the work had started: what is finished is kept
        err << "rotbench: " << terminal_line(e.what()) << "\n";
        return 3;
    } catch (const std::bad_alloc&) {  // the machine's or the batch system's limit, met once the work had started
        err << "rotbench: out of memory: what was asked for outgrew what this process may have (ulimit -v, the machine); "
               "ask for less (--samples, --t-end, --jobs, --ensemble)\n";
        return 3;
    } catch (const std::exception& e) {  // a bug of rotbench's: said in one line, not an abort
        err << "rotbench: internal error: " << terminal_line(e.what()) << "\n";
        return 4;
    }
}

}  // namespace

int run_cli_arguments(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err,
                      const std::optional<std::filesystem::path>& resuming) {
    remove_temporaries_on_signal();
    fit_allocator_to_address_space();
    std::vector<const char*> argv = {"rotbench"};
    for (const auto& a : arguments) argv.push_back(a.c_str());
    const int argc = static_cast<int>(argv.size());
    CLI::App app{"rotbench: verification and convergence harness for rigid-body rotation schemes"};
    app.fallthrough();  // --plugin may follow the command
    app.require_subcommand(0, 1);
    std::vector<std::string> plugins, clients;
    app.add_option("--plugin", plugins, "load schemes from a plug-in built with rotbench_add_scheme() (repeatable)");
    app.add_option("--client", clients, "a scheme run by a program outside rotbench, from its client file (repeatable; docs/clients.md)");
    bool version = false;
    app.add_flag("--version", version, "print the version, commit, compiler and flags, and exit");
    std::map<std::string, std::pair<CLI::App*, std::unique_ptr<Verb>>> verbs;
    const std::vector<std::string> names = user_verbs();
    for (const auto& name : VerbRegistry::instance().ids()) {
        const auto& entry = VerbRegistry::instance().at(name, "command");
        auto verb = entry.make();
        CLI::App* command = app.add_subcommand(name, entry.summary);
        verb->add_options(*command);
        verbs.emplace(name, std::pair{command, std::move(verb)});
    }

    std::string command_line = "rotbench";
    for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
    try {
        // Every message and the command line a report quotes are one line: an argument with a
        // line break is refused before anything is written.
        for (const auto& a : arguments)
            if (a.find_first_of("\n\r") != std::string::npos)
                throw InputError("an argument holds a line break: '" + a + "'; rotbench takes none");  // shown as \x0A
        if (argc > 1 && argv[1][0] != '-' && !verbs.count(argv[1]))
            throw InputError(std::string("unknown command '") + argv[1] + "'; valid commands: " + join(names, ", "));
        app.parse(argc, argv.data());
        if (version) {
            out << version_text();
            return 0;
        }
        refuse_empty_values(app);
        const auto chosen = std::find_if(verbs.begin(), verbs.end(), [](const auto& v) { return v.second.first->parsed(); });
        if (chosen == verbs.end()) throw InputError("no command given; valid commands: " + join(names, ", "));
        Verb& verb = *chosen->second.second;
        if (resuming && !verb.resumable())
            throw InputError("--resume " + resuming->string() + ": the journal, partial/runs.jsonl, names '" + chosen->first +
                             "', which is not a command rotbench resumes; the folder's bookkeeping was changed by something else");
        const bool internal = internal_verb(chosen->first);
        const auto load = [&] {
            for (const auto& plugin : plugins) {
                const auto ids = load_plugin(plugin);
                if (internal) continue;
                err << "rotbench: loaded " << join(ids, ", ") << " from " << terminal_line(plugin) << "\n";
                if (const std::string w = build_warning(*plugin_of(ids.front())); !w.empty())
                    err << "rotbench: warning: " << terminal_line(w) << "\n";
            }
            for (const auto& client : clients) {
                const std::string id = load_client(client);
                if (!internal) err << "rotbench: loaded client " << id << " from " << terminal_line(client) << "\n";
            }
        };
        if (const std::string why = untrusted_cache_reason(); !why.empty() && !internal) err << "rotbench: warning: " << terminal_line(why) << "\n";
        const Invocation invocation{arguments, command_line, out, err, resuming, load};
        if (!verb.defers_plugins()) load();
        return verb.run(invocation);
    } catch (...) {
        return exit_status(app, out, err);
    }
}

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    return run_cli_arguments(std::vector<std::string>(argv + 1, argv + argc), out, err, std::nullopt);
}

}  // namespace rotbench
