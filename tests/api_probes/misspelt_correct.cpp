// Must not build: a kernel whose correct phase is misspelt.
#include "schemes/scheme.hpp"

namespace {
using namespace rotbench;
struct Kernel {
    struct Memory {};
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody&, Memory&, double) {}
    static void corect(RigidBody&, Memory&, double) {}
};
const RegisterScheme<Kernel> registration("probe", "", "");
}  // namespace
