// The report's recommendation: each rule drives a scheme into "use", "for short runs", "avoid" or
// "not judged here", and Peng's step is flagged only where no sound scheme reaches it.
#include "harness/analysis/scheme_verdicts.hpp"

#include <catch2/catch.hpp>

using namespace rotbench;

namespace {

OrderVerdict claimed(int order, double lo, double hi) {
    OrderVerdict v;
    v.claimed = std::to_string(order), v.claimed_order = order;
    v.fitted = 2, v.lo = lo, v.hi = hi;
    return v;
}

// A scheme that holds everything a user could ask: claims second order and meets its claims,
// momentum kept, energy bounded.
SchemeVerdict sound(const std::string& id, double ns) {
    SchemeVerdict v;
    v.scheme = id, v.free = claimed(2, 1.98, 2.01), v.torque = claimed(2, 2.0, 2.0), v.momentum_runs = 4, v.momentum_kept = true;
    v.energy = EnergyVerdict::bounded, v.stability_lo = 0.4, v.stability_hi = 1.4, v.ns_per_step = ns;
    v.claims_anything = true, v.claims_judged = 5;
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
    first_order.torque = claimed(1, 0.99, 1.01);
    auto leaky = sound("leaky", 40);
    leaky.momentum_kept = false, leaky.momentum_worst = 5e-3;
    auto weak = sound("weak", 40);
    weak.stability_lo = 0.004, weak.stability_weak = "sphere_pair ζ = 0";
    auto exact = sound("exact", 45);  // exact without torque: second order or better there
    exact.free.claimed = "exact", exact.free.claimed_order = 0, exact.free.fitted = 0, exact.free.exact = 2;
    // Claims 2 and shows 2.4 on a claim scene: above the lowest order the user asks, but its claim
    // fails as the gate judges it (|2.4 - 2| > order_tolerance), so it is not recommended.
    auto overshoots = sound("overshoots", 20);
    overshoots.free = claimed(2, 2.4, 2.4), overshoots.claims_failed = {"order_without_torque on asymmetric_free"};
    auto unjudged = sound("unjudged", 10);  // none of the claim scenes ran
    unjudged.claims_judged = 0;
    auto control = sound("control", 30);
    control.control = true;
    for (const auto& x : {drifting, first_order, leaky, weak, control, exact, overshoots, unjudged}) v.push_back(x);
    const SchemeChoice r = recommend(v, {});
    CHECK(r.use == std::vector<std::string>{"exact", "a", "b"});
    CHECK(r.short_runs == std::vector<std::string>{"drifts"});
    CHECK(r.unjudged == std::vector<std::string>{"unjudged"});
    CHECK(avoided(r, "overshoots", "fails its claims: order_without_torque on asymmetric_free"));
    CHECK(avoided(r, "first", "order 1 under an orientation-dependent torque"));
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
