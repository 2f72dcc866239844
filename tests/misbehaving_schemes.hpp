// Test-only schemes that misbehave on purpose, for the harness to contain. Templates on the
// scalar like every scheme, so that they step packs too. Registered by including this header:
// a test file that runs one says so by its include (inline variables register once).
#pragma once

#include "schemes/scheme.hpp"

#include <limits>
#include <stdexcept>

namespace rotbench::test {

template <class S = double>
struct ProducesNan {
    template <class T>
    using rebind = ProducesNan<T>;
    struct Memory {};
    static void start(const RigidBodyT<S>&, Memory&) {}
    static void predict(RigidBodyT<S>& b, Memory&, double) { b.omega.x() = S(std::numeric_limits<double>::quiet_NaN()); }
    static void correct(RigidBodyT<S>&, Memory&, double) {}
};
template <class S = double>
struct Throws {
    template <class T>
    using rebind = Throws<T>;
    struct Memory {};
    static void start(const RigidBodyT<S>&, Memory&) {}
    static void predict(RigidBodyT<S>&, Memory&, double) { throw std::runtime_error("plug-in bug"); }
    static void correct(RigidBodyT<S>&, Memory&, double) {}
};
template <class S = double>
struct Explodes {  // doubles w every step: finite for a long time, but no energy bound holds
    template <class T>
    using rebind = Explodes<T>;
    struct Memory {};
    static void start(const RigidBodyT<S>&, Memory&) {}
    static void predict(RigidBodyT<S>& b, Memory&, double) { b.omega *= 2.0; }
    static void correct(RigidBodyT<S>&, Memory&, double) {}
};
inline const RegisterScheme<ProducesNan<>> nan_scheme("test_nan", "test only: writes NaN", "tests", "", {.sound = false});
inline const RegisterScheme<Throws<>> throwing_scheme("test_throws", "test only: throws", "tests", "", {.sound = false});
inline const RegisterScheme<Explodes<>> exploding_scheme("test_explodes", "test only: w doubles each step", "tests", "", {.sound = false});

}  // namespace rotbench::test
