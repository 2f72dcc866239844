// The plug-in ABI: what a scheme compiled outside rotbench must share with the rotbench
// that loads it. Schemes cross the boundary as C++ objects (std::function, std::string,
// Eigen types, the RotationScheme vtable), so the check covers the interface version, the
// compiler and its standard-library ABI, and Eigen's version and alignment. A plug-in
// built against another rotbench, compiler or Eigen is refused with both strings shown.
#pragma once

#include "schemes/scheme.hpp"  // brings in <string> and Eigen, whose macros are read below

// Raise when anything in schemes/scheme.hpp, schemes/bodies.hpp or schemes/registry.hpp
// changes layout or meaning. 2: RotationScheme::lanes(). 3: SchemeClaims::time_reversible.
// 4: SchemeClaims::family. 5: rotbench_plugin_build, SchemeClaims::declared_at.
#define ROTBENCH_PLUGIN_ABI_VERSION 5

#define ROTBENCH_ABI_STR2(x) #x
#define ROTBENCH_ABI_STR(x) ROTBENCH_ABI_STR2(x)
#define ROTBENCH_PLUGIN_ABI                                                                                        \
    "rotbench-plugin-abi " ROTBENCH_ABI_STR(ROTBENCH_PLUGIN_ABI_VERSION) "; compiler " __VERSION__ "; cxx11-abi " \
    ROTBENCH_ABI_STR(_GLIBCXX_USE_CXX11_ABI) "; eigen " ROTBENCH_ABI_STR(EIGEN_WORLD_VERSION) "."              \
    ROTBENCH_ABI_STR(EIGEN_MAJOR_VERSION) "." ROTBENCH_ABI_STR(EIGEN_MINOR_VERSION) " align "                    \
    ROTBENCH_ABI_STR(EIGEN_MAX_STATIC_ALIGN_BYTES)

// How the translation unit that expands it was compiled: optimised or not, assertions on or off.
// A plug-in's entry file is compiled with its schemes' flags, so this is how the plug-in was built.
#ifdef __OPTIMIZE__
#define ROTBENCH_BUILD_OPTIMISATION "optimised"
#else
#define ROTBENCH_BUILD_OPTIMISATION "unoptimised"
#endif
#ifdef NDEBUG
#define ROTBENCH_BUILD_ASSERTIONS "assertions off"
#else
#define ROTBENCH_BUILD_ASSERTIONS "assertions on"
#endif
#define ROTBENCH_PLUGIN_BUILD ROTBENCH_BUILD_OPTIMISATION ", " ROTBENCH_BUILD_ASSERTIONS

// The three C entry points a plug-in exports (cmake/rotbench_plugin_entry.cpp defines them).
extern "C" {
using rotbench_plugin_abi_fn = const char* (*)();
using rotbench_plugin_build_fn = const char* (*)();
using rotbench_plugin_schemes_fn = const rotbench::SchemeRegistry* (*)();
}
