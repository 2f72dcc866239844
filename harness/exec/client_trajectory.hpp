// Reading back the states a client's program wrote, one row per body at every step
// (docs/clients.md, `trajectory.csv`): sized before it is read, checked row by row.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// The columns of one body's trajectory: time, the orientation (body to world, w first; q and -q
// are the same orientation) and the world angular velocity, one row at every step t = k dt.
inline constexpr const char* client_trajectory_header = "t,qw,qx,qy,qz,wx,wy,wz";
// The columns on a contact scene: both bodies at every step, body 0's row first; each body's
// centre of mass and velocity, then its orientation and world angular velocity as above.
inline constexpr const char* contact_trajectory_header = "t,body,x,y,z,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz";

using TrajectoryRow = std::vector<double>;

struct TrajectoryLayout {
    const char* header;
    std::size_t bodies;  // rows per step; a `body` column (second) numbers them 0 ... bodies - 1
    bool finite;         // false: a value that is not finite is a blow-up the caller judges
};
inline constexpr TrajectoryLayout one_body_trajectory{client_trajectory_header, 1, true};
inline constexpr TrajectoryLayout contact_trajectory{contact_trajectory_header, 2, false};

// The rows of the file (steps + 1 times `bodies`), or why they are not a trajectory of `steps` steps
// of `dt`: "" when they are.
std::string read_trajectory(const std::filesystem::path& file, const TrajectoryLayout& layout, std::int64_t steps, double dt,
                            std::vector<TrajectoryRow>& rows);

}  // namespace rotbench
