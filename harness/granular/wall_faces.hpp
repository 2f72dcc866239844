// The walls as flat rectangles, for a DEM code that takes walls as meshes (a granular client,
// harness/exec/granular_client.hpp).
#pragma once

#include "harness/granular/cluster_system.hpp"

#include <array>
#include <vector>

namespace rotbench {

struct WallFace {
    std::array<Vec3, 4> corners;  // in turn around the face, counter-clockwise seen from the side the normal points to
    Vec3 normal;                  // towards the stones
    double friction = 0;
};

// Each wall's plane over its region, clipped to `domain`: one rectangle, or the four around
// its hole. A wall at an infinite offset (not there yet) has none. Throws std::invalid_argument
// for a wall whose normal is not a coordinate axis (every wall a scene builds is one).
std::vector<WallFace> wall_faces(const std::vector<Wall>& walls, const Eigen::AlignedBox3d& domain);

}  // namespace rotbench
