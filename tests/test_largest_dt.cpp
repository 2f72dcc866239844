// The report's headline, the largest dt for a tolerance, branch by branch: each way an answer
// is reached, and a run without a CPU time (a client's) judged by its errors like any other.
#include "harness/analysis/answer.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace rotbench;

namespace {

// A run on a scene of 1 s whose relative error is `error`; `ns` per step, NaN when not timed.
RunResult run(double dt, double error, double ns = 100.0) {
    RunResult r;
    r.spec = {"asymmetric_free", "s", dt, 1.0};
    r.metrics = {{metric::omega_err_max, error}, {metric::omega_ref_max, 1.0}, {metric::ns_per_step, ns}, {metric::steps, 1.0 / dt}};
    return r;
}

OrderRow order(OrderStatus status, double p = 2.0) {
    OrderRow o{"asymmetric_free", "s", metric::omega_err_max, {}, status};
    o.fit.sufficient = status == OrderStatus::fit;
    o.fit.order = p;
    return o;
}

LargestDt answer(const std::vector<RunResult>& runs, const OrderRow& o, double tolerance) {
    std::vector<const RunResult*> pointers;
    for (const auto& r : runs) pointers.push_back(&r);
    return largest_dt(pointers, o, tolerance);
}

}  // namespace

TEST_CASE("largest dt: interpolated log-log between the two steps around the tolerance") {
    // Errors 1e-2 at 0.1 and 1e-4 at 0.01 (order 2): 1e-3 is met at 0.1 x 10^-0.5.
    const auto a = answer({run(0.1, 1e-2), run(0.01, 1e-4)}, order(OrderStatus::fit), 1e-3);
    CHECK(a.how == "interpolated");
    CHECK(a.dt == Approx(0.1 / std::sqrt(10.0)).epsilon(1e-12));
    CHECK(a.cpu_seconds == Approx(100e-9 / a.dt).epsilon(1e-12));  // 100 ns a step, 1 s of steps
}

TEST_CASE("largest dt: the coarsest step already meets it, so dt is at least that") {
    const auto a = answer({run(0.1, 1e-4), run(0.05, 2.5e-5)}, order(OrderStatus::fit), 1e-3);
    CHECK(a.how == "at most");
    CHECK(a.dt == 0.1);
}

TEST_CASE("largest dt: no step meets it, the finest is extended with the observed order") {
    const auto a = answer({run(0.1, 1e-1), run(0.05, 2.5e-2)}, order(OrderStatus::fit, 2.0), 1e-3);
    CHECK(a.how == "extrapolated");
    CHECK(a.dt == Approx(0.05 * std::sqrt(1e-3 / 2.5e-2)).epsilon(1e-12));
}

TEST_CASE("largest dt: exact at every step, the coarsest measured, limited by stability alone") {
    const auto a = answer({run(0.1, 1e-15), run(0.05, 1e-15)}, order(OrderStatus::exact), 1e-6);
    CHECK(a.how == "exact");
    CHECK(a.dt == 0.1);
}

TEST_CASE("largest dt: never, where no step meets it and there is no order to extend with") {
    CHECK(answer({run(0.1, 0.5), run(0.05, 0.5)}, order(OrderStatus::no_convergence), 1e-3).how == "never");
    CHECK(answer({run(0.1, 0.5), run(0.05, 0.2)}, order(OrderStatus::fit, 0.05), 1e-3).how == "never");  // order too small
    auto failed = run(0.1, 1e-4);
    failed.failure = "blew up";
    CHECK(answer({failed}, order(OrderStatus::fit), 1e-3).how == "never");
}

TEST_CASE("largest dt: a run that was not timed (a client's) gets its dt from its errors and no CPU time") {
    const double nan = std::nan("");
    const auto a = answer({run(0.1, 1e-2, nan), run(0.01, 1e-4, nan)}, order(OrderStatus::fit), 1e-3);
    CHECK(a.how == "interpolated");
    CHECK(a.dt == Approx(0.1 / std::sqrt(10.0)).epsilon(1e-12));
    CHECK(std::isnan(a.cpu_seconds));
    const auto met = answer({run(0.1, 3e-15, nan), run(0.05, 3e-15, nan)}, order(OrderStatus::fit), 1e-3);
    CHECK(met.how == "at most");  // agrees to 3e-15 everywhere: met at every step, not "never"
}
