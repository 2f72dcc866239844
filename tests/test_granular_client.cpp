// A client on a granular scene (docs/clients.md, "Granular scenes"): rotbench describes the silo
// as data, and judges the stones the program hands back with the scene's own probe. The program
// of these tests hands back a file the test wrote from a built-in run, whole or spoiled.
#include "cli_helpers.hpp"
#include "harness/exec/executor.hpp"
#include "harness/exec/granular_client.hpp"
#include "harness/exec/run.hpp"
#include "harness/granular/wall_faces.hpp"
#include "harness/store/client.hpp"
#include "schemes/registry.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace rotbench;
using namespace rotbench::test;

namespace {

// A brief silo: 60 stones, opened at 0.4 s, run to 1.2 s.
const ParamOverrides brief_silo = {{"clusters", {60}}, {"fill_time", {0.4}}, {"t_end", {1.2}}};
constexpr double silo_dt = 2e-5;

double area(const WallFace& f) { return (f.corners[1] - f.corners[0]).cross(f.corners[3] - f.corners[0]).norm(); }

// A built-in run of the brief silo, as the samples a client writes, and the metrics its states
// at those samples give the scene's probe.
struct SampledRun {
    std::string csv = std::string(granular_samples_header) + "\n";
    std::vector<std::pair<std::string, double>> metrics;
    std::vector<Sphere> last_spheres;  // of every stone at the last sample, as a picture draws them
};
SampledRun sampled_run() {
    const auto made = make_scene("silo_discharge", brief_silo);
    auto& scene = dynamic_cast<GranularScene&>(*made);
    const std::int64_t steps = step_count(scene.t_end(), silo_dt);
    const SampleSteps due = granular_sample_steps(scene, silo_dt);
    const auto probe = scene.make_probe();
    auto scheme = SchemeRegistry::instance().at("richardson", "scheme").make();
    Bodies b = scene.initial_state();
    std::int64_t evals = 0;
    SampledRun run;
    simulate(scene, *scheme, b, silo_dt, steps, evals, [&](std::int64_t n, double t, const Bodies& state) {
        if (n < due.first || (n - due.first) % due.stride != 0) return true;
        for (std::size_t i = 0; i < state.size(); ++i) {
            const Vec3 x = state.position[i], v = state.velocity[i], w = state.omega[i];
            const Quat q = state.orientation[i];
            run.csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", static_cast<double>(n) * silo_dt, i,
                                   scene.system().shape_of()[i], x.x(), x.y(), x.z(), q.w(), q.x(), q.y(), q.z(), v.x(), v.y(), v.z(),
                                   w.x(), w.y(), w.z());
        }
        Bodies fresh = state;  // as the replay sees it: orientations normalised
        for (std::size_t i = 0; i < fresh.size(); ++i) fresh.orientation.set(i, state.orientation[i].normalized());
        probe->observe(t, fresh);
        run.last_spheres = scene.system().world_spheres(fresh);
        return true;
    });
    run.metrics = probe->metrics();
    return run;
}

// A client whose program copies `samples` to where rotbench asks for them.
std::string copying_client(const fs::path& dir, const std::string& id, const fs::path& samples) {
    const fs::path file = dir / (id + ".toml");
    write(file, "id = \"" + id + "\"\nprogram = [\"python3\", \"-c\", \"import shutil, sys; shutil.copy(sys.argv[1], sys.argv[3])\", \"" +
                    samples.string() + "\"]\nscenes = [\"silo_discharge\", \"direct_shear\"]\nclaims = \"richardson\"\n");
    return load_client(file.string());
}

}  // namespace

