// Test plug-in built for another ABI: it exports the entry points by hand with an old
// version string. rotbench must refuse it before calling anything else in it.
#include "schemes/plugin_abi.hpp"

extern "C" __attribute__((visibility("default"))) const char* rotbench_plugin_abi() {
    return "rotbench-plugin-abi 0; compiler 0.0; cxx11-abi 1; eigen 3.3.0 align 16";
}
extern "C" __attribute__((visibility("default"))) const rotbench::SchemeRegistry* rotbench_plugin_schemes() {
    return nullptr;
}
