// The granular scenes' pictures (reports/granular_pictures.hpp): the snapshot SVG, and the
// curves and snapshots written beside the report and read back whole.
#include "cli_helpers.hpp"

#include "harness/granular/wall_outline.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/store/run_record.hpp"
#include "harness/store/series_csv.hpp"
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
    CHECK(count(svg, "<g stroke=\"#333\"") == 2);  // a group of circles per instant
    CHECK(svg.find("t = 0.5 s") < svg.find("t = 1.5 s"));
    CHECK(svg.find("silo &lt;&amp;&gt;") != std::string::npos);  // the title is XML text
    // Within the second panel the far sphere (y = 0.2, lighter) comes before the near one.
    const std::size_t second = svg.find("t = 1.5 s");
    CHECK(svg.find("rgb(215,", second) < svg.find("rgb(95,", second));
}

TEST_CASE("granular pictures: walls facing x or z are segments within the frame, cut by their hole, absent outside their region") {
    const Vec3 all = Vec3::Constant(INFINITY);
    const auto wall = [&](const Vec3& n, double offset, const Eigen::AlignedBox3d& region) { return Wall{n, offset, 0.0, Vec3::Zero(), region, std::nullopt}; };
    std::vector<Wall> walls = {
        wall(Vec3::UnitX(), -0.2, {Vec3(-INFINITY, -INFINITY, 0.0), all}),     // x = -0.2, above z = 0
        wall(-Vec3::UnitX(), -0.2, {Vec3(-INFINITY, -INFINITY, 0.0), all}),    // x = +0.2
        wall(Vec3::UnitY(), -0.2, {-all, all}),                                // in the picture's plane
        wall(Vec3::UnitZ(), 0.0, {Vec3(-0.2, -0.2, -INFINITY), Vec3(0.2, 0.2, INFINITY)}),  // the bottom
        wall(Vec3::UnitZ(), -0.5, {-all, all}),                                // the floor
        wall(-Vec3::UnitZ(), -INFINITY, {-all, all}),                          // a lid not yet laid
        wall(Vec3::UnitX(), -0.2, {-all, -all}),                               // outside its own region
    };
    walls[3].hole = Eigen::AlignedBox3d(Vec3(-0.05, -0.05, -INFINITY), Vec3(0.05, 0.05, INFINITY));
    // Two stones (sums of binary fractions, exact): one in the silo, one on the floor beside it.
    const std::vector<Sphere> spheres = {{Vec3(0.0, 0.0, 0.125), 0.0625}, {Vec3(0.25, 0.1, -0.375), 0.125}};
    const Eigen::AlignedBox2d frame = picture_frame(spheres, walls);
    CHECK(frame.min() == Eigen::Vector2d(-0.2, -0.5));     // the left wall, the floor
    CHECK(frame.max() == Eigen::Vector2d(0.375, 0.1875));  // the stone beside the silo, the highest stone
    using Segments = std::vector<std::array<double, 4>>;
    CHECK(wall_segments(walls, frame) == Segments{{-0.2, 0.0, -0.2, 0.1875},  // the walls from the bottom to the highest stone
                                                  {0.2, 0.0, 0.2, 0.1875},
                                                  {-0.2, 0.0, -0.05, 0.0},    // the bottom, on each side of its hole
                                                  {0.05, 0.0, 0.2, 0.0},
                                                  {-0.2, -0.5, 0.375, -0.5}}); // the floor across the frame
}

TEST_CASE("granular pictures: a snapshot draws each instant's walls over its stones, on the stones' scale") {
    const std::vector<std::vector<double>> rows = {{0.5, 0.0, 0.0, 0.1, 0.01}, {1.5, 0.0, 0.0, 0.1, 0.01}};
    // At 0.5 s a wall reaching beyond the stones (the scale takes it in); at 1.5 s two; at 2.5 s,
    // an instant without stones, none is drawn.
    const std::vector<std::vector<double>> walls = {
        {0.5, -1.0, 0.0, 1.0, 0.0}, {1.5, -1.0, 0.0, 1.0, 0.0}, {1.5, -1.0, 0.0, -1.0, 0.2}, {2.5, 0.0, 0.0, 0.0, 5.0}};
    const std::string svg = snapshot_svg("silo", rows, walls);
    CHECK(count(svg, "<line") == 3);
    CHECK(count(svg, "<circle") == 2);
    CHECK(svg.find("<line", svg.find("t = 1.5 s")) > svg.find("<circle", svg.find("t = 1.5 s")));  // over the stones
    // The tallest extent, 0.2 m (the wall at 1.5 s), is 360 px: the sphere's radius of 0.01 m is 18 px.
    CHECK(svg.find("r=\"18.0\"") != std::string::npos);
    // Records carry the walls: a run handed back by a worker or kept in the journal has them.
    RunResult r;
    r.spec = {"silo_discharge", "direct", 2e-5, 0.06};
    r.metrics = {{"mass_left_end", 1.0}};
    r.snapshots = rows;
    r.walls = walls;
    const RunRecords back = parse_run_records(run_record(7, r), "record");
    REQUIRE(back.runs.size() == 1);
    CHECK(back.runs.front().second.snapshots == rows);
    CHECK(back.runs.front().second.walls == walls);
}

TEST_CASE("granular pictures: the silo's curve and snapshots are written beside the report and come back whole") {
    const fs::path dir = fresh_dir("granular_pictures");
    // 0.06 s of a small silo, opened at 0.02 s: a curve of a few rows and pictures at three instants.
    const Cli r = cli({"run", "--scenes", "silo_discharge", "--schemes", "direct", "--quick", "--t-end", "0.06", "--set",
                       "silo_discharge.fill_time=0.02", "--set", "silo_discharge.clusters=20", "--set", "silo_discharge.orifice=0.25",
                       "--out", dir.string(), "--quiet"});
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
    const std::string walls = read(dir / "walls" / "silo_discharge_direct_dt2e-05.csv");
    CHECK(walls.rfind("t,x0,z0,x1,z1\n", 0) == 0);
    CHECK(walls_csv(back.front()) == walls);
    // At each instant the bottom (z = 0) runs from the silo's sides (+-0.2 m) to the orifice's
    // rim (+-0.125 m), once the orifice is open: the first instant is the opening itself.
    std::set<double> instants;
    std::map<double, std::set<std::pair<double, double>>> bottom;
    for (const auto& row : back.front().snapshots) instants.insert(row.at(0));
    for (const auto& w : back.front().walls)
        if (w.at(2) == 0.0 && w.at(4) == 0.0) bottom[w.at(0)].insert({w.at(1), w.at(3)});
    for (const double t : instants) {
        INFO("t = " << t);
        CHECK(bottom[t] == std::set<std::pair<double, double>>{{-0.2, -0.125}, {0.125, 0.2}});
    }
    // Three instants (the opening, halfway to the end, the end), each with every sphere.
    CHECK(instants.size() == 3);
    CHECK(back.front().snapshots.size() % 3 == 0);
    fs::remove_all(dir);
}