TEST_CASE("granular client: the walls as rectangles cover each wall's region, less its hole, facing the stones") {
    Wall floor;  // z = 0, over [-1, 1]^2, a hole [-0.2, 0.3] x [-0.1, 0.1]
    floor.region = Eigen::AlignedBox3d(Vec3(-1, -1, -INFINITY), Vec3(1, 1, INFINITY));
    floor.hole = Eigen::AlignedBox3d(Vec3(-0.2, -0.1, -INFINITY), Vec3(0.3, 0.1, INFINITY));
    Wall side;  // x = 0.5 facing -x, above z = 0, unbounded in y: clipped to the domain
    side.normal = -Vec3::UnitX(), side.offset = -0.5, side.friction = 0.3;
    side.region = Eigen::AlignedBox3d(Vec3(-INFINITY, -INFINITY, 0.0), Vec3::Constant(INFINITY));
    Wall lid;  // not laid yet
    lid.normal = -Vec3::UnitZ(), lid.offset = INFINITY;
    const Eigen::AlignedBox3d domain(Vec3(-2, -2, -1), Vec3(2, 2, 3));
    const std::vector<WallFace> faces = wall_faces({floor, side, lid}, domain);
    REQUIRE(faces.size() == 5);  // four around the hole, one side, no lid
    double floor_area = 0;
    for (const WallFace& f : faces) {
        // Counter-clockwise seen from the side the normal points to, flat in the wall's plane.
        CHECK((f.corners[1] - f.corners[0]).cross(f.corners[2] - f.corners[1]).normalized().isApprox(f.normal, 1e-15));
        for (const Vec3& c : f.corners) CHECK(c.dot(f.normal) == (f.normal.z() > 0 ? 0.0 : -0.5));
        if (f.normal.z() > 0) floor_area += area(f);
    }
    CHECK(floor_area == Approx(4.0 - 0.5 * 0.2).epsilon(1e-15));    // round-off
    CHECK(area(faces.back()) == Approx(4.0 * 3.0).epsilon(1e-15));  // y over the domain's 4 m, z from 0 to 3 m
    CHECK(faces.back().friction == 0.3);
    Wall tilted;
    tilted.normal = Vec3(1, 1, 0).normalized();
    CHECK_THROWS_AS(wall_faces({tilted}, domain), std::invalid_argument);
}

TEST_CASE("granular client: the silo's spec holds rotbench's stones, material, packing and walls before and after the opening") {
    const auto made_scene = make_scene("silo_discharge", brief_silo);
    auto& scene = dynamic_cast<GranularScene&>(*made_scene);
    const std::int64_t steps = step_count(scene.t_end(), silo_dt);
    const auto spec =
        nlohmann::json::parse(granular_scene_json(scene, {"silo_discharge", "x", silo_dt, 0.0, brief_silo}, scene.t_end(), steps));
    CHECK(spec["format"] == "rotbench-granular-scene 1");
    REQUIRE(spec["shapes"].size() == scene.system().shapes().size());
    for (std::size_t k = 0; k < spec["shapes"].size(); ++k) {
        const ClusterShape& shape = scene.system().shapes()[k];
        CHECK(spec["shapes"][k]["mass"].get<double>() == shape.mass);
        CHECK(spec["shapes"][k]["inertia_body"][2].get<double>() == shape.inertia.z());
        CHECK(spec["shapes"][k]["spheres"].size() == shape.spheres.size());
    }
    CHECK(spec["material"]["restitution"].get<double>() == 0.0);  // seed Table 3
    CHECK(spec["material"]["friction"].get<double>() == 0.6);
    CHECK(spec["stones"]["count"].get<int>() == 60);
    // Two stages: closed until fill_time, then the bottom is four faces around the orifice.
    REQUIRE(spec["walls"].size() == 2);
    CHECK(spec["walls"][1]["from"].get<double>() == 0.4);
    const auto bottom_area = [&](const nlohmann::json& stage) {
        double a = 0;
        for (const auto& f : stage["faces"]) {
            const Vec3 c0(f["corners"][0][0], f["corners"][0][1], f["corners"][0][2]),
                c1(f["corners"][1][0], f["corners"][1][1], f["corners"][1][2]),
                c3(f["corners"][3][0], f["corners"][3][1], f["corners"][3][2]);
            if (c0.z() == 0.0 && f["normal"][2].get<double>() == 1.0) a += (c1 - c0).cross(c3 - c0).norm();
        }
        return a;
    };
    CHECK(bottom_area(spec["walls"][0]) == Approx(0.4 * 0.4).epsilon(1e-15));
    CHECK(bottom_area(spec["walls"][1]) == Approx(0.4 * 0.4 - 0.2 * 0.2).epsilon(1e-15));
    // Samples every 10 ms from the opening: 20 000 steps in, every 500.
    CHECK(spec["sample_first"].get<int>() == 20000);
    CHECK(spec["sample_stride"].get<int>() == 500);
    // A scene whose walls follow the stones (the shear box's lid) is refused.
    const auto shear = make_scene("direct_shear", {});
    CHECK_THROWS_AS(granular_scene_json(dynamic_cast<GranularScene&>(*shear), {"direct_shear", "x", silo_dt, 0.0}, 1.0, 50000), InputError);
}

