// Every registered scheme states what it claims (schemes/scheme.hpp, SchemeClaims): its
// order with and without torque, exactness, momentum conservation. These tests hold each
// scheme to its own claims, so a new scheme is tested by registering it.
#include "harness/analysis/claims.hpp"
#include "harness/exec/run.hpp"
#include "schemes/detail/free_rigid_body.hpp"
#include "schemes/quaternion.hpp"
#include "harness/analysis/expected_orders.hpp"
#include "harness/analysis/orders.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace rotbench;

namespace {

std::vector<RunResult> halving_runs(const std::string& scene, const std::string& scheme, double dt0, int count) {
    std::vector<RunResult> runs;
    for (int k = 0; k < count; ++k) {
        runs.push_back(run_one({scene, scheme, dt0 * std::pow(0.5, k), 0.0}, {.measure_time = false}));
        INFO(scheme << " on " << scene << " at dt = " << runs.back().spec.dt);
        REQUIRE(runs.back().failure.empty());  // a failed run must not hide in a fit over the others
    }
    return runs;
}

OrderFit fit_of(const std::vector<RunResult>& runs, const std::string& metric) {
    for (const auto& row : observed_orders(runs))
        if (row.metric == metric) return row.fit;
    FAIL("no order row for " << metric);
    return {};
}

std::vector<std::string> schemes_where(bool (*predicate)(const SchemeClaims&)) {
    std::vector<std::string> out;
    for (const auto& id : SchemeRegistry::instance().ids())
        if (predicate(SchemeRegistry::instance().at(id, "scheme").extra)) out.push_back(id);
    return out;
}

}  // namespace

TEST_CASE("each scheme shows the order it claims, on a free asymmetric top and under an orientation-dependent torque", "[study]") {
    for (const auto& expected : expected_orders()) {
        // Halving ladders of 5 steps from 1e-2, inside each scene's asymptotic range.
        const std::string scene = expected.with_torque ? "dipole_top" : "asymmetric_free";
        const OrderFit fit = fit_of(halving_runs(scene, expected.scheme, 1e-2, 5), "omega_err_max");
        INFO(scene << " / " << expected.scheme << ": observed " << fit.order << " [" << fit.order_lo << ", "
                   << fit.order_hi << "], claimed " << expected.order << " (" << expected.reason << ")");
        REQUIRE(fit.sufficient);
        // 0.1: what is left of the pre-asymptotic terms on these ladders.
        CHECK(fit.order == Approx(expected.order).margin(0.1));
    }
}

TEST_CASE("on the symmetric free cylinder each scheme converges at least at its claimed order", "[study]") {
    // A symmetric top turns at two constant rates, which some schemes follow exactly to a
    // higher order (rozmanov_kusalik: fourth; its errors reach round-off by dt = 2.5e-4).
    for (const auto& expected : expected_orders()) {
        if (expected.with_torque) continue;
        const auto runs = halving_runs("cylinder_free", expected.scheme, 2e-4, 5);
        const OrderFit fit = fit_of(runs, "omega_err_max");
        INFO(expected.scheme << ": observed " << fit.order << ", claimed " << expected.order);
        if (fit.sufficient) {
            CHECK(fit.order >= expected.order - 0.1);
        } else {
            // No fit: every error must then be at the round-off floor of |w| = 100 rad/s
            // over 2500-40000 steps (1e-9 = 1e-11 relative).
            for (const auto& r : runs) CHECK(r.value("omega_err_max") < 1e-9);
        }
    }
}

// How much the closed-form motion of a scene amplifies a perturbation of its initial angular
// velocity: max over t of |w(t) - w'(t)| / |dw0|, by finite differences with relative
// perturbations of 1e-8 along each body axis (small enough to stay linear, large enough to
// stand clear of round-off), sampled at every step of dt.
double perturbation_growth(const std::string& scene_id, double dt) {
    const auto scene = make_scene(scene_id);
    const Bodies initial = scene->initial_state();
    const Vec3 inertia = initial.inertia[0];
    const Quat q0 = initial.orientation[0];
    const Vec3 omega0 = to_body(q0, initial.omega[0]);
    const FreeRigidBody exact(inertia, q0, omega0);
    double growth = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 perturbed = omega0;
        const double h = 1e-8 * omega0.norm();
        perturbed[axis] += h;
        const FreeRigidBody nearby(inertia, q0, perturbed);
        for (double t = dt; t <= scene->t_end() + 0.5 * dt; t += dt)
            growth = std::max(growth, (exact.omega_world(t) - nearby.omega_world(t)).norm() / h);
    }
    return growth;
}

TEST_CASE("a scheme that claims to be exact without torque follows the closed form to round-off") {
    const auto exact = schemes_where([](const SchemeClaims& c) { return c.exact_without_torque; });
    REQUIRE_FALSE(exact.empty());
    for (const auto& scheme : exact)
        for (const char* scene : {"asymmetric_free", "tumbling_brick"}) {
            const RunResult r = run_one({scene, scheme, 0.1, 0.0}, {.measure_time = false});
            const Judgement j = judge_exact({&r});
            INFO(scheme << " on " << scene << ": " << j.message);
            CHECK(j.passed);
        }
    const RunResult direct = run_one({"asymmetric_free", "direct", 0.1, 0.0}, {.measure_time = false});
    CHECK_FALSE(judge_exact({&direct}).passed);  // and the judge separates
}

