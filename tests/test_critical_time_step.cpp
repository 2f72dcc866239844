#include "harness/exec/run.hpp"
#include "harness/scenes/contact_pair.hpp"
#include "references/critical_time_step.hpp"

#include <catch2/catch.hpp>

using namespace rotbench;

TEST_CASE("Peng et al.'s closed forms reproduce the paper's own special cases") {
    const double m = 2.0, k = 3e4, r = 0.1;
    // Eq. 49: two identical spheres, A_max = 7/m and dt = (2/sqrt 7) sqrt(m/k).
    const double a = peng::a_max(r, 0.4 * m * r * r, m, r, 0.4 * m * r * r, m);
    CHECK(a == Approx(7.0 / m).epsilon(1e-14));
    CHECK(peng::undamped(k, a) == Approx(2.0 / std::sqrt(7.0) * std::sqrt(m / k)).epsilon(1e-14));
    // Eq. 46 with c = 0 is eq. 47; eq. 60 in the seed's beta = c / sqrt(mk) for spheres:
    // dt sqrt(k/m) = (sqrt(28 + 49 beta^2) + 7 beta) / 7 (rewritten from eq. 46 with A = 7/m).
    CHECK(peng::damped(k, 0.0, a) == Approx(peng::undamped(k, a)).epsilon(1e-14));
    const double beta = 0.3, c = beta * std::sqrt(m * k);
    CHECK(peng::damped(k, c, a) * std::sqrt(k / m) == Approx((std::sqrt(28.0 + 49.0 * beta * beta) + 7.0 * beta) / 7.0).epsilon(1e-13));
    // Eq. 37 and eq. 58's asymptote beta = 2/sqrt 7 are the same critical damping.
    CHECK(peng::critical_damping(k, a) / std::sqrt(m * k) == Approx(2.0 / std::sqrt(7.0)).epsilon(1e-14));
}

TEST_CASE("B_max (eq. 54) and the rotation-dominant step (eq. 57)") {
    CHECK(peng::b_max(Vec3(1, 1, 1)) == 0.0);
    CHECK(peng::b_max(Vec3(1, 2, 3)) == Approx(1.0));  // |2 - 3| / 1
    CHECK(peng::rotation_dominant(10.0, 0.5) == Approx(0.2));
}

TEST_CASE("sphere_pair: A_max = 7/m, and the undamped contact conserves energy to second order under direct") {
    const auto scene = make_scene("sphere_pair");
    const auto& pair = dynamic_cast<const ContactPairScene&>(*scene);
    const double m = scene->initial_state().mass[0];
    CHECK(pair.a_max() == Approx(7.0 / m).epsilon(1e-14));  // seed eq. 49's case
    const double e1 = run_one({"sphere_pair", "direct", 2e-5, 0.0}, {.measure_time = false}).value("energy_drift_max");
    const double e2 = run_one({"sphere_pair", "direct", 1e-5, 0.0}, {.measure_time = false}).value("energy_drift_max");
    CHECK(std::log2(e1 / e2) == Approx(2.0).margin(0.05));
}

TEST_CASE("linear contact: munjiza_rk4 and zvw gain energy at every step size, direct and zvw_corrected do not") {
    // A finding pinned so that it cannot change silently. Both schemes use only the
    // start-of-step torque (eq. 44; zvw's velocity update) while the contact spring couples
    // rotation and translation: each step multiplies the energy by 1 + O(dt^2), so a run
    // blows up after O(dt^-2) steps however small dt is, far below Peng's limit (1.7e-4 s).
    for (const char* scheme : {"munjiza_rk4", "zvw"}) {
        INFO(scheme);
        const RunResult coarse = run_one({"sphere_pair", scheme, 2e-5, 0.2}, {.measure_time = false});
        const RunResult fine = run_one({"sphere_pair", scheme, 1e-5, 0.2}, {.measure_time = false});
        REQUIRE(coarse.value("unstable") == 1);
        REQUIRE(fine.value("unstable") == 1);
        // Blow-up step ~ dt^-2: halving dt takes about four times the steps (3 to 5).
        const double ratio = fine.value("fail_step") / coarse.value("fail_step");
        CHECK(ratio > 3.0);
        CHECK(ratio < 5.0);
    }
    for (const char* scheme : {"direct", "zvw_corrected"}) {
        INFO(scheme);
        CHECK(run_one({"sphere_pair", scheme, 1e-4, 0.2}, {.measure_time = false}).value("unstable") == 0);
    }
}
