// Baselines (`rotbench compare`, `gate --baseline`): an identical rerun passes, a degraded
// error, a lost order, a run newly unstable or a significant slow-down fails.
#include "harness/analysis/mann_whitney.hpp"
#include "harness/gate/compare.hpp"
#include "harness/store/csv.hpp"
#include "harness/store/results_csv.hpp"
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace rotbench;
using namespace rotbench::test;

namespace {

// By value: callers pass the temporary that compare_runs returns.
Verdict find(const Comparison& c, const std::string& id) {
    for (const auto& v : c.verdicts)
        if (v.of.id == id) return v;
    FAIL("no verdict " << id);
    return {};
}

std::vector<RunResult> ladder(const std::string& scheme) {
    std::vector<RunResult> runs;
    for (double dt : {0.02, 0.01, 0.005, 0.0025}) runs.push_back(run_one({"dipole_top", scheme, dt, 2.0}, {.measure_time = false}));
    return runs;
}

}  // namespace

TEST_CASE("Mann-Whitney U: the normal approximation with tie and continuity corrections") {
    // Separated samples of 5: U = 0; mean 12.5, variance 25/12 x 11 = 22.917; z = (12.5 - 0.5) / 4.787 =
    // 2.5067; two-sided p = 2 Q(2.5067) = 0.012186.
    const UTest t = mann_whitney({1, 2, 3, 4, 5}, {6, 7, 8, 9, 10});
    CHECK(t.valid);
    CHECK(t.u == 0);
    CHECK(t.p == Approx(0.012186).epsilon(1e-4));
    // With ties: ranks of the first sample 1, 3, 3, 6, 6, so U = 19 - 15 = 4; tie term 24 + 24 + 6 = 54,
    // variance 25/12 x (11 - 54/90) = 21.667; z = (8.5 - 0.5) / 4.6547 = 1.7187; p = 2 Q(1.7187) = 0.08567.
    const UTest ties = mann_whitney({1, 2, 2, 3, 3}, {2, 3, 4, 4, 5});
    CHECK(ties.u == 4);
    CHECK(ties.p == Approx(0.08567).epsilon(1e-3));
    CHECK_FALSE(mann_whitney({1, 2, 3}, {4, 5, 6}).valid);  // too few to test
}

TEST_CASE("compare: an identical rerun passes, a degraded error and a lost order fail") {
    const auto base = ladder("no_squish");
    const Comparison same = compare_runs(base, ladder("no_squish"), {}, "base");
    for (const auto& v : same.verdicts) {
        INFO(v.message);
        CHECK(v.passed);
    }
    auto worse = base;
    for (auto& [name, value] : worse[2].metrics)
        if (name == "omega_err_max") value *= 1.2;
    const Verdict acc = find(compare_runs(base, worse, {}, "base"), "baseline_accuracy");
    CHECK_FALSE(acc.passed);
    CHECK_THAT(acc.message, Catch::Contains("omega_err_max at dt = 0.005") && Catch::Contains("+20.0 %"));
    auto within = base;
    for (auto& [name, value] : within[2].metrics)
        if (name == "omega_err_max") value *= 1.05;
    CHECK(find(compare_runs(base, within, {}, "base"), "baseline_accuracy").passed);
    // A first-order scheme in place of a second-order one: the order falls by one.
    auto first_order = ladder("zvw");
    for (auto& r : first_order) r.spec.scheme = "no_squish";
    const Verdict ord = find(compare_runs(base, first_order, {}, "base"), "baseline_order");
    CHECK_FALSE(ord.passed);
    CHECK_THAT(ord.message, Catch::Contains("fell from 2.00 [2.00, 2.00] to 1.00 [1.00, 1.00]"));
}

