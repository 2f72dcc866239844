// The walls as a picture of the stones shows them (reports/granular_pictures.hpp): seen along
// +y, a wall facing x or z is a line in the x-z plane; one facing y lies in that plane and is
// not drawn.
#pragma once

#include "harness/granular/cluster_system.hpp"

#include <array>
#include <vector>

namespace rotbench {

// The visible part of every wall facing x or z, as segments {x0, z0, x1, z1}, clipped to the
// frame's x-z box: a wall's region bounds it, its hole (the silo's orifice) cuts it in two,
// and a wall outside its own region (the shear box's upper half before the split) or at an
// infinite offset (the lid before it is laid) is not there.
std::vector<std::array<double, 4>> wall_segments(const std::vector<Wall>& walls, const Eigen::AlignedBox2d& frame);

// The x-z box a picture of these spheres and walls needs: the spheres' extent and the position
// of every wall drawn. Walls end at its edges, so that a floor or a lid spans the stones and a
// side wall runs from the floor to the highest stone or the lid, not into empty space.
Eigen::AlignedBox2d picture_frame(const std::vector<Sphere>& spheres, const std::vector<Wall>& walls);

}  // namespace rotbench
