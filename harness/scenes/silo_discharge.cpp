// `silo_discharge`: seed 000, test case 3 (after Chen et al., a test of the angle of repose of
// railway ballast) at laptop scale. A flat-bottomed square silo (side `width`) is filled by
// dropping `clusters` ballast stones from a lattice (their fall is part of the run, so every
// scheme fills its own silo from the same start); at t = `fill_time` a square orifice of side
// `orifice` opens at the centre of its bottom, and the stones fall onto a square table (side
// `table`) `drop` below it, where they form a heap; what rolls off the table falls to a floor
// `spill` below. A heap on a table of fixed size (the fixed-base method) stands at its angle of
// repose whatever the mass that reaches it, once the mass is enough to cover the table, where a
// heap on an open floor is as flat as the stream spreads it. Stones slide freely on the silo
// (friction 0) and grip the table, the floor and each other (0.6), as in seed Table 3. A sphere
// over the orifice meets its rim, and one beside the table its edge: sharp edges (no thickness).
//
// A flat-bottomed silo keeps stones in its corners (a wedge at the angle of repose on each
// side of the orifice), so the discharge ends with mass left. Metrics, from the mass left in
// the silo (the stones whose centre is above its bottom), sampled every millisecond:
//   discharge_time   s from the opening until `discharged` (0.95) of the mass that leaves by
//                    t_end has left; NaN unless the flow has stopped by then (less than 2 %
//                    of that mass left the silo in the run's last `stall` s: one or two
//                    stones of the 5 kg or so that leave; a stricter rule is voided by a single
//                    late stone), since it would then depend on t_end;
//   mass_flow_rate   kg/s, least-squares slope of the mass left while 20 % to 80 % of the mass
//                    that leaves has left;
//   repose_angle     degrees, of the heap on the table at t_end, as the seed measures it, at
//                    four places: along each of the directions +x, -x, +y, -y, in a strip one
//                    stone wide, the highest sphere top in bins one stone long, and the least-
//                    squares line through the bins from the highest one out to the last that
//                    is more than one stone high; the mean of the four angles. Only stones at
//                    rest (below 0.05 m/s) on the table count;
//   mass_left_end    kg left in the silo at t_end;
//   clogged          1 when the flow has stopped (as for discharge_time) with more than
//                    three quarters of the mass at the opening left in the silo: an arch over
//                    the orifice (a clean discharge leaves the corner wedges, 4-8 % of the
//                    fill at the default orifice, half of a 100-stone silo's thin layer; an
//                    arch more than nine tenths). Its discharge_time and mass_flow_rate (of the
//                    moments before the arch) are then NaN. 0 otherwise.
#include "harness/scenes/granular_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace rotbench {
namespace {

using Vec2 = Eigen::Vector2d;

// Least-squares slope of y against x.
double slope(const std::vector<std::pair<double, double>>& points) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& [x, y] : points) n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    const double d = n * sxx - sx * sx;
    return n >= 2 && d > 0.0 ? (n * sxy - sx * sy) / d : NAN;
}

class SiloDischarge final : public GranularScene {
public:
    SiloDischarge() {
        params.set("clusters", {1100});
        params.declare("width", {0.4}, "m", "inner side of the square silo");
        params.declare("orifice", {0.2}, "m", "side of the square orifice at the centre of the bottom (4 mean stone sizes)");
        params.declare("drop", {0.35}, "m",
                       "height of the silo's bottom above the table (room for the heap: it must not reach the orifice)");
        params.declare("wall_friction", {0.0}, "-", "friction coefficient with the silo (seed Table 3)");
        params.declare("floor_friction", {0.6}, "-", "friction coefficient with the table and the floor (seed Table 3)");
        params.declare("table", {0.7}, "m",
                       "side of the square table under the orifice the heap forms on; stones that roll off it fall to the floor");
        params.declare("spill", {0.3}, "m", "depth of the floor below the table");
        params.declare("fill_time", {2.0}, "s", "time the stones are given to settle before the orifice opens");
        params.declare("discharged", {0.95}, "-", "fraction of the mass that leaves whose leaving ends the discharge (discharge_time)");
        params.declare("stall", {0.2}, "s", "the flow has stopped when less than 2 % of the mass that leaves left in this long (discharge_time)");
        params.declare("t_end", {7.5}, "s", "duration, filling included");
    }

