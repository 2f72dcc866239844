#include "harness/analysis/order_fit.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace rotbench;

namespace {

std::vector<OrderPoint> ladder(double dt0, int n, auto error_of) {
    std::vector<OrderPoint> p;
    for (int k = 0; k < n; ++k) {
        const double dt = dt0 * std::pow(0.5, k);
        p.push_back({dt, error_of(dt)});
    }
    return p;
}

}  // namespace

TEST_CASE("order fit: an exact power law gives its order, with a zero-width interval") {
    const OrderFit f = fit_order(ladder(0.1, 6, [](double dt) { return 3.0 * dt * dt; }));
    REQUIRE(f.sufficient);
    CHECK(f.order == Approx(2.0).epsilon(1e-12));
    CHECK(f.order_lo == Approx(2.0).epsilon(1e-10));
    CHECK(f.order_hi == Approx(2.0).epsilon(1e-10));
    CHECK(f.points == 6);
    CHECK(f.local_orders.size() == 5);
}

TEST_CASE("order fit: noise widens the interval, which still holds the true order") {
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.03);  // 3 % multiplicative noise
    int covered = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const OrderFit f = fit_order(ladder(0.1, 8, [&](double dt) { return dt * dt * dt * std::exp(noise(rng)); }));
        REQUIRE(f.sufficient);
        CHECK(f.order_hi > f.order_lo);
        covered += f.order_lo <= 3.0 && 3.0 <= f.order_hi;
    }
    // A 95 % interval: 190 of 200 expected; below 180 has probability < 1e-3 (binomial).
    CHECK(covered >= 180);
}

TEST_CASE("order fit: points at the round-off floor are left out") {
    // Second order down to a plateau at 1e-11 (round-off of an O(1e5) quantity).
    const auto points = ladder(1e-2, 12, [](double dt) { return std::max(dt * dt, 1e-11); });
    const OrderFit f = fit_order(points);
    REQUIRE(f.sufficient);
    CHECK(f.order == Approx(2.0).margin(1e-9));
    CHECK(f.dt_min > 2e-6);  // the plateau starts where dt^2 < 1e-11
    SECTION("and so are those below the absolute floor") {
        const OrderFit g = fit_order(ladder(1e-3, 8, [](double dt) { return dt * dt * dt * 1e-4; }));
        CHECK(g.points < 8);
    }
}

TEST_CASE("order fit: pre-asymptotic points are left out") {
    // e = dt^2 (1 + 50 dt^2): far from order 2 at dt ~ 0.1, order 2 once 50 dt^2 << 1.
    const OrderFit f = fit_order(ladder(0.4, 10, [](double dt) { return dt * dt * (1 + 50 * dt * dt); }));
    REQUIRE(f.sufficient);
    CHECK(f.order == Approx(2.0).margin(0.05));
    CHECK(f.dt_max < 0.4);
}

TEST_CASE("order fit: a saturated error at the coarse steps does not hide the asymptotic range") {
    // As fincham on dzhanibekov: an O(1) error that wanders (1.5, then 1.3 at half the step)
    // before it falls at third order from dt = 0.025. Read as a round-off plateau, the rise
    // from 1.3 to 2.2 used to drop every finer point: "insufficient".
    auto points = ladder(0.025, 6, [](double dt) { return 2.2 * std::pow(dt / 0.025, 3); });
    points.insert(points.begin(), {{0.1, 1.5}, {0.05, 1.3}});
    const OrderFit f = fit_order(points);
    REQUIRE(f.sufficient);
    CHECK(f.order == Approx(3.0).margin(1e-9));
    CHECK(f.dt_max == 0.025);
    CHECK(f.points == 6);
    // A ladder whose finest error is its largest never converges: no order.
    CHECK_FALSE(fit_order({{0.1, 1e-2}, {0.05, 1e-4}, {0.025, 1e-6}, {0.0125, 0.5}}).sufficient);
}

TEST_CASE("order fit: fewer than 3 usable points is insufficient, not a number") {
    CHECK_FALSE(fit_order(ladder(0.1, 2, [](double dt) { return dt; })).sufficient);
    CHECK_FALSE(fit_order({{0.1, 1e-3}, {0.05, NAN}, {0.025, 1e-20}, {0.0125, 2e-4}}).sufficient);
}