TEST_CASE("compare: the headline is the claims' metric when it regressed, and a large change is a factor") {
    const auto base = ladder("no_squish");
    auto worse = base;
    for (auto& [name, value] : worse[2].metrics) {
        if (name == "omega_err_max") value *= 1.5;          // the claimed metric: +50 %
        if (name == "energy_drift_max") value *= 63786.0;   // another, far more
    }
    const Verdict acc = find(compare_runs(base, worse, {}, "base"), "baseline_accuracy");
    CHECK_FALSE(acc.passed);
    CHECK_THAT(acc.message, Catch::Contains("omega_err_max at dt = 0.005") && Catch::Contains("+50.0 %"));
    auto energy_only = base;
    for (auto& [name, value] : energy_only[2].metrics)
        if (name == "energy_drift_max") value *= 63786.0;
    const Verdict factor = find(compare_runs(base, energy_only, {}, "base"), "baseline_accuracy");
    CHECK_FALSE(factor.passed);
    CHECK_THAT(factor.message, Catch::Contains("6.38e+04 times as large") && !Catch::Contains("%)"));
}

TEST_CASE("compare: a run newly unstable fails") {
    const auto base = ladder("direct");
    auto now = base;
    for (auto& [name, value] : now[0].metrics)
        if (name == "unstable") value = 1.0;
    now[0].failure = "blew up at step 3 (t = 0.06 s)";
    const Verdict v = find(compare_runs(base, now, {}, "base"), "baseline_stability");
    CHECK_FALSE(v.passed);
    CHECK_THAT(v.message, Catch::Contains("unstable now (blew up at step 3"));
}

TEST_CASE("compare: a run or an ensemble that fails now is a regression, never a pass for want of errors") {
    const auto base = ladder("direct");
    SECTION("a run that fails without being unstable") {
        auto now = base;
        now[1].metrics.clear();
        now[1].failure = "its worker was killed by signal 9";
        const Verdict v = find(compare_runs(base, now, {}, "base"), "baseline_stability");
        CHECK_FALSE(v.passed);
        CHECK_THAT(v.message, Catch::Contains("the run at dt = 0.01 fails now (its worker was killed by signal 9)"));
    }
    SECTION("an ensemble with more failed members, every one of them at the worst") {
        auto with_members = [](std::vector<RunResult> runs, double failed) {
            for (auto& r : runs) r.metrics.emplace_back(metric::ensemble_failed, failed);
            return runs;
        };
        const auto before = with_members(base, 0);
        auto now = with_members(base, 3);
        for (auto& r : now) r.failure = "blew up at step 3 (t = 0.06 s)";
        const Verdict v = find(compare_runs(before, now, {}, "base"), "baseline_stability");
        CHECK_FALSE(v.passed);
        CHECK_THAT(v.message, Catch::Contains("fails now, 3 of its members against 0"));
        CHECK(find(compare_runs(now, now, {}, "base"), "baseline_stability").passed);  // failing as before: no change
    }
}

TEST_CASE("compare: a change from round-off is not a percentage, and orders that barely differ are shown apart") {
    const auto base = ladder("no_squish");
    auto from_round_off = base;
    for (auto& r : from_round_off)
        for (auto& [name, value] : r.metrics)
            if (name == "omega_err_max") value = 1e-17;
    const Verdict acc = find(compare_runs(from_round_off, base, {}, "base"), "baseline_accuracy");
    CHECK_FALSE(acc.passed);
    CHECK_THAT(acc.message, Catch::Contains("went from round-off (1e-17) to") && !Catch::Contains("%)"));
    // A drop of 0.002 in order: reported with the digits that tell the two apart.
    auto slightly = base;
    for (auto& r : slightly)
        for (auto& [name, value] : r.metrics)
            if (name == "omega_err_max") value *= std::pow(r.spec.dt / 0.02, -0.002);
    const Verdict ord = find(compare_runs(base, slightly, {}, "base"), "baseline_order");
    CHECK(ord.passed);
    CHECK_THAT(ord.message, Catch::Matches(".*fell from 2\\.\\d{4} \\[.*\\] to 1\\.99\\d{2} \\[.*"));
}

TEST_CASE("compare: an order change within the intervals is no change, and an improvement is said to be one") {
    const auto base = ladder("no_squish");
    // Noise of a few per cent on each error: the fitted orders move by a few hundredths, inside their intervals.
    auto noisy = base;
    double sign = 1;
    for (auto& r : noisy)
        for (auto& [name, value] : r.metrics)
            if (name == "omega_err_max") value *= 1 + 0.04 * (sign = -sign);
    const Verdict same = find(compare_runs(base, noisy, {}, "base"), "baseline_order");
    CHECK(same.passed);
    CHECK_THAT(same.message, Catch::Contains("no observed order changed beyond its 95 % interval"));
    // The other way round: a first-order ladder replaced by a second-order one, errors all smaller.
    const auto first = ladder("direct");
    auto second = first;
    for (auto& r : second)
        for (auto& [name, value] : r.metrics)
            if (name == "omega_err_max" || name == "orientation_err_max") value *= r.spec.dt / 0.05;
    const Comparison c = compare_runs(first, second, {}, "base");
    CHECK_THAT(find(c, "baseline_order").message, Catch::Contains("improved: the order of"));
    CHECK_THAT(find(c, "baseline_accuracy").message, Catch::Contains("improved: "));
}

