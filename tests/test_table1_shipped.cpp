// Table 1's third column: the seed's own code, Kratos DEM as shipped, set beside the published
// value and rotbench's, from whatever client runs are in the results.
#include "harness/analysis/seed_table1.hpp"

#include <catch2/catch.hpp>

using namespace rotbench;

namespace {

RunResult table1_run(const std::string& scheme, double dt, double omega_rms_x, const std::string& failure = "") {
    RunResult r;
    r.spec = {"cylinder_free", scheme, dt, 0.5};
    r.metrics = {{"omega_rms_x", omega_rms_x}, {"omega_rms_y", omega_rms_x}};
    r.failure = failure;
    return r;
}

const Table1Comparison& row_of(const std::vector<Table1Comparison>& rows, const std::string& scheme, char component) {
    for (const auto& row : rows)
        if (row.entry.scheme == scheme && row.entry.component == component) return row;
    throw std::logic_error("no such row");
}

}  // namespace

TEST_CASE("Table 1: Kratos's value stands beside the built-in scheme's, judged by the same 1 % band") {
    // Published at dt = 1e-3: direct w'x 2.79e-1, Runge-Kutta w'x 4.23e-3 (seed 000, Table 1).
    const std::vector<RunResult> runs = {table1_run("direct", 1e-3, 2.79e-1), table1_run("kratos_direct", 1e-3, 1.45e-1),
                                         table1_run("munjiza_rk4", 1e-3, 4.23e-3),
                                         table1_run("kratos_runge_kutta", 1e-3, 4.23e-3 * 1.009)};
    const auto rows = compare_table1(runs);
    const auto& direct = row_of(rows, "direct", 'x');
    CHECK(direct.agrees);
    REQUIRE(direct.shipped);
    CHECK(*direct.shipped == 1.45e-1);
    CHECK_FALSE(direct.shipped_agrees);  // 48 % below the published value
    const auto& rk4 = row_of(rows, "munjiza_rk4", 'x');
    REQUIRE(rk4.shipped);
    CHECK(rk4.shipped_agrees);  // 0.9 %: inside the band of 1 %
}

TEST_CASE("Table 1: no Kratos value where its client did not run or its run failed") {
    const std::vector<RunResult> runs = {table1_run("direct", 1e-3, 2.79e-1), table1_run("zvw_corrected", 1e-3, 4.23e-3),
                                         table1_run("kratos_quaternion", 1e-3, 4.23e-3, "its program exited with status 1")};
    const auto rows = compare_table1(runs);
    CHECK_FALSE(row_of(rows, "direct", 'x').shipped);
    CHECK_FALSE(row_of(rows, "zvw_corrected", 'x').shipped);
    CHECK_FALSE(row_of(rows, "zvw_corrected", 'x').shipped_agrees);
}