TEST_CASE("granular client: stones handed back at the sample times give the probe's metrics bit for bit, and spoiled ones fail the run") {
    const fs::path dir = fresh_dir("granular_client");
    fs::create_directories(dir);
    const SampledRun run = sampled_run();
    const fs::path good = dir / "good.csv";
    write(good, run.csv);
    const std::string id = copying_client(dir, "copying_good", good);
    const RunResult r = made({"silo_discharge", id, silo_dt, 0.0, brief_silo});
    INFO(r.failure);
    REQUIRE(r.failure.empty());
    REQUIRE(run.metrics.size() == 5);
    for (const auto& [name, value] : run.metrics) {
        INFO(name << " " << value << " " << r.value(name));
        CHECK((r.value(name) == value || (std::isnan(value) && std::isnan(r.value(name)))));
    }
    CHECK(std::isfinite(r.value("mass_left_end")));
    CHECK(!r.series.empty());  // the mass curve
    // The report's cost figure for a client: its program's CPU time per simulated second.
    CHECK(r.value(metric::client_cpu_seconds_per_simulated_second) == r.value(metric::client_cpu_seconds) / r.spec.t_end);
    // The last picture: every sphere where the stone's shape, place and orientation put it.
    REQUIRE(r.snapshots.size() >= run.last_spheres.size());
    const std::size_t last = r.snapshots.size() - run.last_spheres.size();
    CHECK(r.snapshots[last][0] == Approx(1.2).epsilon(1e-12));
    for (std::size_t s = 0; s < run.last_spheres.size(); ++s) {
        const Sphere& sphere = run.last_spheres[s];
        CHECK(std::vector<double>(r.snapshots[last + s].begin() + 1, r.snapshots[last + s].end()) ==
              std::vector<double>{sphere.centre.x(), sphere.centre.y(), sphere.centre.z(), sphere.radius});
    }

    // Spoiled copies: each a failed run saying why.
    const std::size_t header = run.csv.find('\n') + 1, second = run.csv.find('\n', header) + 1;
    const std::string first_row = run.csv.substr(header, second - header);
    const std::vector<std::pair<std::string, std::string>> spoiled = {
        {"t,stone\n", "its samples.csv:1: the header must be"},
        {run.csv.substr(0, run.csv.size() - 1), "the last line is cut short"},
        {run.csv.substr(0, run.csv.find("\n" + fmt::format("{},", 60000 * silo_dt)) + 1), "stops before step 60000"},
        {run.csv.substr(0, header) + first_row + run.csv.substr(header),
         "its samples.csv:3: stone 0 is not one of 0 ... 59 once in its sample"},
        {run.csv.substr(0, header) + "0.4," + first_row.substr(first_row.find(',') + 1) + run.csv.substr(second), ""},
        {run.csv.substr(0, header) + "0.41," + first_row.substr(first_row.find(',') + 1) + run.csv.substr(second),
         "its samples.csv:2: t = 0.41 where the next sample is due at step 20000"},
        {run.csv.substr(0, header) + first_row.substr(0, first_row.size() - 1) + ",1\n" + run.csv.substr(second),
         "its samples.csv:2: 16 fields are due"},
        {run.csv.substr(0, header) + "0.4,0,9" + first_row.substr(first_row.find(',', first_row.find(',', first_row.find(',') + 1) + 1)) +
             run.csv.substr(second),
         "its samples.csv:2: shape 9 is not one of 0 ... 5"},
        {run.csv.substr(0, header) + "0.4,0,0,nan" +
             first_row.substr(first_row.find(',', first_row.find(',', first_row.find(',', first_row.find(',') + 1) + 1) + 1)) +
             run.csv.substr(second),
         "its samples.csv:2: a value that is not finite"},
        {run.csv + std::string(64 * 16 * 60 * 81, '0') + "\n", "is larger than every stone in every sample can make it"},
    };
    int n = 0;
    for (const auto& [text, message] : spoiled) {
        const fs::path file = dir / fmt::format("spoiled{}.csv", n);
        write(file, text);
        const RunResult bad = made({"silo_discharge", copying_client(dir, fmt::format("copying_{}", n++), file), silo_dt, 0.0, brief_silo});
        INFO(n << ": " << bad.failure);
        if (message.empty()) {  // the same sample, its time written otherwise: no failure
            CHECK(bad.failure.empty());
            continue;
        }
        CHECK_THAT(bad.failure, Catch::Contains(message));
        CHECK(bad.value(metric::unstable) == 1.0);
    }
    // A samples.csv that is a FIFO (no writer will come): refused, not waited on.
    const fs::path fifo_file = dir / "fifo_client.toml";
    write(fifo_file, "id = \"fifo_client\"\nprogram = [\"python3\", \"-c\", \"import os, sys; os.mkfifo(sys.argv[2])\"]\n"
                     "scenes = [\"silo_discharge\"]\nclaims = \"richardson\"\n");
    const RunResult fifo = made({"silo_discharge", load_client(fifo_file.string()), silo_dt, 0.0, brief_silo});
    CHECK_THAT(fifo.failure, Catch::Contains("its samples.csv is not a regular file"));
    // The shear box's walls follow its stones: a client cannot take it.
    CHECK_THAT(made({"direct_shear", id, silo_dt, 0.0, {{"clusters", {20}}}}).failure, Catch::Contains("walls that move with the stones"));
    fs::remove_all(dir);
}

