// The on-disk cache of reference trajectories. Directory: $ROTBENCH_CACHE if set ("off"
// disables it), else $XDG_CACHE_HOME/rotbench, else $HOME/.cache/rotbench. A file is named
// by a hash of its key and stores the key itself, so a hash collision is a miss. Files are
// written atomically; a cache that cannot be read or written is a miss, never an error.
// The key is completed with the build (commit, compiler, flags); a build of a modified tree
// uses no disk cache.
#pragma once

#include "references/trajectory.hpp"

#include <optional>
#include <string>

namespace rotbench {

// The build a cached trajectory must come from (commit, compiler, flags): another build rounds
// differently. A build of a modified tree is not pinned by its commit and uses no disk cache.
std::string cache_build_key();
bool build_is_pinned();

std::optional<Trajectory> load_cached(const std::string& scene_id, const std::string& key);
void store_cached(const std::string& scene_id, const std::string& key, const Trajectory& trajectory);

}  // namespace rotbench
