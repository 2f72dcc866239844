// The on-disk cache of reference trajectories. Directory: $ROTBENCH_CACHE if set ("off"
// disables it), else $XDG_CACHE_HOME/rotbench, else $HOME/.cache/rotbench. A file is named
// by a hash of its key and stores the key itself, so a hash collision is a miss. Files are
// written atomically; a cache that cannot be read or written is a miss, never an error.
// The key is completed with the build (commit, compiler, flags); a build of a modified tree
// uses no disk cache.
#pragma once

#include "references/trajectory.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace rotbench {

// The build a cached trajectory must come from (commit, compiler, flags): another build rounds
// differently. A build of a modified tree is not pinned by its commit and uses no disk cache.
std::string cache_build_key();
bool build_is_pinned();

// Larger trajectories are not kept: 512 MiB, 9.6 million body-steps of 56 bytes.
inline constexpr std::size_t max_cached_bytes = std::size_t(1) << 29;

std::optional<Trajectory> load_cached(const std::string& scene_id, const std::string& key);
void store_cached(const std::string& scene_id, const std::string& key, const Trajectory& trajectory);

// The file format: magic, key, sizes, values, and an FNV-1a checksum of all of it. A file that
// is damaged anywhere (truncated, a flipped bit, sizes that do not add up) decodes to nothing.
std::string encode_trajectory(const std::string& key, const Trajectory& trajectory);
std::optional<Trajectory> decode_trajectory(const std::string& bytes, const std::string& key);

}  // namespace rotbench