TEST_CASE("granular client: a sample with no stone left is its time alone, which must be the time due") {
    const fs::path dir = fresh_dir("granular_client_empty");
    fs::create_directories(dir);
    const SampledRun run = sampled_run();
    // The last sample's rows replaced by its time alone: every stone gone by then.
    const std::size_t last_row = run.csv.rfind('\n', run.csv.size() - 2) + 1;
    const std::string last_t = run.csv.substr(last_row, run.csv.find(',', last_row) - last_row);
    const std::size_t first_of_last = run.csv.find("\n" + last_t + ",") + 1;
    const std::string emptied = run.csv.substr(0, first_of_last) + last_t + "\n";
    const auto replayed = [&](const std::string& text, const std::string& id) {
        write(dir / (id + ".csv"), text);
        return made({"silo_discharge", copying_client(dir, id, dir / (id + ".csv")), silo_dt, 0.0, brief_silo});
    };
    const RunResult r = replayed(emptied, "copying_emptied");
    INFO(r.failure);
    CHECK(r.failure.empty());
    CHECK(r.value("mass_left_end") == 0.0);
    // The same sample left out altogether: the samples stop short, as before.
    CHECK_THAT(replayed(run.csv.substr(0, first_of_last), "copying_cut").failure, Catch::Contains("stops before step"));
    // Its time alone after rows of the same sample.
    CHECK_THAT(replayed(run.csv + last_t + "\n", "copying_both").failure, Catch::Contains("the time alone of a sample that has stones"));
    // Its time alone at another time than the one due.
    CHECK_THAT(replayed(run.csv.substr(0, first_of_last) + "0.123\n", "copying_wrong_time").failure,
               Catch::Contains("t = 0.123 where the next sample is due"));
    fs::remove_all(dir);
}

TEST_CASE("granular client: LIGGGHTS runs rotbench's small silo from its spec, and refuses the seed's restitution of 0", "[slow]") {
    const std::string id = load_client(std::string(ROTBENCH_SOURCE_DIR) + "/examples/clients/liggghts/multisphere.toml");
    // LIGGGHTS 3.8.0 takes no restitution at or below 0.05: the adapter declines the run before it starts.
    const RunResult declined = made({"silo_discharge", id, silo_dt, 0.0, brief_silo});
    CHECK_THAT(declined.failure, Catch::Contains("LIGGGHTS 3.8.0 refuses a restitution coefficient at or below 0.05"));
    CHECK(declined.value(metric::declined) == 1.0);
    ParamOverrides small = small_silo();
    small.push_back({"restitution", {0.051}});
    const RunResult r = made({"silo_discharge", id, silo_dt, 0.0, small});
    INFO(r.failure);
    REQUIRE(r.failure.empty());
    // Every stone inserted and sampled (the adapter checks both); stones left the silo at a rate.
    const double start = r.series.front()[1], end = r.value("mass_left_end");
    CHECK(start > 0.0);
    CHECK(end < 0.9 * start);
    CHECK(r.value("mass_flow_rate") > 0.0);
    // The adapter imports its granular half: no bytecode cache left beside it.
    CHECK(!fs::exists(fs::path(ROTBENCH_SOURCE_DIR) / "examples/clients/liggghts/__pycache__"));
}
