// Must not build: a kernel's own `family`, no longer read, would be silently ignored.
#include "schemes/scheme.hpp"

namespace {
using namespace rotbench;
struct Kernel {
    static constexpr const char* family = "seed";
    struct Memory {};
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody&, Memory&, double) {}
    static void correct(RigidBody&, Memory&, double) {}
};
const RegisterScheme<Kernel> registration("probe", "", "");
}  // namespace
