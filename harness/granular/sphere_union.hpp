// Mass, centre of mass and principal moments and axes of a union of overlapping spheres of
// uniform density: the rigid body of a cluster (issue 23, seed section 3.2).
#pragma once

#include "schemes/bodies.hpp"

#include <vector>

namespace rotbench {

struct Sphere {
    Vec3 centre;
    double radius = 0;
};

struct MassProperties {
    double mass = 0;
    Vec3 centre = Vec3::Zero();                          // centre of mass
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // tensor about the centre of mass
    Vec3 principal = Vec3::Zero();                       // its eigenvalues, ascending
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: the principal axes (right-handed)
};

// Each point of the union belongs to the first sphere (in the given order) that holds it.
// Sphere i integrates the part of itself that no earlier sphere holds, in spherical
// coordinates about its own centre: along each ray the part kept is a set of intervals, over
// which the radial integrals of 1, x and x x^T are done exactly; the directions are a
// product rule, Gauss-Legendre in cos(theta) (`nodes` points) times the trapezoid rule in phi
// (2 `nodes` points). The rule integrates polynomials of degree below 2 `nodes` on the sphere
// exactly, so a lone sphere, and spheres that overlap no earlier one, are exact to round-off.
// Where spheres overlap, the kept length has a kink along the intersection circle and the
// error falls about as nodes^-2 (tests/test_sphere_union.cpp measures it).
MassProperties union_mass_properties(const std::vector<Sphere>& spheres, double density, int nodes = 128);

}  // namespace rotbench
