#include "harness/exec/run.hpp"
#include "harness/exec/executor.hpp"
#include "harness/analysis/sweep_plan.hpp"
#include "harness/exec/reference.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/misbehaving_schemes.hpp"
#include "schemes/quaternion.hpp"

#include <catch2/catch.hpp>
#include <sstream>
#include <cmath>
#include <filesystem>
#include <cstring>
#include <limits>
#include <stdexcept>

using namespace rotbench;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> seed_schemes = {"direct", "munjiza_rk4", "zvw", "zvw_corrected"};

RunResult quick_run(const std::string& scheme, double dt, double t_end = 0.0) {
    return run_one({"cylinder_free", scheme, dt, t_end}, {.measure_time = false});
}

}  // namespace

TEST_CASE("the harness evaluates forces exactly once per step, plus once at t = 0") {
    for (const auto& scheme : seed_schemes) {
        const RunResult r = quick_run(scheme, 1e-3);
        INFO(scheme);
        CHECK(r.value("steps") == 500);
        CHECK(r.value("force_evals") == 501);
        CHECK(r.value("unstable") == 0);
    }
}

TEST_CASE("every run reports the metrics of docs/outputs.md that apply to a torque-free scene with a reference") {
    const RunResult r = quick_run("direct", 1e-3);
    for (const char* m : {"omega_rms_x", "omega_rms_y", "omega_rms_z", "omega_err_max", "orientation_err_max",
                          "energy_drift_max", "momentum_drift_max", "quat_norm_err_max", "steps", "force_evals",
                          "cpu_seconds", "ns_per_step", "unstable"}) {
        INFO(m);
        CHECK(r.has(m));
    }
}

TEST_CASE("the step count rule: t_end/dt rounded when it is an integer to 1e-9, else rounded up") {
    CHECK(step_count(0.5, 1e-3) == 500);          // 0.5/1e-3 = 499.99999999999994 in binary
    CHECK(step_count(0.5, 0.3) == 2);             // not a multiple: the run covers 0.6 s
    CHECK(step_count(1.0, 1.0) == 1);
    CHECK_THROWS_AS(step_count(0.5, 0.0), InputError);
    CHECK_THROWS_AS(step_count(0.5, -1e-3), InputError);
    CHECK_THROWS_AS(step_count(0.5, std::numeric_limits<double>::quiet_NaN()), InputError);
    CHECK_THROWS_AS(step_count(1e-4, 1e-3), InputError);  // t_end shorter than dt
}

TEST_CASE("zvw and zvw_corrected coincide without torque (seed section 3.1.1)") {
    const RunResult a = quick_run("zvw", 1e-4), b = quick_run("zvw_corrected", 1e-4);
    for (const char* m : {"omega_rms_x", "omega_rms_y", "orientation_err_max", "energy_drift_max"}) CHECK(a.value(m) == b.value(m));
}

TEST_CASE("Munjiza's scheme keeps the angular momentum of a free body to round-off") {
    // H is its state variable and no torque acts: only the rotations round.
    CHECK(quick_run("munjiza_rk4", 1e-4).value("momentum_drift_max") < 1e-14);
}

