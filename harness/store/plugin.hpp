// `--plugin path.so`: schemes built out of tree (cmake/rotbench_plugin.cmake, README "Add
// your scheme"). Loading checks the ABI string (schemes/plugin_abi.hpp) before anything of
// the plug-in is called, then adds its schemes to the registry; a missing file, a library
// that is not a rotbench plug-in, an ABI mismatch, a plug-in without schemes or one whose
// ids clash with registered ones are InputErrors. The library stays loaded for the life of
// the process. (Its static initialisers run inside dlopen, before the ABI check; they only
// touch the plug-in's own registry.)
#pragma once

#include <string>
#include <vector>

namespace rotbench {

// Returns the ids of the schemes it added. Every id must be 1 to 64 letters, digits and underscores,
// and new to the registry.
std::vector<std::string> load_plugin(const std::string& path);

struct LoadedPlugin {
    std::string path;  // absolute
    std::string hash;  // FNV-1a of the file's bytes, hex: a plug-in rebuilt since is another one
    std::vector<std::string> schemes;
    std::string build;  // e.g. "optimised, assertions off" (ROTBENCH_PLUGIN_BUILD, schemes/plugin_abi.hpp)
    // Built as the built-in schemes of this rotbench are: its cost compares with theirs.
    bool built_like_builtins() const;
};
const std::vector<LoadedPlugin>& loaded_plugins();
// The plug-in a scheme came from, or nullptr for a built-in one.
const LoadedPlugin* plugin_of(const std::string& scheme);
// One line for a plug-in built otherwise than the built-in schemes, or "" for one built like them.
std::string build_warning(const LoadedPlugin& plugin);

}  // namespace rotbench
