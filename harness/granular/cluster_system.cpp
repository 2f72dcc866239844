#include "harness/granular/cluster_system.hpp"

#include "schemes/quaternion.hpp"

#include <algorithm>
#include <stdexcept>

namespace rotbench {

// The contact search drops a pair only when it is apart by this relative margin, far above
// round-off: every contact is kept, and the pairs keep their order (and the sums their rounding).
constexpr double pruning_margin = 1.0 + 1e-9;
// The near sphere pairs' skin, in the smallest sphere's radius: a thinner one is listed more
// often, a thicker one lists more pairs (docs/performance.md); the results do not depend on it.
constexpr double skin_of_radius = 0.5;

ClusterSystem::ClusterSystem(std::vector<ClusterShape> shapes, const ContactMaterial& material, double friction,
                             const Vec3& gravity)
    : shapes_(std::move(shapes)), law_(material), friction_(friction), gravity_(gravity) {
    if (shapes_.empty()) throw std::invalid_argument("ClusterSystem: no shapes");
    double smallest_radius = INFINITY;
    for (const ClusterShape& s : shapes_) {
        largest_reach_ = std::max(largest_reach_, s.reach);
        for (const Sphere& sphere : s.spheres) smallest_radius = std::min(smallest_radius, sphere.radius);
    }
    skin_ = skin_of_radius * smallest_radius;
}

Bodies ClusterSystem::make_bodies(const std::vector<int>& shape_of, const std::vector<Vec3>& positions,
                                  const std::vector<Quat>& orientations) {
    if (positions.size() != shape_of.size() || orientations.size() != shape_of.size())
        throw std::invalid_argument("ClusterSystem::make_bodies: one shape, position and orientation per body");
    shape_of_ = shape_of;
    first_sphere_.clear();
    reach_.clear();
    Bodies b;
    b.resize(shape_of.size());
    std::size_t spheres = 0;
    for (std::size_t i = 0; i < shape_of.size(); ++i) {
        const ClusterShape& shape = shapes_.at(static_cast<std::size_t>(shape_of[i]));
        b.mass[i] = shape.mass;
        b.inertia.set(i, shape.inertia);
        b.position.set(i, positions[i]);
        b.orientation.set(i, orientations[i]);
        first_sphere_.push_back(spheres);
        reach_.push_back(shape.reach);
        spheres += shape.spheres.size();
    }
    springs_.clear();
    near_pairs_ = NearSpherePairs{};
    last_time_ = NAN;
    return b;
}

std::vector<Sphere> ClusterSystem::world_spheres(const Bodies& b) const {
    std::vector<Sphere> out;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const Eigen::Matrix3d rotation = b.orientation[i].normalized().toRotationMatrix();
        const Vec3 x = b.position[i];
        for (const Sphere& s : shapes_[static_cast<std::size_t>(shape_of_[i])].spheres) out.push_back({x + rotation * s.centre, s.radius});
    }
    return out;
}

double ClusterSystem::potential_energy(const Bodies& b) const {
    double e = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) e -= b.mass[i] * gravity_.dot(b.position[i]);
    return e;
}

