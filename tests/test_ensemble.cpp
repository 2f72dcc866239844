// Ensembles (harness/analysis/ensemble.hpp): K runs per scheme and dt from K seeds, collapsed
// to a mean, a 95 % interval and a paired difference from the reference scheme.
#include "harness/analysis/ensemble.hpp"
#include "harness/exec/executor.hpp"
#include "harness/analysis/sweep_plan.hpp"
#include "harness/analysis/ensemble_csv.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace rotbench;

namespace {

RunResult member(const std::string& scheme, double seed, double value, const std::string& failure = "") {
    RunResult r;
    r.spec = {"silo_discharge", scheme, 2e-5, 4.5, {{"clusters", {10}}, {"seed", {seed}}}};
    r.metrics = {{"discharge_time", value}, {"steps", 100}};
    r.failure = failure;
    return r;
}

const RunResult& of(const std::vector<RunResult>& runs, const std::string& scheme) {
    for (const RunResult& r : runs)
        if (r.spec.scheme == scheme) return r;
    FAIL("no run of " << scheme);
    return runs.front();
}

}  // namespace

TEST_CASE("ensembles: members collapse to a mean, a Student interval and a paired difference") {
    const std::vector<RunResult> runs = {member("direct", 1, 1.0), member("direct", 2, 2.0), member("direct", 3, 3.0),
                                         member(ensemble_reference_scheme, 1, 1.0), member(ensemble_reference_scheme, 2, 1.0),
                                         member(ensemble_reference_scheme, 3, 1.0)};
    const std::vector<RunResult> collapsed = collapse_ensembles(runs);
    REQUIRE(collapsed.size() == 2);
    const RunResult& direct = of(collapsed, "direct");
    // {1, 2, 3}: mean 2, s = 1, t(0.975, 2) = 4.302652729911275 (tables), half-width t s / sqrt(3);
    // GSL's quantile agrees with the tables to about 1e-10.
    const double t = 4.302652729911275;
    CHECK(direct.value("discharge_time") == Approx(2.0).epsilon(1e-15));
    CHECK(direct.value("discharge_time_ci95") == Approx(t / std::sqrt(3.0)).epsilon(1e-9));
    // Paired differences {0, 1, 2} from a reference mean of 1: 100 % +- the same half-width in %.
    CHECK(direct.value("discharge_time_diff") == Approx(100.0).epsilon(1e-12));
    CHECK(direct.value("discharge_time_diff_ci95") == Approx(100.0 * t / std::sqrt(3.0)).epsilon(1e-9));
    CHECK(direct.value("ensemble_size") == 3);
    CHECK(direct.value("ensemble_failed") == 0);
    CHECK(direct.value("steps") == 100);
    CHECK_FALSE(direct.has("steps_ci95"));  // counts have no interval
    // The collapsed run keeps the scene's other keys, not the seed.
    CHECK(direct.spec.params == ParamOverrides{{"clusters", {10}}});
    const RunResult& reference = of(collapsed, ensemble_reference_scheme);
    CHECK(reference.value("discharge_time_ci95") == 0.0);
    CHECK_FALSE(reference.has("discharge_time_diff"));
}

TEST_CASE("ensembles: a failed member is counted and left out, and a lone run passes through") {
    std::vector<RunResult> runs = {member("direct", 1, 1.0), member("direct", 2, 5.0, "blew up at step 3"), member("direct", 3, 3.0)};
    RunResult lone = member("zvw", 1, 7.0);
    runs.push_back(lone);
    const std::vector<RunResult> collapsed = collapse_ensembles(runs);
    REQUIRE(collapsed.size() == 2);
    CHECK(of(collapsed, "direct").value("discharge_time") == 2.0);
    CHECK(of(collapsed, "direct").value("ensemble_failed") == 1);
    CHECK(of(collapsed, "zvw").metrics == lone.metrics);
    CHECK(of(collapsed, "zvw").spec.params == lone.spec.params);

    const std::string csv = ensemble_csv(runs);
    CHECK(csv.rfind("scene,scheme,dt,seed,metric,value\n", 0) == 0);
    CHECK(csv.find("silo_discharge,direct,2e-05,2,discharge_time,5\n") != std::string::npos);
    CHECK(csv.find(",zvw,") == std::string::npos);  // not a member of an ensemble
}

TEST_CASE("ensembles: --ensemble K runs each seeded scene K times, seeds seed ... seed + K - 1, and the others once") {
    SweepSpec spec;
    spec.scenes = {"silo_discharge", "cylinder_free"};
    spec.schemes = {"direct"};
    spec.dts = {1e-3};
    spec.t_end = 1.5;
    spec.ensemble = 3;
    spec.params["silo_discharge"] = {{"seed", {7}}};
    const std::vector<RunSpec> plan = plan_sweep(spec);
    REQUIRE(plan.size() == 5);  // and cylinder_free's horizon run (its energy is judged)
    for (int k = 0; k < 3; ++k) {
        CHECK(plan[static_cast<std::size_t>(k)].scene == "silo_discharge");
        CHECK(member_seed(plan[static_cast<std::size_t>(k)]) == 7 + k);
    }
    CHECK(plan[3].scene == "cylinder_free");
    CHECK(plan[4].kind == RunKind::horizon);
    spec.ensemble = 0;
    CHECK_THROWS_AS(plan_sweep(spec), InputError);
}

TEST_CASE("ensembles: the members' curves become a band over the rows they share, and the first member's pictures stay") {
    RunResult a = member("direct", 1, 1.0), b = member("direct", 2, 2.0), c = member("direct", 3, 3.0, "blew up at step 3");
    a.series_columns = b.series_columns = c.series_columns = {"t_open", "mass_left"};
    a.series = {{0.0, 6.0}, {0.01, 5.0}, {0.02, 4.0}};
    b.series = {{0.0, 8.0}, {0.01, 3.0}};  // ended sooner: the band stops with it
    c.series = {{0.0, 100.0}, {0.01, 100.0}};  // failed: not in the band
    a.snapshots = {{0.0, 1.0, 2.0, 3.0, 0.1}};
    b.snapshots = {{0.0, 9.0, 9.0, 9.0, 0.1}};
    a.walls = {{0.0, -1.0, 0.0, 1.0, 0.0}};
    b.walls = {{0.0, -2.0, 0.0, 2.0, 0.0}};
    const std::vector<RunResult> collapsed = collapse_ensembles({a, b, c});
    REQUIRE(collapsed.size() == 1);
    const RunResult& band = collapsed.front();
    CHECK(band.series_columns == std::vector<std::string>{"t_open", "mass_left", "mass_left_min", "mass_left_max"});
    CHECK(band.series == std::vector<std::vector<double>>{{0.0, 7.0, 6.0, 8.0}, {0.01, 4.0, 3.0, 5.0}});
    CHECK(band.snapshots == a.snapshots);
    CHECK(band.walls == a.walls);  // the walls of the same member's pictures
    // Members whose abscissae part ways share only the rows before.
    b.series = {{0.0, 8.0}, {0.015, 3.0}};
    CHECK(collapse_ensembles({a, b}).front().series == std::vector<std::vector<double>>{{0.0, 7.0, 6.0, 8.0}});
}