TEST_CASE("compare: comparing nothing fails") {
    const auto base = ladder("direct"), now = ladder("zvw");
    const Comparison c = compare_runs(base, now, {}, "base");
    const Verdict v = find(c, "baseline_matched");
    CHECK_FALSE(v.passed);
    CHECK_THAT(v.message, Catch::Contains("no run of the new results is in the baseline (4 new, 4 in the baseline): nothing was compared"));
    const Comparison same = compare_runs(base, base, {}, "base");
    CHECK_FALSE(std::any_of(same.verdicts.begin(), same.verdicts.end(), [](const Verdict& x) { return x.of.id == "baseline_matched"; }));
}

TEST_CASE("compare: runs of the baseline missing from the new results fail, and an order they carried is lost") {
    const auto base = ladder("direct");
    SECTION("one run missing: baseline_matched fails and names it; the order on three rungs is still measured") {
        const std::vector<RunResult> now(base.begin(), base.end() - 1);
        const Comparison c = compare_runs(base, now, {}, "base");
        const Verdict v = find(c, "baseline_matched");
        CHECK_FALSE(v.passed);
        CHECK(v.of.scene == "dipole_top");
        CHECK(v.of.scheme == "direct");
        CHECK_THAT(v.message, Catch::Contains("1 run of the baseline not in the new results (trajectory dt=0.0025)"));
    }
    SECTION("two missing: the order is not measurable on the two left, a regression") {
        const std::vector<RunResult> now(base.begin(), base.begin() + 2);
        const Verdict ord = find(compare_runs(base, now, {}, "base"), "baseline_order");
        CHECK_FALSE(ord.passed);
        CHECK_THAT(ord.message, Catch::Contains("and is not measurable now"));
    }
    SECTION("a whole scheme missing: a failed verdict of its own, though every run of the other matched") {
        auto both = base;
        for (const auto& r : ladder("zvw")) both.push_back(r);
        const Comparison c = compare_runs(both, base, {}, "base");
        const Verdict v = find(c, "baseline_matched");
        CHECK_FALSE(v.passed);
        CHECK(v.of.scheme == "zvw");
        CHECK_THAT(v.message, Catch::Contains("4 runs of the baseline not in the new results"));
    }
}

TEST_CASE("compare: a cost regression counts only when it is large and significant against the timing repeats") {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(1.0, 0.02);
    const auto timed = [&](double factor, int repeats) {
        auto runs = ladder("direct");
        for (auto& r : runs) {
            r.timing_samples.clear();
            for (int k = 0; k < repeats; ++k) r.timing_samples.push_back(factor * noise(rng) * r.value("steps") * 1e-7);
        }
        return runs;
    };
    const auto base = timed(1.0, 3);
    CHECK_FALSE(find(compare_runs(base, timed(1.2, 3), {}, "base"), "baseline_cost").passed);  // 12 repeats each: +20 %
    CHECK(find(compare_runs(base, timed(1.02, 3), {}, "base"), "baseline_cost").passed);       // +2 %: within 5 %
    CHECK(find(compare_runs(base, timed(1.0, 3), {}, "base"), "baseline_cost").passed);        // the same
    const auto thin = [&](double factor) {
        auto runs = timed(factor, 1);
        runs.resize(2);
        return runs;
    };
    const Verdict untested = find(compare_runs(thin(1.0), thin(1.5), {}, "base"), "baseline_cost");
    CHECK(untested.passed);  // 2 repeats each: nothing to test
    CHECK_THAT(untested.message, Catch::Contains("not tested"));
}

