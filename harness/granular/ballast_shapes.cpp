#include "harness/granular/ballast_shapes.hpp"

#include "harness/granular/random_stream.hpp"

#include <algorithm>
#include <stdexcept>

namespace rotbench {

ClusterShape cluster_shape(const std::vector<Sphere>& spheres, double density) {
    const MassProperties p = union_mass_properties(spheres, density);
    ClusterShape shape;
    shape.mass = p.mass;
    shape.inertia = p.principal;
    double lo = INFINITY, hi = -INFINITY;
    for (const Sphere& s : spheres) {
        const Vec3 c = p.axes.transpose() * (s.centre - p.centre);
        shape.spheres.push_back({c, s.radius});
        lo = std::min(lo, c.x() - s.radius);
        hi = std::max(hi, c.x() + s.radius);
        shape.reach = std::max(shape.reach, c.norm() + s.radius);
    }
    shape.size = hi - lo;
    return shape;
}

namespace {

// A stone grown sphere by sphere: each new sphere overlaps one already placed, in a direction
// squashed into a flattened ellipsoid (semi-axes 1 : b : c), and is kept inside it, so the
// stones are elongated and flat like ballast rather than round. Lengths in units of the long
// semi-axis; the caller scales them.
std::vector<Sphere> grow_stone(std::uint64_t seed, int count) {
    RandomStream random(seed);
    const double b = random.uniform(0.6, 0.85), c = random.uniform(0.4, 0.65);
    auto inside = [&](const Vec3& x, double r) {
        const Vec3 e(x.x(), x.y() / b, x.z() / c);
        return e.norm() + r <= 1.0;
    };
    std::vector<Sphere> spheres{{Vec3::Zero(), random.uniform(0.3, 0.4)}};
    for (int attempt = 0; static_cast<int>(spheres.size()) < count; ++attempt) {
        if (attempt == 100000) throw std::logic_error("grow_stone: no room for another sphere");
        const Sphere& parent = spheres[random.index(spheres.size())];
        const double r = random.uniform(0.2, 0.4);
        const Vec3 u = random.unit_vector();
        const Vec3 direction = Vec3(u.x(), b * u.y(), c * u.z()).normalized();
        const Vec3 centre = parent.centre + random.uniform(0.4, 0.8) * (parent.radius + r) * direction;
        if (inside(centre, r)) spheres.push_back({centre, r});
    }
    return spheres;
}

// At unit density: the integration takes a noticeable time (0.15 s here, far more under the
// sanitizers), and every run of a sweep asks for the same stones, so it is done once a process.
std::vector<ClusterShape> unit_density_shapes() {
    std::vector<ClusterShape> shapes;
    for (int k = 0; k < ballast_shape_count; ++k) {
        std::vector<Sphere> stone = grow_stone(20230 + static_cast<std::uint64_t>(k), 5 + 2 * k);
        const double target = 0.030 + 0.007 * k;
        const double scale = target / cluster_shape(stone, 1.0).size;
        for (Sphere& s : stone) s = {scale * s.centre, scale * s.radius};
        shapes.push_back(cluster_shape(stone, 1.0));
    }
    return shapes;
}

}  // namespace

std::vector<ClusterShape> ballast_shapes(double density) {
    static const std::vector<ClusterShape> unit = unit_density_shapes();  // thread-safe initialisation
    std::vector<ClusterShape> shapes = unit;
    for (ClusterShape& s : shapes) {
        s.mass *= density;
        s.inertia *= density;
    }
    return shapes;
}

}  // namespace rotbench
