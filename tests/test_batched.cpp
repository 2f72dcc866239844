// The batched loops: a scheme that steps packs of bodies (schemes/simd.hpp) must give each
// body the motion it gets when stepped alone: the same bits, unless a step turns it by more
// than a radian.
#include "benchmarks/random_bodies.hpp"
#include "schemes/scheme.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

using namespace rotbench;

namespace {
// Steps n random bodies for `steps` steps of dt, all together and then each alone, and
// returns the largest difference, over the bodies, in w and in q.
std::pair<double, double> batch_minus_alone(const std::string& id, double dt, int steps) {
    constexpr std::size_t n = 9;  // two packs of four and one body left over
    const auto make = SchemeRegistry::instance().at(id, "scheme").make;
    Bodies batch = random_bodies(n);
    auto scheme = make();
    scheme->start(batch);
    for (int s = 0; s < steps; ++s) scheme->predict(batch, dt), scheme->correct(batch, dt);
    const Bodies initial = random_bodies(n);
    double omega_diff = 0, q_diff = 0;
    for (std::size_t i = 0; i < n; ++i) {
        Bodies one = random_bodies(1);
        one.inertia.set(0, initial.inertia[i]);
        one.orientation.set(0, initial.orientation[i]);
        one.omega.set(0, initial.omega[i]);
        one.torque.set(0, initial.torque[i]);
        auto alone = make();
        alone->start(one);
        for (int s = 0; s < steps; ++s) alone->predict(one, dt), alone->correct(one, dt);
        omega_diff = std::max(omega_diff, (batch.omega[i] - one.omega[0]).norm());
        q_diff = std::max(q_diff, (batch.orientation[i].coeffs() - one.orientation[0].coeffs()).norm());
    }
    return {omega_diff, q_diff};
}
const char* const batched_schemes[] = {"direct", "no_gyro", "zvw", "zvw_corrected", "munjiza_rk4", "spiral", "cayley"};
}  // namespace

TEST_CASE("a body stepped in a batch moves as it does alone") {
    if (!ROTBENCH_SIMD) WARN("built without AVX2: every body takes the double code, the same as alone");
    SECTION("bit for bit while each step turns it by less than a radian (the exponential map's series)") {
        for (const char* id : batched_schemes) {
            INFO(id);
            // |w| < 2 at the start and constant torques below 2 rad/s^2 (random_bodies): |w dt|
            // stays below 0.1 rad over the 2 s.
            const auto [omega_diff, q_diff] = batch_minus_alone(id, 1e-2, 200);
            CHECK(omega_diff == 0.0);
            CHECK(q_diff == 0.0);
        }
    }
    SECTION("to round-off when steps turn it further (xsimd's sin and cos, not glibc's)") {
        for (const char* id : batched_schemes) {
            INFO(id);
            // |w dt| up to 1.2 rad at the start: sin and cos, which agree with glibc's to
            // about an ulp. 3 steps: 10 ulp per step, relative to |w| <= 2 and |q| = 1, holds
            // with room (longer runs at such steps diverge: they are past these schemes'
            // stability limits).
            const auto [omega_diff, q_diff] = batch_minus_alone(id, 0.7, 3);
            const double bound = 3 * 10 * std::numeric_limits<double>::epsilon() * 2.0;
            CHECK(omega_diff < bound);
            CHECK(q_diff < bound);
        }
    }
}
