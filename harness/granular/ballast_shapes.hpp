// The six irregular clusters of overlapping spheres that stand in for railway ballast (seed
// section 3.2, its Fig. 12: 30-65 mm stones; here 5-15 spheres each, generated from fixed
// seeds, so every build and platform has the same stones).
#pragma once

#include "harness/granular/sphere_union.hpp"

#include <vector>

namespace rotbench {

struct ClusterShape {
    std::vector<Sphere> spheres;  // in the body frame: principal axes, centre of mass at the origin
    double mass = 0;
    Vec3 inertia = Vec3::Zero();  // principal moments, ascending (body x: the long axis)
    double size = 0;              // extent along the long axis, m
    double reach = 0;             // largest distance of a sphere's surface from the centre of mass
};

// A cluster as given (any frame) moved to its principal frame, with its mass properties.
ClusterShape cluster_shape(const std::vector<Sphere>& spheres, double density);

inline constexpr int ballast_shape_count = 6;
// Shape k (0-5): 5 + 2k spheres, size 30 + 7k mm, density in kg/m^3.
std::vector<ClusterShape> ballast_shapes(double density);

}  // namespace rotbench
