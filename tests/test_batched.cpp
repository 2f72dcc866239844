// The batched loops: a scheme that steps packs of bodies (schemes/simd.hpp) must give each
// body the motion it gets when stepped alone, to round-off.
#include "benchmarks/random_bodies.hpp"
#include "schemes/scheme.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace rotbench;

TEST_CASE("a body stepped in a batch moves as it does alone, to round-off") {
    if (!ROTBENCH_SIMD) WARN("built without AVX2: every body takes the double code, the same as alone");
    constexpr std::size_t n = 9;  // two packs of four and one body left over
    constexpr int steps = 200;
    constexpr double dt = 1e-2;   // |w dt| up to 0.02: the exponential map's sine branch, not its series
    for (const auto& id : {"direct", "no_gyro", "zvw", "zvw_corrected", "munjiza_rk4", "spiral", "cayley"}) {
        const auto make = SchemeRegistry::instance().at(id, "scheme").make;
        Bodies batch = random_bodies(n);
        auto scheme = make();
        scheme->start(batch);
        for (int s = 0; s < steps; ++s) scheme->predict(batch, dt), scheme->correct(batch, dt);
        const Bodies initial = random_bodies(n);
        for (std::size_t i = 0; i < n; ++i) {
            Bodies one = random_bodies(1);
            one.inertia.set(0, initial.inertia[i]);
            one.orientation.set(0, initial.orientation[i]);
            one.omega.set(0, initial.omega[i]);
            one.torque.set(0, initial.torque[i]);
            auto alone = make();
            alone->start(one);
            for (int s = 0; s < steps; ++s) alone->predict(one, dt), alone->correct(one, dt);
            // xsimd's sin and cos agree with glibc's to about an ulp; the step maps are
            // contractions or near-isometries at |w dt| = 0.02, so after 200 steps a bound of
            // 10 ulp per step, relative to |w| <= 2 and |q| = 1, holds with room.
            const double bound = steps * 10 * std::numeric_limits<double>::epsilon() * 2.0;
            INFO(id << ", body " << i);
            CHECK((batch.omega[i] - one.omega[0]).norm() < bound);
            CHECK((batch.orientation[i].coeffs() - one.orientation[0].coeffs()).norm() < bound);
        }
    }
}
