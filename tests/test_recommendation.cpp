// The report's recommendation: each rule drives a scheme into "use", "for short runs" or "avoid",
// and Peng's step is flagged only where no sound scheme reaches it.
#include "harness/analysis/scheme_verdicts.hpp"

#include <catch2/catch.hpp>

using namespace rotbench;

namespace {

OrderVerdict fitted(double lo, double hi) {
    OrderVerdict v;
    v.fitted = 2, v.lo = lo, v.hi = hi;
    return v;
}

// A scheme that holds everything a user could ask: second order, momentum kept, energy bounded.
SchemeVerdict sound(const std::string& id, double ns) {
    SchemeVerdict v;
    v.scheme = id, v.free = fitted(1.98, 2.01), v.torque = fitted(2.0, 2.0), v.momentum_runs = 4, v.momentum_kept = true;
    v.energy = EnergyVerdict::bounded, v.stability_lo = 0.4, v.stability_hi = 1.4, v.ns_per_step = ns;
    return v;
}

bool avoided(const SchemeChoice& r, const std::string& id, const std::string& why) {
    for (const auto& [scheme, reason] : r.avoid)
        if (scheme == id) return reason.find(why) != std::string::npos;
    return false;
}

StabilityRow row(const std::string& scene, const std::string& scheme, double zeta, double ratio) {
    StabilityRow s;
    s.scene = scene, s.scheme = scheme, s.zeta = zeta, s.dt_peng = 1e-4, s.dt_empirical = ratio * 1e-4;
    return s;
}

}  // namespace

TEST_CASE("recommendation: a scheme holding every claim is used, cheapest first, and each failed rule moves it") {
    std::vector<SchemeVerdict> v = {sound("b", 200), sound("a", 100)};
    auto drifting = sound("drifts", 50);
    drifting.energy = EnergyVerdict::drifting;
    auto first_order = sound("first", 40);
    first_order.torque = fitted(0.99, 1.01);
    auto leaky = sound("leaky", 40);
    leaky.momentum_kept = false, leaky.momentum_worst = 5e-3;
    auto weak = sound("weak", 40);
    weak.stability_lo = 0.004, weak.stability_weak = "sphere_pair ζ = 0";
    auto plateau = sound("plateau", 45);  // exact, but its error stops falling at 1.2e-9 on one scene: round-off
    plateau.free.fitted = 0, plateau.free.exact = 4, plateau.free.no_convergence = 1, plateau.free.stuck_lo = plateau.free.stuck_hi = 1.2e-9;
    auto stuck = sound("stuck", 45);  // an error that stops falling at 1e-3: not converging
    stuck.free.no_convergence = 1, stuck.free.stuck_lo = stuck.free.stuck_hi = 1e-3;
    auto control = sound("control", 30);
    control.control = true;
    for (const auto& x : {drifting, first_order, leaky, weak, control, plateau, stuck}) v.push_back(x);
    const SchemeChoice r = recommend(v, {});
    CHECK(r.use == std::vector<std::string>{"plateau", "a", "b"});
    CHECK(avoided(r, "stuck", "no second order without torque"));
    CHECK(r.short_runs == std::vector<std::string>{"drifts"});
    CHECK(avoided(r, "first", "order 0.99 under an orientation-dependent torque"));
    CHECK(avoided(r, "leaky", "loses angular momentum without torque (up to 5.0e-03)"));
    CHECK(avoided(r, "weak", "stable only to 0.004 of Peng's step on sphere_pair ζ = 0"));
    CHECK(avoided(r, "control", "a deliberately wrong control"));
    CHECK(r.avoid.size() == 5);
}

TEST_CASE("recommendation: Peng's step is flagged at a damping ratio only where no sound scheme reaches it") {
    const std::vector<SchemeVerdict> v = {sound("a", 1), sound("b", 1)};
    const std::vector<StabilityRow> rows = {row("sphere_pair", "a", 0.0, 1.0),      row("sphere_pair", "b", 0.0, 1.0),
                                            row("sphere_pair", "a", 0.1, 0.8),      row("sphere_pair", "b", 0.1, 0.82),
                                            row("ellipsoid_pair", "a", 0.1, 1.19),  row("sphere_pair", "a", 0.3, 1.0),
                                            row("sphere_pair", "b", 0.3, 0.5),      row("ellipsoid_pair", "b", 0.5, 0.9)};
    const SchemeChoice r = recommend(v, rows);
    REQUIRE(r.peng_unsafe.size() == 2);  // ζ = 0 is not damped; at ζ = 0.3 scheme a reaches Peng's step
    CHECK(r.peng_unsafe[0].zeta == 0.1);
    CHECK(r.peng_unsafe[0].scene == "sphere_pair");
    CHECK(r.peng_unsafe[0].best_ratio == Approx(0.82));
    CHECK(r.peng_unsafe[1].zeta == 0.5);
    CHECK(r.peng_unsafe[1].scene == "ellipsoid_pair");
}
