// Test plug-in whose entry points are all there but one answers NULL (NULL_ENTRY names which):
// rotbench must refuse it in one line, never call through the NULL.
#include "schemes/plugin_abi.hpp"
#include "schemes/scheme.hpp"

#include <cstring>

namespace {
rotbench::SchemeRegistry registry;  // empty: the entry points are what is tested
bool is(const char* entry) { return std::strcmp(NULL_ENTRY, entry) == 0; }
}  // namespace

extern "C" __attribute__((visibility("default"))) const char* rotbench_plugin_abi() { return is("abi") ? nullptr : ROTBENCH_PLUGIN_ABI; }
extern "C" __attribute__((visibility("default"))) const rotbench::SchemeRegistry* rotbench_plugin_schemes() {
    return is("schemes") ? nullptr : &registry;
}
extern "C" __attribute__((visibility("default"))) const char* rotbench_plugin_build() { return is("build") ? nullptr : "test build"; }