    void prepare() override {
        prepare_material();
        width_ = params.positive("width");
        orifice_ = params.positive("orifice");
        params.require(orifice_ < width_, "orifice", "must be smaller than the silo's width");
        drop_ = params.positive("drop");
        const double table = params.positive("table");
        const double spill = params.positive("spill");
        fill_time_ = params.number("fill_time");
        params.require(fill_time_ >= 0.0, "fill_time", "must not be negative");
        discharged_ = params.number("discharged");
        params.require(discharged_ > 0.0 && discharged_ <= 1.0, "discharged", "must lie in (0, 1]");
        stall_ = params.positive("stall");
        params.positive("t_end");  // a run that ends before the opening (the filling alone) has NaN metrics
        const double wall_friction = params.number("wall_friction"), floor_friction = params.number("floor_friction");
        params.require(wall_friction >= 0.0, "wall_friction", "must not be negative");
        params.require(floor_friction >= 0.0, "floor_friction", "must not be negative");
        // The walls act on spheres whose centre is above the bottom; the bottom is closed
        // until fill_time (place_walls opens it).
        Eigen::AlignedBox3d inside(Vec3(-INFINITY, -INFINITY, 0.0), Vec3::Constant(INFINITY));
        const double h = 0.5 * width_;
        for (const Vec3& n : std::vector<Vec3>{Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()})
            system_->walls.push_back({n, -h, wall_friction, Vec3::Zero(), inside, std::nullopt});
        // The bottom spans the silo's footprint only, so that a stone on the table beside the
        // silo is not under a shelf (and the pictures draw the silo as it is).
        system_->walls.push_back({Vec3::UnitZ(), 0.0, wall_friction, Vec3::Zero(), {Vec3(-h, -h, -INFINITY), Vec3(h, h, INFINITY)}, std::nullopt});
        const double t = 0.5 * table;
        const Eigen::AlignedBox3d table_top(Vec3(-t, -t, -INFINITY), Vec3(t, t, INFINITY));
        const Eigen::AlignedBox3d everywhere(Vec3::Constant(-INFINITY), Vec3::Constant(INFINITY));
        system_->walls.push_back({Vec3::UnitZ(), -drop_, floor_friction, Vec3::Zero(), table_top, std::nullopt, true});
        system_->walls.push_back({Vec3::UnitZ(), -drop_ - spill, floor_friction, Vec3::Zero(), everywhere, std::nullopt});
    }

    Bodies initial_state() const override {
        const double h = 0.5 * width_;
        return lattice_packing(Vec3(-h, -h, 0.0), Vec3(h, h, INFINITY));
    }
    // The bottom is closed until fill_time.
    std::optional<std::vector<double>> wall_changes() const override { return std::vector<double>{fill_time_}; }
    void place_walls(double t) const override {
        auto& bottom = system_->walls[bottom_wall];
        const double o = 0.5 * orifice_;
        if (t >= fill_time_) bottom.hole = Eigen::AlignedBox3d(Vec3(-o, -o, -INFINITY), Vec3(o, o, INFINITY));
        else bottom.hole.reset();
    }
    double observed_from() const override { return fill_time_; }

    std::vector<double> default_dts() const override { return {2e-5, 1e-5}; }
    // `--quick` keeps the whole silo (no quick_params): 100 stones made a heap too thin for an
    // angle of repose and a flow too short for Beverloo's law (docs/granular.md).
    std::vector<double> quick_dts() const override { return {2e-5}; }

    std::unique_ptr<SceneProbe> make_probe() const override { return std::make_unique<Probe>(*this); }

private:
    static constexpr std::size_t bottom_wall = 4;

