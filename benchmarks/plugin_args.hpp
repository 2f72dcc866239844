// `--plugin PATH` (or `--plugin=PATH`, repeatable) for the speed tools, so that a candidate
// scheme built as a plug-in is benchmarked and counted like a built-in one. The options are
// taken out of argv, and the plug-ins loaded, before anything else reads the arguments or
// the registry. A bad plug-in is one line on stderr and exit 2, as for `rotbench run`.
#pragma once

#include "harness/store/plugin.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace rotbench {

inline void load_plugin_args(int& argc, char** argv, const char* tool) {
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        std::string path;
        if (arg == "--plugin" && i + 1 < argc) path = argv[++i];
        else if (arg.rfind("--plugin=", 0) == 0) path = arg.substr(9);
        else {
            argv[kept++] = argv[i];
            continue;
        }
        try {
            load_plugin(path);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s\n", tool, e.what());
            std::exit(2);
        }
    }
    argc = kept;
    argv[argc] = nullptr;
}

}  // namespace rotbench