void ClusterSystem::evaluate(Bodies& b, double t) const {
    // The springs' clock: a steady step follows on; anything else (the first evaluation, a step
    // more than half as long again as the last, time going back) starts the springs afresh.
    double elapsed = t - last_time_;
    if (!(elapsed > 0.0) || (last_step_ > 0.0 && elapsed > 1.5 * last_step_)) {
        springs_.clear();
        elapsed = 0.0;
        last_step_ = 0.0;
    } else {
        last_step_ = elapsed;
    }
    last_time_ = t;

    centres_.clear();
    radii_.clear();
    owner_.clear();
    for (std::size_t i = 0; i < b.size(); ++i) {
        const Eigen::Matrix3d rotation = b.orientation[i].normalized().toRotationMatrix();
        const Vec3 x = b.position[i];
        for (const Sphere& s : shapes_[static_cast<std::size_t>(shape_of_[i])].spheres) {
            centres_.push_back(x + rotation * s.centre);
            radii_.push_back(s.radius);
            owner_.push_back(i);
        }
        b.force.set(i, b.mass[i] * gravity_);
        b.torque.set(i, Vec3::Zero());
    }
    wall_loads_.assign(walls.size(), Vec3::Zero());
    elastic_energy_ = 0.0;
    next_springs_.clear();

    const std::uint64_t sphere_count = centres_.size();
    auto point_velocity = [&](std::size_t body, const Vec3& point) -> Vec3 {  // Vec3: not an expression of temporaries
        return b.velocity[body] + b.omega[body].cross(point - b.position[body]);
    };
    auto apply = [&](std::size_t body, const Vec3& point, const Vec3& force) {
        b.force.set(body, b.force[body] + force);
        b.torque.set(body, b.torque[body] + (point - b.position[body]).cross(force));
    };

    // Two levels: stones whose bounding spheres overlap (linked cells over the stones' centres),
    // then their spheres that may touch (near_pairs_). A cell of the largest sphere's size would
    // hold dozens of the small ones, and a sphere-level search test ten times more pairs.
    positions_.resize(b.size());
    for (std::size_t i = 0; i < b.size(); ++i) positions_[i] = b.position[i];
    cells_.build(positions_, 2.0 * largest_reach_);
    if (near_pairs_.stale(centres_)) near_pairs_.build(centres_, radii_, positions_, first_sphere_, reach_, skin_);
    auto sphere_pair = [&](std::size_t i, std::size_t j) {
        const std::size_t a = std::min(i, j), c = std::max(i, j);  // the normal from the lower index
        const Vec3 d = centres_[c] - centres_[a];
        const double touch = radii_[a] + radii_[c];
        if (d.squaredNorm() > touch * touch * pruning_margin) return;  // apart, whatever the round-off: no square root
        const double distance = d.norm(), overlap = touch - distance;
        if (!(overlap > 0.0) || distance == 0.0) return;
        const Vec3 n = d / distance;
        const Vec3 point = centres_[a] + (radii_[a] - 0.5 * overlap) * n;
        const std::size_t body_a = owner_[a], body_c = owner_[c];
        const Vec3 v = point_velocity(body_c, point) - point_velocity(body_a, point);
        const double radius = radii_[a] * radii_[c] / (radii_[a] + radii_[c]);
        const double mass = b.mass[body_a] * b.mass[body_c] / (b.mass[body_a] + b.mass[body_c]);
        const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | c;
        Vec3 spring = springs_.find(key);
        const Vec3 f = law_.force(overlap, n, v, radius, mass, spring, elapsed, friction_);
        next_springs_.put(key, spring);
        apply(body_c, point, f);
        apply(body_a, point, -f);
        elastic_energy_ += law_.normal_energy(overlap, radius);
    };
    // The stones in the order of the cells, and the spheres of two stones in the order of
    // theirs: the sums' rounding does not depend on when the near pairs were listed.
    cells_.for_each_pair([&](std::size_t p, std::size_t q) {
        const double reach_p = reach_of(p), reach_q = reach_of(q);
        if ((positions_[p] - positions_[q]).squaredNorm() >= (reach_p + reach_q) * (reach_p + reach_q)) return;
        for (const auto& [i, j] : near_pairs_.pairs(p, q)) sphere_pair(i, j);
    });

    for (std::size_t body = 0, s = 0; body < b.size(); ++body) {
        // Only walls within the stone's reach of its centre can touch one of its spheres (a
        // margin far above round-off keeps every contact): most stones are near no wall.
        near_walls_.clear();
        for (std::size_t w = 0; w < walls.size(); ++w)
            if (!(std::abs(walls[w].normal.dot(b.position[body]) - walls[w].offset) > reach_of(body) * pruning_margin))
                near_walls_.push_back(w);
        for (const std::size_t end = s + sphere_count_of(body); s < end; ++s)
            for (const std::size_t w : near_walls_) {
                const Wall& wall = walls[w];
                const double height = wall.normal.dot(centres_[s]) - wall.offset;
                Vec3 n = wall.normal;
                double gap = height;
                if (!wall.region.contains(centres_[s])) {
                    if (!wall.plate) continue;
                    // Beside a plate: the sphere meets its edge, so that the force does not vanish
                    // at once as the sphere's centre passes the edge.
                    const Vec3 edge = (centres_[s] - height * wall.normal).cwiseMax(wall.region.min()).cwiseMin(wall.region.max());
                    const Vec3 d = centres_[s] - edge;
                    gap = d.norm();
                    if (!(gap > 0.0)) continue;
                    n = d / gap;
                } else if (wall.hole && wall.hole->contains(centres_[s])) {
                    // Over the opening: the sphere meets the opening's rim, at the rim point nearest
                    // its centre, so that the force is continuous as the sphere crosses the rim.
                    if (!(std::abs(height) < radii_[s])) continue;
                    Vec3 rim = centres_[s] - height * wall.normal;
                    int axis = 0;
                    double nearest = INFINITY, edge = 0;
                    for (int k = 0; k < 3; ++k) {
                        if (std::abs(wall.normal[k]) > 0.5) continue;  // the plane's own axis
                        for (const double bound : {wall.hole->min()[k], wall.hole->max()[k]})
                            if (std::abs(rim[k] - bound) < nearest) nearest = std::abs(rim[k] - bound), axis = k, edge = bound;
                    }
                    rim[axis] = edge;
                    const Vec3 d = centres_[s] - rim;
                    gap = d.norm();
                    if (!(gap > 0.0)) continue;
                    n = d / gap;
                } else if (!(height > 0.0)) {
                    continue;  // behind the wall
                }
                if (!(gap < radii_[s])) continue;
                const double overlap = radii_[s] - gap;
                const Vec3 point = centres_[s] - (radii_[s] - 0.5 * overlap) * n;
                const Vec3 v = point_velocity(body, point) - wall.velocity;
                const std::uint64_t key = (static_cast<std::uint64_t>(s) << 32) | (sphere_count + w);
                Vec3 spring = springs_.find(key);
                const Vec3 f = law_.force(overlap, n, v, radii_[s], b.mass[body], spring, elapsed, wall.friction);
                next_springs_.put(key, spring);
                apply(body, point, f);
                wall_loads_[w] -= f;
                elastic_energy_ += law_.normal_energy(overlap, radii_[s]);
            }
    }
    springs_.swap(next_springs_);
}

}  // namespace rotbench
