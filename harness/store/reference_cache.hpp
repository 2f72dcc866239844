// The on-disk cache of reference trajectories. Directory: $ROTBENCH_CACHE if set ("off"
// disables it), else $XDG_CACHE_HOME/rotbench, else $HOME/.cache/rotbench. A file is named
// by a hash of its key and stores the key itself, so a hash collision is a miss. Files are
// written atomically; a cache that cannot be read or written is a miss, never an error.
// The key is completed with the build (commit, compiler, flags); a build of a modified tree
// uses no disk cache.
#pragma once

#include "references/trajectory.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace rotbench {

// The build a cached trajectory must come from (commit, compiler, flags): another build rounds
// differently. A build of a modified tree is not pinned by its commit and uses no disk cache.
std::string cache_build_key();
bool build_is_pinned();

// Why the configured cache folder is not used, or "" when it is: a folder another user owns, or
// one that others may write, could be edited to change every later result (the checksums find
// damage, not edits), so it is neither read nor written.
std::string untrusted_cache_reason();

// Larger trajectories are not kept: 512 MiB, 9.6 million body-steps of 56 bytes.
inline constexpr std::size_t max_cached_bytes = std::size_t(1) << 29;
// The whole cache is kept below this: past it, storing a trajectory removes the cache's files
// used least recently (a hit refreshes a file's time). The key names the build, so every commit
// makes new files; unbounded, a developer's cache grew to 77 GB and filled the disk.
inline constexpr std::uintmax_t max_cache_bytes = std::uintmax_t(2) << 30;
// Removes the least recently used cache files of `dir` (named as the cache names them and
// beginning with its magic: nothing else is touched) until the folder holds at most `limit`
// bytes; never `keep`.
void trim_cache(const std::filesystem::path& dir, std::uintmax_t limit, const std::filesystem::path& keep = {});

std::optional<Trajectory> load_cached(const std::string& scene_id, const std::string& key);
void store_cached(const std::string& scene_id, const std::string& key, const Trajectory& trajectory);

// The file format: magic, key, sizes, values, and an FNV-1a checksum of all of it. A file that
// is damaged anywhere (truncated, a flipped bit, sizes that do not add up) decodes to nothing.
std::string encode_trajectory(const std::string& key, const Trajectory& trajectory);
std::optional<Trajectory> decode_trajectory(const std::string& bytes, const std::string& key);

}  // namespace rotbench
