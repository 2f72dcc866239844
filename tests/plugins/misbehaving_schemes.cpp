// Test plug-in: schemes that throw or produce NaN. rotbench must report them and go on.
#include "schemes/scheme.hpp"

#include <limits>
#include <stdexcept>

namespace {

using namespace rotbench;

struct Throws {
    struct Memory {};
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody&, Memory&, double) { throw std::runtime_error("bug in the plug-in"); }
    static void correct(RigidBody&, Memory&, double) {}
};
struct ProducesNan {
    struct Memory {};
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody& b, Memory&, double) { b.omega.x() = std::numeric_limits<double>::quiet_NaN(); }
    static void correct(RigidBody&, Memory&, double) {}
};

const RegisterScheme<Throws> throws("plugin_throws", "test plug-in: throws", "tests/plugins", "", {.sound = false});
const RegisterScheme<ProducesNan> nan("plugin_nan", "test plug-in: writes NaN", "tests/plugins", "", {.sound = false});

}  // namespace