TEST_CASE("rotbench compare: exit 0 on an identical rerun, 1 on a degraded one, with CSV and JUnit") {
    const fs::path dir = fresh_dir("compare");
    const std::vector<std::string> sweep = {"run", "--scenes", "dipole_top", "--schemes", "direct,zvw", "--quick", "--energy-series", "0"};
    auto into = [&](const std::string& name) {
        std::vector<std::string> args = sweep;
        args.insert(args.end(), {"--out", (dir / name).string()});
        return cli(args).status;
    };
    REQUIRE(into("a") == 0);
    REQUIRE(into("b") == 0);
    fs::create_directories(dir / "reports");
    // Timing is not a unit test's business (the tests share the machine): the cost tolerance is
    // set out of reach, and the cost check is tested above on fixed samples.
    const Cli same = cli({"compare", (dir / "a").string(), (dir / "b").string(), "--out", (dir / "cmp").string(), "--junit",
                          (dir / "reports" / "compare.xml").string(), "--cost-tolerance", "100"});
    INFO(same.out);
    CHECK(same.status == 0);
    CHECK_THAT(read(dir / "cmp" / "compare.csv"), Catch::StartsWith("scene,scheme,kind,dt,metric,base,new,change\n"));
    CHECK_THAT(read(dir / "reports" / "compare.xml"), Catch::Contains("baseline_accuracy on dipole_top"));
    // Degrade one error of b by half in its run store: a regression, named.
    std::vector<RunResult> degraded = read_results(dir / "b");
    for (auto& r : degraded)
        for (auto& [name, value] : r.metrics)
            if (r.spec.scheme == "zvw" && r.spec.dt == 0.005 && name == "omega_err_max") value *= 1.5;
    write(dir / "b" / "runs.jsonl", run_store(degraded));
    const Cli worse = cli({"compare", (dir / "a").string(), (dir / "b").string(), "--cost-tolerance", "100", "--summary",
                           (dir / "reports" / "compare.md").string()});
    CHECK(worse.status == 1);
    CHECK_THAT(read(dir / "reports" / "compare.md"), Catch::StartsWith("## rotbench compare: FAILED"));
    CHECK_THAT(worse.out, Catch::Contains("FAIL dipole_top/zvw: zvw: baseline_accuracy on dipole_top: omega_err_max at dt = 0.005"));
    CHECK(cli({"compare", (dir / "a").string(), (dir / "absent").string()}).status == 2);
    fs::remove_all(dir);
}

TEST_CASE("gate --baseline: the same gate against its own earlier run passes") {
    const fs::path dir = fresh_dir("gate_baseline");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nscene = \"dipole_top\"\nschemes = [\"direct\", \"zvw\"]\nmin_order = 0.8\n"
                          "dt = [0.02, 0.01, 0.005]\n");
    REQUIRE(cli({"gate", (dir / "g.toml").string(), "--out", (dir / "first").string()}).status == 0);
    const Cli again = cli({"gate", (dir / "g.toml").string(), "--baseline", (dir / "first").string()});
    INFO(again.out);
    CHECK(again.status == 0);
    CHECK_THAT(again.out, Catch::Contains("PASS dipole_top/zvw: zvw: baseline_order on dipole_top"));
    // One scheme of the two selected: the other's baseline runs are not missing, they were not asked for.
    const Cli one = cli({"gate", (dir / "g.toml").string(), "--schemes", "zvw", "--baseline", (dir / "first").string()});
    INFO(one.out);
    CHECK(one.status == 0);
    CHECK_THAT(one.out, !Catch::Contains("baseline_matched"));
    // A step dropped from the gate file (another added): the baseline's run at it is missing, a regression.
    write(dir / "g.toml", "[[check]]\nscene = \"dipole_top\"\nschemes = [\"direct\", \"zvw\"]\nmin_order = 0.8\n"
                          "dt = [0.02, 0.01, 0.0025]\n");
    const Cli fewer = cli({"gate", (dir / "g.toml").string(), "--baseline", (dir / "first").string()});
    CHECK(fewer.status == 1);
    CHECK_THAT(fewer.out, Catch::Contains("FAIL dipole_top/zvw: zvw: baseline_matched on dipole_top: 1 run of the baseline not in the "
                                          "new results (trajectory dt=0.005)"));
    fs::remove_all(dir);
}
