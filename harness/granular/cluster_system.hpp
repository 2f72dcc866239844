// Clusters of spheres in contact with one another and with walls, under gravity: the force
// model of the granular scenes (silo_discharge, direct_shear). Contacts are found by a linked-
// cell search over the spheres, between spheres of different clusters and between a sphere
// and a wall, and act by the Hertz-Mindlin law (hertz_mindlin.hpp). Contacts between spheres
// of one cluster are not contacts: the cluster is rigid.
#pragma once

#include "harness/granular/ballast_shapes.hpp"
#include "harness/granular/hertz_mindlin.hpp"
#include "harness/granular/linked_cells.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace rotbench {

// A flat wall, one-sided: it pushes a sphere whose centre lies in front of it (on the side of
// the normal) closer than its radius, and inside `region` but not inside `hole` (an opening,
// such as a silo's orifice; the opening's edges are not modelled).
struct Wall {
    Vec3 normal = Vec3::UnitZ();  // unit, towards the particles
    double offset = 0;            // the plane: normal . x = offset
    double friction = 0;
    Vec3 velocity = Vec3::Zero();  // a moving wall (the shear box's lower half, a lid)
    Eigen::AlignedBox3d region{Vec3::Constant(-INFINITY), Vec3::Constant(INFINITY)};
    std::optional<Eigen::AlignedBox3d> hole;
};

class ClusterSystem {
public:
    ClusterSystem(std::vector<ClusterShape> shapes, const ContactMaterial& material, double friction, const Vec3& gravity);

    // Bodies of the given shapes (indices into shapes()), at rest, at the given places.
    Bodies make_bodies(const std::vector<int>& shape_of, const std::vector<Vec3>& positions,
                       const std::vector<Quat>& orientations);
    const std::vector<ClusterShape>& shapes() const { return shapes_; }
    const std::vector<int>& shape_of() const { return shape_of_; }

    std::vector<Wall> walls;  // scenes move them between evaluations

    // Forces and torques at time t (world frame), gravity included. The tangential springs
    // are advanced by the time since the previous evaluation; an evaluation that does not
    // follow on from the previous one at a steady step (the first, or a restart elsewhere in
    // the run) starts every spring afresh.
    void evaluate(Bodies& bodies, double t) const;

    // Of the last evaluation: the force the particles put on each wall, the normal springs'
    // elastic energy, the number of contacts.
    const std::vector<Vec3>& wall_loads() const { return wall_loads_; }
    double elastic_energy() const { return elastic_energy_; }
    std::size_t contacts() const { return springs_.size(); }

    double potential_energy(const Bodies& bodies) const;  // of gravity, zero at the origin
    // The spheres in the world, for pictures and for tests.
    std::vector<Sphere> world_spheres(const Bodies& bodies) const;

private:
    std::vector<ClusterShape> shapes_;
    HertzMindlin law_;
    double friction_;
    Vec3 gravity_;
    std::vector<int> shape_of_;
    std::vector<std::size_t> first_sphere_;  // of each body, in the list of all spheres
    double largest_radius_ = 0;

    // The state of the contacts between evaluations, and scratch space reused at every step.
    mutable std::unordered_map<std::uint64_t, Vec3> springs_, next_springs_;
    mutable double last_time_ = NAN, last_step_ = 0;
    mutable std::vector<Vec3> wall_loads_, centres_;
    mutable std::vector<double> radii_;
    mutable std::vector<std::size_t> owner_;
    mutable double elastic_energy_ = 0;
    mutable LinkedCells cells_;
};

}  // namespace rotbench
