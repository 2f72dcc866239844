#include "harness/exec/granular_client.hpp"

#include "harness/exec/json_vec.hpp"
#include "harness/granular/wall_faces.hpp"
#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <sstream>
#include <nlohmann/json.hpp>

namespace rotbench {
namespace {

// Room around the walls and the stones where a client's stones may go: a stone that leaves
// it (far along the floor) is gone from later samples, as a DEM code deletes it.
constexpr double domain_margin = 1.0;

nlohmann::ordered_json box(const Eigen::AlignedBox3d& b) { return {json_vec(b.min()), json_vec(b.max())}; }

// The box the spheres fill.
Eigen::AlignedBox3d extent_of(const std::vector<Sphere>& spheres) {
    Eigen::AlignedBox3d extent;
    for (const Sphere& s : spheres) extent.extend(s.centre - Vec3::Constant(s.radius)).extend(s.centre + Vec3::Constant(s.radius));
    return extent;
}
// `extent`, grown to hold every finite coordinate of the walls (planes, regions, holes).
void extend_by_walls(Eigen::AlignedBox3d& extent, const std::vector<Wall>& walls) {
    const auto finite = [](const Vec3& v) { return v.unaryExpr([](double c) { return std::isfinite(c) ? c : 0.0; }); };
    for (const Wall& w : walls) {
        if (std::isfinite(w.offset)) extent.extend(w.normal * w.offset);
        for (const Eigen::AlignedBox3d& b : {w.region, w.hole.value_or(w.region)}) extent.extend(finite(b.min())).extend(finite(b.max()));
    }
}

using Sample = std::array<double, 16>;

// A sample's stones as bodies of their shapes (the cluster system takes their shapes), for the probe.
void set_stones(GranularScene& scene, const std::vector<Sample>& rows, Bodies& b) {
    std::vector<int> shapes;
    std::vector<Vec3> places;
    std::vector<Quat> orientations;
    for (const Sample& r : rows) {
        shapes.push_back(static_cast<int>(r[2]));
        places.emplace_back(r[3], r[4], r[5]);
        orientations.push_back(Quat(r[6], r[7], r[8], r[9]).normalized());
    }
    b = scene.system().make_bodies(shapes, places, orientations);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        b.velocity.set(i, Vec3(rows[i][10], rows[i][11], rows[i][12]));
        b.omega.set(i, Vec3(rows[i][13], rows[i][14], rows[i][15]));
    }
}

}  // namespace

SampleSteps granular_sample_steps(const GranularScene& scene, double dt) {
    const std::int64_t stride = std::max<std::int64_t>(1, std::llround(granular_sample_interval / dt));
    const auto from = static_cast<std::int64_t>(std::ceil(scene.observed_from() / dt * (1.0 - 1e-12)));
    return {(from + stride - 1) / stride * stride, stride};  // after `steps`: no samples (the run ends before the probe looks)
}

std::string granular_scene_json(const GranularScene& scene, const RunSpec& spec, double t_end, std::int64_t steps) {
    const auto changes = scene.wall_changes();
    if (!changes) throw InputError("scene '" + spec.scene + "' has walls that move with the stones: a client cannot take it as data");
    ClusterSystem& system = scene.system();
    const Bodies start = scene.initial_state();
    const Eigen::AlignedBox3d packing = extent_of(system.world_spheres(start));
    std::vector<double> times{0.0};
    for (double t : *changes)
        if (t > 0.0 && t < t_end) times.push_back(t);
    Eigen::AlignedBox3d extent = packing;
    for (double t : times) scene.place_walls(t), extend_by_walls(extent, system.walls);
    const Eigen::AlignedBox3d domain(extent.min() - Vec3::Constant(domain_margin), extent.max() + Vec3::Constant(domain_margin));
    nlohmann::ordered_json stages = nlohmann::ordered_json::array();
    for (double t : times) {
        scene.place_walls(t);
        nlohmann::ordered_json faces = nlohmann::ordered_json::array();
        for (const WallFace& f : wall_faces(system.walls, domain))
            faces.push_back({{"normal", json_vec(f.normal)},
                             {"friction", f.friction},
                             {"corners", {json_vec(f.corners[0]), json_vec(f.corners[1]), json_vec(f.corners[2]), json_vec(f.corners[3])}}});
        stages.push_back({{"from", t}, {"faces", faces}});
    }
    scene.place_walls(0.0);
    nlohmann::ordered_json shapes = nlohmann::ordered_json::array();
    for (const ClusterShape& s : system.shapes()) {
        nlohmann::ordered_json spheres = nlohmann::ordered_json::array();
        for (const Sphere& sphere : s.spheres) spheres.push_back({sphere.centre.x(), sphere.centre.y(), sphere.centre.z(), sphere.radius});
        shapes.push_back({{"mass", s.mass}, {"inertia_body", json_vec(s.inertia)}, {"spheres", spheres}});
    }
    const ContactMaterial& m = scene.material();
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (const auto& [key, values] : spec.params) params[key] = values;
    const SampleSteps samples = granular_sample_steps(scene, spec.dt);
    const nlohmann::ordered_json j = {{"format", "rotbench-granular-scene 1"},
                              {"scene", spec.scene},
                              {"gravity", json_vec(scene.gravity())},
                              {"material",
                               {{"density", scene.params.number("density")},
                                {"young", m.young},
                                {"poisson", m.poisson},
                                {"restitution", m.restitution},
                                {"friction", scene.friction()}}},
                              {"shapes", shapes},
                              {"stones",
                               {{"count", start.size()},
                                {"spheres", system.world_spheres(start).size()},
                                {"seed", static_cast<std::uint64_t>(scene.params.number("seed"))},
                                {"box", box(packing)}}},
                              {"domain", box(domain)},
                              {"walls", stages},
                              {"dt", spec.dt},
                              {"t_end", t_end},
                              {"steps", steps},
                              {"sample_first", samples.first},
                              {"sample_stride", samples.stride},
                              {"columns", granular_samples_header},
                              {"params", params}};  // last: the user's keys after the scene's own
    return j.dump(2) + "\n";
}