TEST_CASE("near the separatrix an exact scheme's error stays within round-off amplified by the motion itself") {
    for (const auto& scheme : schemes_where([](const SchemeClaims& c) { return c.exact_without_torque; })) {
        const double dt = 0.1;
        const RunResult r = run_one({"dzhanibekov", scheme, dt, 0.0}, {.measure_time = false});
        // Each step restarts the closed form from a state that carries a few ulp of round-off
        // (allow 10 ulp of |w0| per step), and the motion amplifies each such error by at most
        // perturbation_growth until t_end. Near the separatrix that growth is large: the
        // claims module's round-off bound, which has no such factor, is not the judge here.
        const double growth = perturbation_growth("dzhanibekov", dt);
        const double bound = r.value("steps") * 10.0 * std::numeric_limits<double>::epsilon() *
                             make_scene("dzhanibekov")->initial_state().omega[0].norm() * growth;
        INFO(scheme << ": growth " << growth << ", bound " << bound);
        CHECK(r.value("omega_err_max") < bound);
        CHECK(r.value("orientation_err_max") < bound);
    }
}

TEST_CASE("a scheme that claims to conserve angular momentum keeps it to round-off without torque") {
    const auto conserving = schemes_where([](const SchemeClaims& c) { return c.conserves_momentum; });
    REQUIRE(conserving.size() >= 8);
    for (const auto& scheme : conserving) {
        const RunResult r = run_one({"asymmetric_free", scheme, 0.0125, 0.0}, {.measure_time = false});
        const Judgement j = judge_momentum({&r});
        INFO(scheme << ": " << j.message);
        CHECK(j.passed);
    }
    // And the judge separates: a scheme that does not claim it drifts far above the bound.
    const RunResult direct = run_one({"asymmetric_free", "direct", 0.0125, 0.0}, {.measure_time = false});
    CHECK_FALSE(judge_momentum({&direct}).passed);
}

TEST_CASE("spiral: the body-frame angular velocity is third order as published, the orientation second") {
    const auto runs = halving_runs("asymmetric_free", "spiral", 1e-2, 5);
    CHECK(fit_of(runs, "omega_rms_x").order == Approx(3.0).margin(0.1));
    CHECK(fit_of(runs, "orientation_err_max").order == Approx(2.0).margin(0.1));
}

TEST_CASE("no_gyro, the negative control, does not converge on a non-spherical body") {
    REQUIRE_FALSE(SchemeRegistry::instance().at("no_gyro", "scheme").extra.sound);
    const double coarse = run_one({"asymmetric_free", "no_gyro", 1e-2, 0.0}, {.measure_time = false}).value("omega_err_max");
    const double fine = run_one({"asymmetric_free", "no_gyro", 1.25e-3, 0.0}, {.measure_time = false}).value("omega_err_max");
    // |w| ~ 0.8 rad/s: an O(1) error that an 8x smaller step leaves within 1 %.
    CHECK(coarse > 0.5);
    CHECK(fine == Approx(coarse).epsilon(0.01));
}

TEST_CASE("a scheme that claims bounded energy shows no secular drift over an 8 times longer run") {
    const auto bounded = schemes_where([](const SchemeClaims& c) { return c.bounded_energy; });
    REQUIRE(bounded.size() >= 5);
    const auto judged = [](const std::string& scheme) {
        return judge_bounded_energy(run_one({"dipole_top", scheme, 0.02, 10.0, {}, RunKind::horizon}));
    };
    for (const auto& scheme : bounded) {
        const Judgement j = judged(scheme);
        INFO(scheme << ": " << j.message);
        CHECK(j.passed);
    }
    const Judgement direct = judged("direct");
    INFO(direct.message);
    CHECK_FALSE(direct.passed);  // and the judge separates: the first-order direct drifts
}

TEST_CASE("a scheme that claims to be time-reversible returns to its start to round-off when stepped back") {
    const auto reversible = schemes_where([](const SchemeClaims& c) { return c.time_reversible; });
    REQUIRE(reversible.size() >= 5);
    for (const auto& scheme : reversible)
        for (const char* scene : {"dipole_top", "tumbling_brick"}) {
            const Judgement j = judge_reversal(run_one({scene, scheme, 0.01, 0.0, {}, RunKind::reversal}));
            INFO(scheme << " on " << scene << ": " << j.message);
            CHECK(j.passed);
        }
    // And the judge separates: a scheme that does not claim it (fincham's explicit mid-point rule) does not return.
    CHECK_FALSE(judge_reversal(run_one({"dipole_top", "fincham", 0.01, 0.0, {}, RunKind::reversal})).passed);
}
