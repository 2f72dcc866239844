// The seed's Table 1 (Irazabal et al., test case 1), reproduced entry by entry.
#include "harness/exec/run.hpp"
#include "harness/analysis/seed_table1.hpp"
#include "schemes/munjiza_rk4.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace rotbench;

namespace {

const std::vector<RunResult>& table1_runs() {
    static const std::vector<RunResult> runs = [] {
        std::vector<RunResult> r;
        for (const char* scheme : {"direct", "munjiza_rk4", "zvw_corrected"})
            for (double dt : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6})
                r.push_back(run_one({"cylinder_free", scheme, dt, 0.0}, {.measure_time = false}));
        return r;
    }();
    return runs;
}

const Table1Comparison& entry(const std::vector<Table1Comparison>& rows, const std::string& scheme, double dt, char c) {
    for (const auto& row : rows)
        if (row.entry.scheme == scheme && row.entry.dt == dt && row.entry.component == c) return row;
    throw std::logic_error("no such Table 1 entry");
}

// The small-angle branch of q(w, dt) in the authors' code (Kratos DEMApplication,
// GeometryFunctions::UpdateOrientation), re-expressed here only to test the explanation
// of the dt = 1e-6 entry: below (theta^4/24 < eps) it uses (1 + theta^2/2, theta (1 -
// theta^2/6)) normalised, where the cosine series is 1 - theta^2/2.
struct PublishedSmallAngleIncrement {
    static constexpr bool steps_packs = true;
    template <class S>
    static QuatT<S> map(const Vec3T<S>& omega, double dt) {
        const Vec3T<S> theta = 0.5 * dt * omega;
        const S t = theta.norm();
        const auto exact = t * t * t * t / 24.0 >= std::numeric_limits<double>::epsilon();
        const Vec3T<S> v = (1.0 - t * t / 6.0) * theta;
        return select(exact, rotation_increment<S>(omega, dt), normalized(QuatT<S>(1.0 + t * t / 2.0, v.x(), v.y(), v.z())));
    }
};

const RegisterScheme<MunjizaRk4<PublishedSmallAngleIncrement>> published_rk4(
    "test_munjiza_rk4_published_small_angle", "test only: munjiza_rk4 with the publication's small-angle q(w, dt)",
    "tests/test_table1.cpp", "", {.sound = false});

}  // namespace

TEST_CASE("Table 1: every entry with dt = 1e-2 ... 1e-5 agrees within 1 %", "[study]") {
    const auto rows = compare_table1(table1_runs());
    REQUIRE(rows.size() == 30);
    int checked = 0;
    for (const auto& row : rows) {
        if (row.entry.dt < 1e-5) continue;
        INFO(row.entry.scheme << " dt=" << row.entry.dt << " w'" << row.entry.component << ": published "
                              << row.entry.published << ", computed " << row.computed);
        CHECK(std::abs(row.relative_difference) <= table1_tolerance);
        ++checked;
    }
    CHECK(checked == 24);
}

TEST_CASE("Table 1 at dt = 1e-6: direct agrees, the other two disagree for the reasons the report gives", "[study]") {
    const auto rows = compare_table1(table1_runs());
    for (char c : {'x', 'y'}) {
        INFO("component " << c);
        CHECK(entry(rows, "direct", 1e-6, c).agrees);

        // Munjiza: the scheme continues its dt^2 trend (published dt = 1e-5 value / 100,
        // to the 0.5 % that 3 printed digits and the measured departure from pure dt^2
        // scaling allow) and lies far below the printed 1e-6 value...
        const auto& rk = entry(rows, "munjiza_rk4", 1e-6, c);
        const double rk_trend = entry(rows, "munjiza_rk4", 1e-5, c).entry.published / 100.0;
        CHECK(std::abs(rk.computed / rk_trend - 1.0) < 0.005);
        CHECK(rk.entry.published / rk.computed > 5.0);
        // ...which the same scheme reproduces, within the 1 % band, with the
        // publication's small-angle map.
        const RunResult replica = run_one({"cylinder_free", "test_munjiza_rk4_published_small_angle", 1e-6, 0.0},
                                          {.measure_time = false});
        CHECK(std::abs(replica.value(std::string("omega_rms_") + c) / rk.entry.published - 1.0) <= table1_tolerance);
        // ...and which barely touches dt = 1e-5, where only the half-step increments of
        // eqs. 47-48 take the branch (|w| dt/4 = 2.5e-4 < 2.7e-4): the replica stays within
        // 0.1 % of the scheme there, far inside the 1 % band of that published entry.
        const RunResult replica_1e5 = run_one({"cylinder_free", "test_munjiza_rk4_published_small_angle", 1e-5, 0.0},
                                              {.measure_time = false});
        const double rk_1e5 = entry(rows, "munjiza_rk4", 1e-5, c).computed;
        CHECK(std::abs(replica_1e5.value(std::string("omega_rms_") + c) / rk_1e5 - 1.0) < 0.001);

        // Zhao-van Wachem: on its dt^2 trend within 0.5 %; the printed value is 1.5-2.5 %
        // above it, a finding pinned here so that it cannot change silently.
        const auto& zvw = entry(rows, "zvw_corrected", 1e-6, c);
        const double zvw_trend = entry(rows, "zvw_corrected", 1e-5, c).entry.published / 100.0;
        CHECK(std::abs(zvw.computed / zvw_trend - 1.0) < 0.005);
        CHECK(-zvw.relative_difference > 0.015);
        CHECK(-zvw.relative_difference < 0.025);
    }
}

TEST_CASE("Table 1's orders: direct first order, Runge-Kutta and quaternion second order", "[study]") {
    // Ratio of errors between dt = 1e-4 and 1e-5 (asymptotic range): 10^p.
    const auto rows = compare_table1(table1_runs());
    auto order = [&](const std::string& scheme) {
        return std::log10(entry(rows, scheme, 1e-4, 'x').computed / entry(rows, scheme, 1e-5, 'x').computed);
    };
    CHECK(order("direct") == Approx(1.0).margin(0.05));
    CHECK(order("munjiza_rk4") == Approx(2.0).margin(0.05));
    CHECK(order("zvw_corrected") == Approx(2.0).margin(0.05));
}
