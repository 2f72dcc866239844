// The metric table (harness/core/metrics.hpp) is the vocabulary of every run: whatever a run
// of any kind records is in it, or is a scene's own metric.
#include "harness/core/metrics.hpp"
#include "harness/exec/run.hpp"
#include "harness/scenes/scene.hpp"

#include <catch2/catch.hpp>
#include <set>

using namespace rotbench;

TEST_CASE("every metric that a trajectory, reversal or stability run records is in the metric table") {
    std::set<std::string> recorded;
    for (const RunSpec& spec :
         {RunSpec{"asymmetric_free", "direct", 0.05}, RunSpec{"dipole_top", "cayley", 0.05}, RunSpec{"fibre_bounce", "zvw", 1e-6, 1e-4},
          RunSpec{"dipole_top", "omelyan", 0.05, 0, {}, RunKind::reversal}, RunSpec{"sphere_pair", "direct", 0, 0, {}, RunKind::stability}})
        for (const auto& [name, value] : run_one(spec).metrics) recorded.insert(name);
    REQUIRE(recorded.size() > 20);
    for (const auto& name : recorded) {
        INFO(name);
        CHECK(find_metric(name) != nullptr);
    }
}

TEST_CASE("an unstable run records where it stopped, in the table's failure metrics") {
    const RunResult r = run_one({"sphere_pair", "direct", 1e-2, 0.05}, {.measure_time = false});
    REQUIRE(r.value(metric::unstable) == 1.0);
    CHECK(find_metric("fail_step")->kind == MetricKind::failure);
    CHECK(r.has(metric::fail_step));
}

TEST_CASE("the metric table: unique names, and fitted metrics are errors or drifts with a round-off bound") {
    std::set<std::string_view> names;
    for (const auto& m : metric_table()) CHECK(names.insert(m.name).second);
    REQUIRE(fitted_metrics().front() == metric::omega_err_max);  // orders.csv lists it first
    for (const auto& name : fitted_metrics()) {
        INFO(name);
        CHECK(is_error_metric(name));
        CHECK(find_metric(name)->round_off != RoundOff::none);
    }
    CHECK(is_timing_metric(metric::ns_per_step));
    CHECK_FALSE(is_timing_metric(metric::timed_steps));  // how many steps were timed is not a timing
    CHECK_FALSE(is_error_metric(metric::omega_ref_max));
    CHECK(find_metric("discharge_time") == nullptr);  // a scene's own metric
}

TEST_CASE("the report prints counts whole and errors in three significant digits") {
    CHECK(metric_cell(metric::steps, 1000.0) == "1000");
    CHECK(metric_cell(metric::omega_err_max, 1.23456e-5) == "1.235e-05");
    CHECK(metric_cell(metric::omega_err_max, std::numeric_limits<double>::quiet_NaN()) == "—");
}
