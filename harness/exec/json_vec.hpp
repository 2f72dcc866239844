// A vector as the scene specs handed to clients write it: [x, y, z].
#pragma once

#include "schemes/quaternion.hpp"

#include <nlohmann/json.hpp>

namespace rotbench {

inline nlohmann::ordered_json json_vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace rotbench
