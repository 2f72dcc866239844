// Clusters of spheres in contact with one another and with walls, under gravity: the force
// model of the granular scenes (silo_discharge, direct_shear). Contacts are found by a linked-
// cell search over the clusters' bounding spheres, then between the spheres of two clusters
// that may touch, and between a sphere and a wall; they act by the Hertz-Mindlin law
// (hertz_mindlin.hpp). Spheres of one cluster do not touch: the cluster is rigid.
#pragma once

#include "harness/granular/ballast_shapes.hpp"
#include "harness/granular/hertz_mindlin.hpp"
#include "harness/granular/linked_cells.hpp"
#include "harness/granular/near_sphere_pairs.hpp"
#include "harness/granular/spring_table.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

namespace rotbench {

// A flat wall, one-sided: it pushes a sphere whose centre lies inside `region`, in front of it
// (on the side of the normal) and closer than its radius. `hole` is an opening (a silo's
// orifice), a box whose sides are parallel to the wall's normal, which must be a coordinate
// axis: a sphere whose centre lies in it meets the opening's rim instead, from either side.
// A `plate` is a wall of finite extent (a table): a sphere whose centre lies beside its region
// meets the plate's edge, the nearest point of the plate.
struct Wall {
    Vec3 normal = Vec3::UnitZ();  // unit, towards the particles
    double offset = 0;            // the plane: normal . x = offset
    double friction = 0;
    Vec3 velocity = Vec3::Zero();  // a moving wall (the shear box's lower half, a lid)
    Eigen::AlignedBox3d region{Vec3::Constant(-INFINITY), Vec3::Constant(INFINITY)};
    std::optional<Eigen::AlignedBox3d> hole;
    bool plate = false;
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
    void set_friction(double friction) { friction_ = friction; }  // between stones; a scene may change it too

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
    double largest_reach_ = 0, skin_ = 0;
    std::vector<double> reach_;  // of each body
    double reach_of(std::size_t body) const { return reach_[body]; }
    std::size_t sphere_count_of(std::size_t body) const { return shapes_[static_cast<std::size_t>(shape_of_[body])].spheres.size(); }

    // The state of the contacts between evaluations, and scratch space reused at every step.
    mutable SpringTable springs_, next_springs_;
    mutable double last_time_ = NAN, last_step_ = 0;
    mutable std::vector<Vec3> wall_loads_, centres_, positions_;
    mutable std::vector<double> radii_;
    mutable std::vector<std::size_t> owner_, near_walls_;
    mutable double elastic_energy_ = 0;
    mutable LinkedCells cells_;
    mutable NearSpherePairs near_pairs_;
};

}  // namespace rotbench
