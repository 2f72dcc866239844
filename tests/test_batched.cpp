// The batched loops: a scheme that steps packs of bodies (schemes/simd.hpp) must give each
// body the motion it gets when stepped alone: the same bits, unless a step turns it by more
// than a radian.
#include "benchmarks/random_bodies.hpp"
#include "schemes/scheme.hpp"
#include "tests/skip.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

using namespace rotbench;

namespace {

// Steps `bodies` for `steps` steps of dt; false when the scheme throws (a step too large for it).
bool step(const std::string& id, Bodies& bodies, double dt, int steps) {
    auto scheme = SchemeRegistry::instance().at(id, "scheme").make();
    try {
        scheme->start(bodies);
        for (int s = 0; s < steps; ++s) scheme->predict(bodies, dt), scheme->correct(bodies, dt);
    } catch (const std::exception&) {
        return false;
    }
    return true;
}

// Steps n random bodies for `steps` steps of dt, all together and then each alone, and
// returns the largest difference, over the bodies, in w and in q. A batch must throw exactly
// when one of its bodies throws alone; then there is nothing to compare (0, 0).
std::pair<double, double> batch_minus_alone(const std::string& id, double dt, int steps) {
    constexpr std::size_t n = 9;  // two packs of four and one body left over
    Bodies batch = random_bodies(n);
    const bool batch_ok = step(id, batch, dt, steps);
    const Bodies initial = random_bodies(n);
    double omega_diff = 0, q_diff = 0;
    bool all_ok = true;
    for (std::size_t i = 0; i < n; ++i) {
        Bodies one = body_alone(initial, i);
        if (!step(id, one, dt, steps)) {
            all_ok = false;
            continue;
        }
        omega_diff = std::max(omega_diff, (batch.omega[i] - one.omega[0]).norm());
        q_diff = std::max(q_diff, (batch.orientation[i].coeffs() - one.orientation[0].coeffs()).norm());
    }
    CHECK(batch_ok == all_ok);
    if (!all_ok) return {0.0, 0.0};
    return {omega_diff, q_diff};
}

}  // namespace

TEST_CASE("every registered scheme steps packs of bodies") {
    if (!ROTBENCH_SIMD) ROTBENCH_SKIP("built without AVX2: there are no packs, every body takes the double code");
    for (const auto& id : SchemeRegistry::instance().ids()) {
        INFO(id);
        CHECK(SchemeRegistry::instance().at(id, "scheme").make()->lanes() == pack_size);
    }
}

TEST_CASE("a body stepped in a batch moves as it does alone") {
    if (!ROTBENCH_SIMD) WARN("built without AVX2: every body takes the double code, the same as alone");
    const auto ids = SchemeRegistry::instance().ids();
    SECTION("bit for bit while each step turns it by less than a radian (the exponential map's series)") {
        for (const auto& id : ids) {
            INFO(id);
            // |w| < 2 at the start and constant torques below 2 rad/s^2 (random_bodies): |w dt|
            // stays below 0.1 rad over the 2 s.
            const auto [omega_diff, q_diff] = batch_minus_alone(id, 1e-2, 200);
            CHECK(omega_diff == 0.0);
            CHECK(q_diff == 0.0);
        }
    }
    SECTION("to round-off when steps turn it further (xsimd's sin and cos, not glibc's)") {
        for (const auto& id : ids) {
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
