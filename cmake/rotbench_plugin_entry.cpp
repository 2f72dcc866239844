// Compiled into every plug-in by rotbench_add_scheme() (cmake/rotbench_plugin.cmake). The
// plug-in's schemes register themselves, exactly as in tree, into the plug-in's own copy of
// the registry (it is built with hidden visibility and loaded RTLD_LOCAL); rotbench checks
// the ABI string first and then copies the entries into its own registry.
#include "schemes/plugin_abi.hpp"

extern "C" __attribute__((visibility("default"))) const char* rotbench_plugin_abi() { return ROTBENCH_PLUGIN_ABI; }

extern "C" __attribute__((visibility("default"))) const char* rotbench_plugin_build() { return ROTBENCH_PLUGIN_BUILD; }

extern "C" __attribute__((visibility("default"))) const rotbench::SchemeRegistry* rotbench_plugin_schemes() {
    return &rotbench::SchemeRegistry::instance();
}