TEST_CASE("a scheme that fails is recorded and the sweep goes on") {
    const auto plan = plan_sweep({{"cylinder_free"}, {"test_nan", "test_throws", "test_explodes", "direct"}, {1e-3}, 0.0});
    std::ostringstream out, err;
    Executor executor(out, err, {.run = {.measure_time = false}});
    const auto results = executor.run(plan);
    REQUIRE(results.size() == 8);  // each scheme's run and its horizon run (cylinder_free's energy is judged)
    std::vector<std::string> seen;
    for (const auto& r : results)
        if (r.spec.kind == RunKind::trajectory) seen.push_back(r.spec.scheme);
    CHECK(seen == std::vector<std::string>{"test_nan", "test_throws", "test_explodes", "direct"});
    const auto of = [&](const std::string& scheme, RunKind kind) -> const RunResult& {
        for (const auto& r : results)
            if (r.spec.scheme == scheme && r.spec.kind == kind) return r;
        FAIL("no " << kind_name(kind) << " run of " << scheme);
        return results.front();
    };

    const RunResult& nan_run = of("test_nan", RunKind::trajectory);
    CHECK(nan_run.value("unstable") == 1);
    CHECK(nan_run.value("fail_step") == 1);
    CHECK(std::isnan(nan_run.value("omega_rms_x")));
    CHECK(nan_run.failure.find("blew up at step 1") != std::string::npos);

    CHECK(of("test_throws", RunKind::trajectory).value("unstable") == 1);
    CHECK(of("test_throws", RunKind::trajectory).failure == "threw: plug-in bug");
    CHECK_THAT(of("test_throws", RunKind::horizon).failure, Catch::Contains("threw: plug-in bug"));

    // |w| doubles per step, E grows 4x: 4^n > 1e6 + 1 first at n = 10.
    CHECK(of("test_explodes", RunKind::trajectory).value("unstable") == 1);
    CHECK(of("test_explodes", RunKind::trajectory).value("fail_step") == 10);

    CHECK(of("direct", RunKind::trajectory).value("unstable") == 0);
    CHECK(of("direct", RunKind::trajectory).value("steps") == 500);
    CHECK(of("direct", RunKind::horizon).failure.empty());
    // Each failed run is said in one line as it finishes, the others are not.
    CHECK_THAT(out.str(), Catch::Contains("cylinder_free test_nan trajectory dt=0.001 FAILED: blew up at step 1"));
    CHECK_THAT(out.str(), Catch::Contains("cylinder_free test_throws horizon dt=0.001 FAILED: over 0.5 s: threw: plug-in bug"));
    CHECK_THAT(out.str(), !Catch::Contains("direct"));
}

TEST_CASE("a caught exception becomes the run's failure, except rotbench's own running out of memory") {
    const auto caught = [](auto thrown, const std::string& scheme) {
        try {
            throw thrown;
        } catch (...) {
            return caught_failure(scheme);
        }
    };
    CHECK(caught(std::runtime_error("plug-in bug"), "direct") == "threw: plug-in bug");
    CHECK(caught(42, "direct") == "threw an exception that is not a std::exception");
    // A built-in kernel allocates nothing: a bad_alloc during its run is the harness's, passed up to run_one.
    CHECK_THROWS_AS(caught(std::bad_alloc(), "direct"), std::bad_alloc);
}

TEST_CASE("a damped scene whose energy runs away upwards is stopped there, long before the state overflows") {
    // test_explodes doubles |w| every step, so the kinetic energy grows 4x a step: it passes
    // E0 + 1e6 x the energy scale within log4(1e6) ~ 10 steps of the rotational energy
    // dominating, while |w| overflows to inf only after ~1000 doublings.
    for (const double zeta : {0.0, 0.3}) {
        INFO("zeta " << zeta);
        const RunResult r = run_one({"ellipsoid_pair", "test_explodes", 1e-7, 0.0, {{"zeta", {zeta}}}}, {.measure_time = false});
        CHECK(r.value("unstable") == 1);
        CHECK(r.value("fail_step") < 40);
        CHECK_THAT(r.failure, Catch::Contains("blew up at step"));
    }
}

TEST_CASE("bad sweep inputs are rejected before anything runs, naming the valid ids") {
    try {
        plan_sweep({{"cylinder_fre"}, {}, {}, 0.0});
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("unknown scene 'cylinder_fre'") && Catch::Contains("cylinder_free"));
    }
    try {
        plan_sweep({{"cylinder_free"}, {"rk4"}, {}, 0.0});
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("unknown scheme 'rk4'") && Catch::Contains("munjiza_rk4") &&
                                 Catch::Contains("zvw_corrected"));
    }
    CHECK_THROWS_AS(plan_sweep({{"cylinder_free"}, {"direct"}, {1e-3}, 1e-4}), InputError);
}

