#include "harness/core/fnv1a.hpp"
#include "harness/store/plugin.hpp"

#include "schemes/plugin_abi.hpp"

#include "harness/store/output_files.hpp"

#include "harness/store/parse.hpp"

#include <algorithm>
#include <fstream>
#include <string_view>
#include <cctype>
#include <cstdint>
#include <dlfcn.h>
#include <fmt/format.h>
#include <filesystem>

namespace rotbench {

namespace {

std::vector<LoadedPlugin>& plugins() {
    static std::vector<LoadedPlugin> list;
    return list;
}


}  // namespace

const std::vector<LoadedPlugin>& loaded_plugins() { return plugins(); }

const LoadedPlugin* plugin_of(const std::string& scheme) {
    for (const auto& p : plugins())
        if (std::find(p.schemes.begin(), p.schemes.end(), scheme) != p.schemes.end()) return &p;
    return nullptr;
}

// This file is compiled with the built-in schemes' flags: the macro says how they were built.
bool LoadedPlugin::built_like_builtins() const { return build == ROTBENCH_PLUGIN_BUILD; }

std::string build_warning(const LoadedPlugin& p) {
    if (p.built_like_builtins()) return "";
    return fmt::format("plug-in {} was built {} (the built-in schemes: {}): its cost does not compare with theirs; build it "
                       "with rotbench_add_scheme() and its default flags",
                       p.path, p.build, ROTBENCH_PLUGIN_BUILD);
}

std::vector<std::string> load_plugin(const std::string& path) {
    const std::string where = "--plugin " + path;
    if (!std::filesystem::exists(path)) throw InputError(where + ": no such file");
    if (!std::filesystem::is_regular_file(path)) throw InputError(where + ": not a regular file");
    // Its first bytes before all of them: a file of gigabytes that is no library is refused at once.
    char magic[4] = {};
    std::ifstream(path, std::ios::binary).read(magic, sizeof magic);
    if (std::string_view(magic, 4) != "\x7f" "ELF") throw InputError(where + ": not a shared library (no ELF header)");
    Fnv1a bytes;
    if (!feed_file(path, bytes)) throw InputError(where + ": cannot read the file");
    // The same file again (a long-lived process, or the option given twice): already loaded.
    // Symlinks resolved: the same library reached another way is loaded once.
    const std::string absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(path)).string(), hash = bytes.hex();
    for (const auto& p : plugins())
        if (p.path == absolute && p.hash == hash) return p.schemes;
    // A path without '/' would make dlopen search the library path instead of this file.
    const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw InputError(where + ": cannot load: " + dlerror());
    const auto abi = reinterpret_cast<rotbench_plugin_abi_fn>(dlsym(handle, "rotbench_plugin_abi"));
    const auto schemes = reinterpret_cast<rotbench_plugin_schemes_fn>(dlsym(handle, "rotbench_plugin_schemes"));
    const auto build = reinterpret_cast<rotbench_plugin_build_fn>(dlsym(handle, "rotbench_plugin_build"));
    if (!abi || !schemes) {
        dlclose(handle);
        throw InputError(where + ": not a rotbench plug-in (no rotbench_plugin_abi / rotbench_plugin_schemes); build it "
                                 "with rotbench_add_scheme() from find_package(rotbench)");
    }
    // Each entry point's answer is checked before use: a NULL from any is a broken plug-in, not a crash.
    const char* abi_text = abi();
    if (!abi_text) {
        dlclose(handle);
        throw InputError(where + ": its rotbench_plugin_abi returned no text; rebuild it with rotbench_add_scheme()");
    }
    if (std::string(abi_text) != ROTBENCH_PLUGIN_ABI) {
        const std::string theirs = abi_text;
        dlclose(handle);
        throw InputError(where + ": ABI mismatch: the plug-in was built for '" + theirs + "', this rotbench is '" +
                         ROTBENCH_PLUGIN_ABI + "'; rebuild the plug-in against this rotbench");
    }
    if (!build) {  // the same ABI string, yet an entry point missing: not built by rotbench_add_scheme()
        dlclose(handle);
        throw InputError(where + ": no rotbench_plugin_build; build it with rotbench_add_scheme() from find_package(rotbench)");
    }
    const SchemeRegistry* registry = schemes();
    const char* build_text = build();
    if (!registry || !build_text) {
        dlclose(handle);
        throw InputError(where + ": its " + (registry ? "rotbench_plugin_build" : "rotbench_plugin_schemes") +
                         " returned NULL; rebuild it with rotbench_add_scheme()");
    }
    const SchemeRegistry& theirs = *registry;
    const auto ids = theirs.ids();
    if (ids.empty()) throw InputError(where + ": the plug-in registers no scheme");
    auto& ours = SchemeRegistry::instance();
    for (const auto& id : ids) {
        if (!is_id(id)) throw InputError(where + ": scheme id '" + id + "' is not 1 to " + std::to_string(max_id_length) + " letters, digits and underscores");
        if (ours.contains(id))
            throw InputError(where + ": scheme '" + id + "' is already registered; give the plug-in's scheme another id");
    }
    for (const auto& id : ids) ours.add(theirs.at(id, "scheme"));
    plugins().push_back({absolute, hash, ids, build_text});
    return ids;  // the handle is kept open: the factories live in the library
}

}  // namespace rotbench
