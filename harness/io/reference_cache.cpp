#include "harness/io/reference_cache.hpp"

#include "harness/io/output_files.hpp"

#include "build_info.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

namespace rotbench {
namespace {

constexpr char magic[8] = {'R', 'B', 'T', 'R', 'J', '0', '0', '1'};

// A trajectory is only as reproducible as the build that computed it: another compiler, other
// flags or other code round differently. The stored key therefore names the build, and a
// build from a modified tree (whose code the commit does not pin) keeps no disk cache at all.
// (Before, a sample report reused references cached by a build without -ffp-contract=off and
// differed from a fresh run in the 14th digit.)
std::string stored_key(const std::string& run_key) { return run_key + "|build=" + cache_build_key(); }

std::filesystem::path directory() {
    if (!build_is_pinned()) return "";
    if (const char* dir = std::getenv("ROTBENCH_CACHE")) return std::string(dir) == "off" ? "" : dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "rotbench";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "rotbench";
    return "";
}

std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    return h;
}

std::filesystem::path file_for(const std::string& scene_id, const std::string& key) {
    const auto dir = directory();
    return dir.empty() ? dir : dir / fmt::format("{}-{:016x}.traj", scene_id, fnv1a(key));
}

}  // namespace

std::string cache_build_key() {
    return fmt::format("{}|{}|{}|{}", build_info::commit, build_info::compiler, build_info::build_type, build_info::flags);
}

bool build_is_pinned() {
    const std::string commit = build_info::commit;
    return commit != "unknown" && !commit.ends_with("-dirty");
}

std::optional<Trajectory> load_cached(const std::string& scene_id, const std::string& run_key) {
    const std::string key = stored_key(run_key);
    const auto path = file_for(scene_id, key);
    if (path.empty()) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    char head[sizeof magic];
    std::uint64_t key_size = 0, bodies = 0, count = 0;
    if (!in.read(head, sizeof head) || std::memcmp(head, magic, sizeof magic) != 0) return std::nullopt;
    if (!in.read(reinterpret_cast<char*>(&key_size), sizeof key_size) || key_size != key.size()) return std::nullopt;
    std::string stored(key_size, '\0');
    if (!in.read(stored.data(), static_cast<std::streamsize>(key_size)) || stored != key) return std::nullopt;
    if (!in.read(reinterpret_cast<char*>(&bodies), sizeof bodies) || !in.read(reinterpret_cast<char*>(&count), sizeof count))
        return std::nullopt;
    Trajectory t;
    t.bodies = bodies;
    t.values.resize(count);
    if (!in.read(reinterpret_cast<char*>(t.values.data()), static_cast<std::streamsize>(count * sizeof(double))))
        return std::nullopt;
    return t;
}

void store_cached(const std::string& scene_id, const std::string& run_key, const Trajectory& trajectory) {
    const std::string key = stored_key(run_key);
    const auto path = file_for(scene_id, key);
    if (path.empty()) return;
    std::string bytes(magic, sizeof magic);
    auto put = [&](const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); };
    const std::uint64_t key_size = key.size(), bodies = trajectory.bodies, count = trajectory.values.size();
    put(&key_size, sizeof key_size);
    bytes += key;
    put(&bodies, sizeof bodies);
    put(&count, sizeof count);
    put(trajectory.values.data(), count * sizeof(double));
    try {
        std::filesystem::create_directories(path.parent_path());
        write_file_atomically(path, bytes);
    } catch (const std::exception&) {
        // An unwritable cache costs time, not correctness.
    }
}

}  // namespace rotbench
