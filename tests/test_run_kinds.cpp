// The kinds of run besides the trajectory (harness/exec/run_kinds.hpp): the reversal and
// the stability search, made by the same engine (run_one) as every other run.
#include "harness/exec/stability.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/exec/run.hpp"
#include "harness/exec/executor.hpp"
#include "harness/analysis/sweep_plan.hpp"
#include "tests/misbehaving_schemes.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace rotbench;

TEST_CASE("a reversal run returns a symmetric scheme to its start to round-off, and not a non-symmetric one") {
    // no_squish is a symmetric splitting of exact flows; fincham's explicit mid-point rule is not.
    const RunResult symmetric = run_one({"dipole_top", "no_squish", 0.01, 10.0, {}, RunKind::reversal});
    const RunResult explicit_midpoint = run_one({"dipole_top", "fincham", 0.01, 10.0, {}, RunKind::reversal});
    REQUIRE(symmetric.failure.empty());
    CHECK(symmetric.value("steps") == 1000);
    // 2000 steps, each rounding every component a few times: 2 N x 4 eps bounds the walk.
    const double bound = 2.0 * 1000 * 4.0 * std::numeric_limits<double>::epsilon();
    CHECK(symmetric.value("reversal_angle") < bound);
    CHECK(symmetric.value("reversal_omega") < bound);
    // The explicit mid-point rule leaves an O(dt^2) error per step that the way back does not undo.
    CHECK(explicit_midpoint.value("reversal_angle") > 1e-8);
}

TEST_CASE("a reversal run of a scheme that blows up or throws is a failed run, not a crash") {
    const RunResult r = run_one({"dipole_top", "test_nan", 0.01, 1.0, {}, RunKind::reversal});
    CHECK(r.value("unstable") == 1);
    CHECK(std::isnan(r.value("reversal_angle")));
    CHECK_FALSE(r.failure.empty());
}

TEST_CASE("a stability-search run gives the limit the stability analysis finds") {
    const RunResult r = run_one({"sphere_pair", "direct", 0.0, 0.0, {{"zeta", {0.3}}}, RunKind::stability});
    REQUIRE(r.failure.empty());
    const auto scene = make_scene("sphere_pair", {{"zeta", {0.3}}});
    const auto& probe = dynamic_cast<const StabilityProbe&>(*scene);
    CHECK(r.value("dt_peng") == probe.predicted_limit());
    CHECK(r.value("stability_ratio") == r.value("dt_empirical") / r.value("dt_peng"));
    // The limit is a bisection bracket's stable end, narrower than 0.5 % (empirical_limit's
    // tolerance): the scene of the run's own parameters is stable there and blows up 1 % above.
    const double limit = r.value("dt_empirical");
    REQUIRE(limit > 0);
    CHECK_FALSE(unstable_at(*scene, "direct", limit, stability_criterion(probe)));
    CHECK(unstable_at(*scene, "direct", 1.01 * limit, stability_criterion(probe)));
}