    class Probe final : public SceneProbe {
    public:
        explicit Probe(const SiloDischarge& scene) : scene_(scene) {}
        void observe(double t, const Bodies& b) override {
            if (t < scene_.observed_from() || t < next_sample_) return;
            next_sample_ = t + 1e-3;  // the mass curve every millisecond
            double left = 0;
            for (std::size_t i = 0; i < b.size(); ++i)
                if (b.position[i].z() > 0.0) left += b.mass[i];
            curve_.emplace_back(t - scene_.fill_time_, left);
            last_ = b;  // the heap is measured on the last sample, at the end
            // Pictures: at the opening, halfway from it to the end, and (snapshots()) at the end.
            const double halfway = 0.5 * (scene_.fill_time_ + scene_.t_end());
            if (pictured_ == 0 || (pictured_ == 1 && t >= halfway)) scene_.add_snapshot(t, b, pictures_), ++pictured_;
        }
        // Every tenth sample (10 ms): enough for the picture, and the same times in every run of one dt.
        Curve curve() const override {
            Curve c{{"t_open", "mass_left"}, {}};
            for (std::size_t k = 0; k < curve_.size(); k += 10) c.rows.push_back({curve_[k].first, curve_[k].second});
            return c;
        }
        Snapshots snapshots() const override {
            Snapshots pictures = pictures_;
            if (!curve_.empty()) scene_.add_snapshot(curve_.back().first + scene_.fill_time_, last_, pictures);
            return pictures;
        }
        std::vector<std::pair<std::string, double>> metrics() const override {
            if (curve_.empty())
                return {{"discharge_time", NAN}, {"mass_flow_rate", NAN}, {"repose_angle", NAN}, {"mass_left_end", NAN}, {"clogged", NAN}};
            const double start = curve_.front().second, end = curve_.back().second, t_last = curve_.back().first;
            // The mass left `stall` s before the end, against that at the end.
            double before_end = start;
            for (const auto& [t, left] : curve_)
                if (t <= t_last - scene_.stall_) before_end = left;
            const bool stopped = t_last >= scene_.stall_ && before_end - end < 0.02 * (start - end);
            double discharge_time = NAN;
            std::vector<std::pair<double, double>> steady;
            for (const auto& [t, left] : curve_) {
                const double gone = start > end ? (start - left) / (start - end) : 0.0;  // of the mass that leaves
                if (stopped && std::isnan(discharge_time) && gone >= scene_.discharged_) discharge_time = t;
                if (gone >= 0.2 && gone <= 0.8) steady.emplace_back(t, left);
            }
            const bool clogged = stopped && end > 0.75 * start;
            return {{"discharge_time", clogged ? NAN : discharge_time},
                    {"mass_flow_rate", clogged ? NAN : -slope(steady)},
                    {"repose_angle", heap_angle(last_)},
                    {"mass_left_end", end},
                    {"clogged", clogged ? 1.0 : 0.0}};
        }

    private:
        double heap_angle(const Bodies& b) const {
            const double stone = 2.0 * scene_.largest_reach();
            const std::vector<Sphere> spheres = scene_.system_->world_spheres(b);
            const std::vector<int>& shape_of = scene_.system_->shape_of();
            double sum = 0;
            int directions = 0;
            for (const Vec2& along : {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)}) {
                std::map<long, double> top;  // bin along the direction -> highest sphere top above the floor
                std::size_t s = 0;
                for (std::size_t i = 0; i < b.size(); ++i) {
                    const std::size_t count = scene_.system_->shapes()[static_cast<std::size_t>(shape_of[i])].spheres.size();
                    const bool counts = b.position[i].z() < 0.0 && b.position[i].z() > -scene_.drop_ && b.velocity[i].norm() < 0.05;
                    for (std::size_t k = 0; k < count; ++k, ++s) {
                        if (!counts) continue;
                        const Vec2 xy(spheres[s].centre.x(), spheres[s].centre.y());
                        const double distance = xy.dot(along), across = std::abs(xy.x() * along.y() - xy.y() * along.x());
                        if (distance < 0.0 || across > 0.5 * stone) continue;
                        const long bin = static_cast<long>(distance / stone);
                        const double height = spheres[s].centre.z() + spheres[s].radius + scene_.drop_;
                        top[bin] = std::max(top.count(bin) ? top[bin] : 0.0, height);
                    }
                }
                if (top.empty()) continue;
                const auto peak = std::max_element(top.begin(), top.end(), [](auto& x, auto& y) { return x.second < y.second; });
                std::vector<std::pair<double, double>> flank;
                for (auto it = peak; it != top.end() && it->second > stone; ++it) flank.emplace_back((it->first + 0.5) * stone, it->second);
                const double a = std::atan(-slope(flank)) * 180.0 / std::numbers::pi;
                if (std::isfinite(a)) sum += a, ++directions;
            }
            return directions ? sum / directions : NAN;
        }

        const SiloDischarge& scene_;
        std::vector<std::pair<double, double>> curve_;  // time since opening, mass left
        double next_sample_ = 0;
        Bodies last_;
        Snapshots pictures_;  // at the opening and halfway
        int pictured_ = 0;
    };

    double width_ = 0, orifice_ = 0, drop_ = 0, fill_time_ = 0, discharged_ = 0, stall_ = 0;
};

const RegisterScene<SiloDischarge> registration(
    "silo_discharge",
    "a thousand ballast stones (clusters of 5-15 spheres) dropped into a square silo, then discharged through its orifice onto a table",
    "Irazabal et al., seed 000, section 3.2.1 (test case 3, after Chen et al.), Table 3 materials; at laptop scale",
    "Chaotic: a single run's difference between schemes means nothing until set against the scatter of an ensemble "
    "of packings (key seed).");

}  // namespace
}  // namespace rotbench