TEST_CASE("the option --jobs does not change the results: bit-identical apart from the timing metrics") {
    SweepSpec spec;
    spec.scenes = {"asymmetric_free", "dipole_top"};
    spec.quick = true;
    const auto plan = plan_sweep(spec);
    std::ostringstream out, err;
    const auto serial = Executor(out, err, {.run = {.measure_time = false}, .jobs = 1}).run(plan);
    const auto parallel = Executor(out, err, {.run = {.measure_time = false}, .jobs = 3}).run(plan);
    REQUIRE(serial.size() == parallel.size());
    for (std::size_t i = 0; i < serial.size(); ++i) {
        INFO(serial[i].spec.scene << " " << serial[i].spec.scheme << " " << serial[i].spec.dt);
        CHECK(parallel[i].spec.scheme == serial[i].spec.scheme);
        REQUIRE(parallel[i].metrics.size() == serial[i].metrics.size());
        for (std::size_t m = 0; m < serial[i].metrics.size(); ++m) {
            const auto& [name, value] = serial[i].metrics[m];
            if (is_timing_metric(name)) continue;
            CHECK(parallel[i].metrics[m].first == name);
            CHECK(std::memcmp(&parallel[i].metrics[m].second, &value, sizeof value) == 0);  // bit for bit (NaN too)
        }
    }
}

TEST_CASE("a sweep with a run that blows up finishes, and its report says which run failed, where and why") {
    const fs::path dir = test::fresh_dir("blowup");
    const test::Cli r = test::cli({"run", "--scenes", "cylinder_free", "--schemes", "test_explodes,direct", "--dt", "1e-3",
                                   "--out", dir.string()});
    REQUIRE(r.status == 0);
    const std::string report = test::read(dir / "report.md");
    CHECK_THAT(report, Catch::Contains("2 runs of 2 schemes on 1 scene, 1 of them unstable or failed"));
    // |w| doubles per step: E passes E0 + 1e6 x E0 first at step 10 (see above).
    CHECK_THAT(report, Catch::Contains("- **test_explodes at dt = 0.001 failed**: blew up at step 10 (t = 0.01 s)."));
    CHECK_THAT(r.out, Catch::Contains("FAILED: blew up at step 10"));
    fs::remove_all(dir);
}

// The observer keeps the maxima of raw quantities (|E - E0|, |q|^2, |L - L0|^2, |w - w_ref|^2)
// and scales them once at the end. Division and sqrt round monotonically, so each metric must
// equal, bit for bit, its definition taken at every step of the same trajectory.
TEST_CASE("the drift and error maxima equal their definitions taken at every step") {
    for (const char* id : {"asymmetric_free", "dipole_top"}) {
        INFO(id);
        const double dt = 1e-2;
        const auto scene = make_scene(id);
        const std::int64_t steps = step_count(scene->t_end(), dt);
        const auto reference = make_reference(*scene, dt, steps);
        Bodies bodies = scene->initial_state();
        const auto scheme = SchemeRegistry::instance().at("direct", "scheme").make();
        const double e0 = scene->energy(bodies);
        const Vec3 l0 = total_angular_momentum(bodies);
        double energy = 0, momentum = 0, norm = 0, omega = 0;
        std::int64_t evals = 0;
        simulate(*scene, *scheme, bodies, dt, steps, evals, [&](std::int64_t n, double t, const Bodies& b) {
            energy = std::max(energy, std::abs(scene->energy(b) - e0) / std::abs(e0));
            momentum = std::max(momentum, (total_angular_momentum(b) - l0).norm() / l0.norm());
            norm = std::max(norm, std::abs(b.orientation[0].norm() - 1.0));
            if (reference) omega = std::max(omega, (b.omega[0] - reference->at(0, n, t).omega).norm());
            return true;
        });
        const RunResult r = run_one({id, "direct", dt, 0.0}, {.measure_time = false});
        CHECK(norm > 0.0);  // direct lets |q| wander at round-off: the check below is not 0 == 0
        CHECK(r.value("quat_norm_err_max") == norm);
        CHECK(r.value("energy_drift_max") == energy);
        if (scene->conserves_angular_momentum()) CHECK(r.value("momentum_drift_max") == momentum);
        if (reference) CHECK(r.value("omega_err_max") == omega);
    }
}
