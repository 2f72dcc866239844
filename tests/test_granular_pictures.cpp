// The granular scenes' pictures (reports/granular_pictures.hpp): the snapshot SVG, and the
// curves and snapshots written beside the report and read back whole.
#include "cli_helpers.hpp"

#include "harness/io/results_csv.hpp"
#include "harness/io/series_csv.hpp"
#include "reports/granular_pictures.hpp"

#include <catch2/catch.hpp>
#include <set>

using namespace rotbench;
using namespace rotbench::test;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("granular pictures: a snapshot is one panel per instant with a circle per sphere, the farthest drawn first") {
    // Two instants; at the second, two spheres at different depths (y).
    const std::vector<std::vector<double>> rows = {{0.5, 0.0, 0.0, 0.0, 0.01}, {1.5, 0.0, 0.2, 0.0, 0.01}, {1.5, 0.05, -0.2, 0.1, 0.02}};
    const std::string svg = snapshot_svg("silo <&>", rows);
    CHECK(count(svg, "<circle") == 3);
    CHECK(count(svg, "<g>") == 2);
    CHECK(svg.find("t = 0.5 s") < svg.find("t = 1.5 s"));
    CHECK(svg.find("silo &lt;&amp;&gt;") != std::string::npos);  // the title is XML text
    // Within the second panel the far sphere (y = 0.2, lighter) comes before the near one.
    const std::size_t second = svg.find("t = 1.5 s");
    CHECK(svg.find("rgb(215,", second) < svg.find("rgb(95,", second));
}

TEST_CASE("granular pictures: the silo's curve and snapshots are written beside the report and come back whole") {
    const fs::path dir = fresh_dir("granular_pictures");
    // 0.06 s of a small silo, opened at 0.02 s: a curve of a few rows and pictures at three instants.
    const Cli r = cli({"run", "--scenes", "silo_discharge", "--schemes", "direct", "--quick", "--t-end", "0.06", "--set",
                       "silo_discharge.fill_time=0.02", "--set", "silo_discharge.clusters=20", "--out", dir.string(), "--quiet"});
    REQUIRE(r.status == 0);
    const std::string curve = read(dir / "series" / "curve_silo_discharge_direct_dt2e-05.csv");
    CHECK(curve.rfind("t_open,mass_left\n", 0) == 0);
    const std::string snapshots = read(dir / "snapshots" / "silo_discharge_direct_dt2e-05.csv");
    CHECK(snapshots.rfind("t,x,y,z,radius\n", 0) == 0);
    CHECK(fs::exists(dir / "plots" / "snapshot_silo_discharge_direct_dt2e-05.svg"));
    CHECK(read(dir / "report.md").find("(plots/snapshot_silo_discharge_direct_dt2e-05.svg)") != std::string::npos);
    const std::vector<RunResult> back = read_results(dir);
    REQUIRE(back.size() == 1);
    CHECK(series_csv(back.front()) == curve);
    CHECK(snapshot_csv(back.front()) == snapshots);
    // Three instants (the opening, halfway to the end, the end), each with every sphere.
    std::set<double> instants;
    for (const auto& row : back.front().snapshots) instants.insert(row.at(0));
    CHECK(instants.size() == 3);
    CHECK(back.front().snapshots.size() % 3 == 0);
    fs::remove_all(dir);
}