RunResult replay_granular_samples(const RunSpec& spec, GranularScene& scene, const std::filesystem::path& file, std::int64_t steps) {
    RunResult result{spec, {}, {}};
    const auto fail = [&](const std::string& why) {
        result.failure = why;
        result.metrics = {{metric::unstable, 1.0}};
        return result;
    };
    const std::string name = "its samples.csv";
    const SampleSteps due = granular_sample_steps(scene, spec.dt);
    const std::size_t count = scene.initial_state().size(), shapes = scene.system().shapes().size();
    const std::int64_t last = due.first <= steps ? due.first + (steps - due.first) / due.stride * due.stride : due.first - due.stride;
    // Never more than every stone in every sample at 64 bytes a number.
    const double most_bytes = 64.0 * 16.0 * static_cast<double>(count) * static_cast<double>((last - due.first) / due.stride + 1) + 4096.0;
    std::string text;
    if (const std::string why = read_program_output(file, name, most_bytes, "every stone in every sample", text); !why.empty()) return fail(why);
    std::istringstream in(text);
    const auto probe = scene.make_probe();
    std::string line;
    if (!std::getline(in, line) || line != granular_samples_header)
        return fail(fmt::format("{}:1: the header must be {}", name, granular_samples_header));
    std::int64_t step = due.first;  // the sample being read
    std::vector<Sample> rows;
    std::vector<bool> seen(count);
    Bodies b;
    const auto end_sample = [&] {
        const double t = static_cast<double>(step) * spec.dt;
        set_stones(scene, rows, b);
        scene.place_walls(t);  // as the probe's pictures show them
        probe->observe(t, b);
        rows.clear();
        std::fill(seen.begin(), seen.end(), false);
        step += due.stride;
    };
    try {
        for (std::size_t n = 2; std::getline(in, line); ++n) {
            if (in.eof()) return fail(fmt::format("{}:{}: the last line is cut short (no line break)", name, n));
            const std::string at = fmt::format("{}:{}", name, n);
            const bool alone = line.find(',') == std::string::npos;  // the time alone: a sample with no stone left
            Sample r;
            std::size_t c = 0, pos = 0;
            for (; c < (alone ? 1 : r.size()) && pos <= line.size(); ++c) {
                const std::size_t comma = std::min(line.find(',', pos), line.size());
                r[c] = csv_number(line.substr(pos, comma - pos), at);
                if (!std::isfinite(r[c])) return fail(fmt::format("{}: a value that is not finite", at));
                pos = comma + 1;
            }
            if ((!alone && c != r.size()) || pos != line.size() + 1) return fail(fmt::format("{}: {} fields are due", at, r.size()));
            // A row of the next sample ends this one.
            const double t = static_cast<double>(step) * spec.dt;
            if (!rows.empty() && std::abs(r[0] - t) > 1e-9 * std::max(1.0, t)) end_sample();
            if (step > last) return fail(fmt::format("{}: a sample after the last one due (step {})", at, last));
            const double due_t = static_cast<double>(step) * spec.dt;
            if (std::abs(r[0] - due_t) > 1e-9 * std::max(1.0, due_t))
                return fail(fmt::format("{}: t = {} where the next sample is due at step {} (t = {})", at, r[0], step, due_t));
            if (alone && !rows.empty()) return fail(fmt::format("{}: the time alone of a sample that has stones", at));
            if (alone) {
                end_sample();
                continue;
            }
            const double stone = r[1], shape = r[2];
            if (stone < 0 || stone >= static_cast<double>(count) || stone != std::floor(stone) || seen[static_cast<std::size_t>(stone)])
                return fail(fmt::format("{}: stone {} is not one of 0 ... {} once in its sample", at, stone, count - 1));
            if (shape < 0 || shape >= static_cast<double>(shapes) || shape != std::floor(shape))
                return fail(fmt::format("{}: shape {} is not one of 0 ... {}", at, shape, shapes - 1));
            seen[static_cast<std::size_t>(stone)] = true;
            rows.push_back(r);
        }
    } catch (const InputError& e) {
        return fail(std::string("its samples are malformed: ") + e.what());
    }
    if (!rows.empty()) end_sample();
    if (step != last + due.stride)
        return fail(fmt::format("{} stops before step {}; samples are due every {} steps from step {} to step {}", name, step, due.stride,
                                due.first, last));
    result.metrics = probe->metrics();
    add_probe_pictures(*probe, result);
    return result;
}

}  // namespace rotbench
