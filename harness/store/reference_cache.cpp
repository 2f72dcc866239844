#include "harness/core/fnv1a.hpp"
#include "harness/store/reference_cache.hpp"

#include "harness/store/output_files.hpp"

#include "build_info.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace rotbench {
namespace {

constexpr char magic[8] = {'R', 'B', 'T', 'R', 'J', '0', '0', '2'};  // 002: with a checksum

// A trajectory is only as reproducible as the build that computed it: another compiler, other
// flags or other code round differently. The stored key therefore names the build, and a
// build from a modified tree (whose code the commit does not pin) keeps no disk cache at all.
// (Before, a sample report reused references cached by a build without -ffp-contract=off and
// differed from a fresh run in the 14th digit.)
std::string stored_key(const std::string& run_key) { return run_key + "|build=" + cache_build_key(); }

std::filesystem::path configured_directory() {
    if (const char* dir = std::getenv("ROTBENCH_CACHE")) return std::string(dir) == "off" ? "" : dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "rotbench";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "rotbench";
    return "";
}

std::filesystem::path directory() { return build_is_pinned() && untrusted_cache_reason().empty() ? configured_directory() : ""; }

std::filesystem::path file_for(const std::string& scene_id, const std::string& key) {
    const auto dir = directory();
    return dir.empty() ? dir : dir / fmt::format("{}-{:016x}.traj", scene_id, Fnv1a().feed(key).value());
}

// A file of the cache: its name as file_for() makes it, and rotbench's magic first. Nothing else
// in the directory is ever removed.
bool cache_file(const std::filesystem::path& path) {
    const std::string name = path.filename().string();
    const auto dash = name.rfind('-');
    if (dash == std::string::npos || name.size() != dash + 1 + 16 + 5 || !name.ends_with(".traj") ||
        name.find_first_not_of("0123456789abcdef", dash + 1) != dash + 17)
        return false;
    char head[sizeof magic] = {};
    std::ifstream in(path, std::ios::binary);
    return in.read(head, sizeof head) && std::memcmp(head, magic, sizeof magic) == 0;
}

}  // namespace

std::string untrusted_cache_reason() {
    const auto dir = configured_directory();
    struct stat st {};
    if (dir.empty() || ::stat(dir.c_str(), &st) != 0) return "";  // none, or made by this user when first stored
    if (!S_ISDIR(st.st_mode)) return fmt::format("the reference cache {} is not a directory", dir.string());
    if (st.st_uid != ::geteuid() || (st.st_mode & (S_IWGRP | S_IWOTH)) != 0)
        return fmt::format("the reference cache {} is not used: it is {}, and whoever can write it could change every later "
                           "result (its checksums find damage, not edits); give each user a cache of their own (ROTBENCH_CACHE)",
                           dir.string(), st.st_uid != ::geteuid() ? "another user's" : "writable by others");
    return "";
}

// Another process may remove the same files at once: errors are ignored.
void trim_cache(const std::filesystem::path& dir, std::uintmax_t limit, const std::filesystem::path& keep) {
    namespace fs = std::filesystem;
    struct Entry {
        fs::file_time_type used;
        std::uintmax_t bytes;
        fs::path path;
    };
    std::vector<Entry> entries;
    std::uintmax_t total = 0;
    std::error_code error;
    for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
        if (!it->is_regular_file(error) || it->is_symlink(error)) continue;
        const auto bytes = it->file_size(error);
        const auto used = it->last_write_time(error);
        if (error) continue;
        total += bytes;
        if (it->path() != keep) entries.push_back({used, bytes, it->path()});
    }
    if (total <= limit) return;
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
    for (const Entry& e : entries) {
        if (total <= limit) break;
        if (!cache_file(e.path)) continue;
        if (fs::remove(e.path, error)) total -= e.bytes;
    }
}

std::string cache_build_key() {
    return fmt::format("{}|{}|{}|{}", build_info::commit, build_info::compiler, build_info::build_type, build_info::flags);
}

bool build_is_pinned() {
    const std::string commit = build_info::commit;
    return commit != "unknown" && !commit.ends_with("-dirty");
}

std::string encode_trajectory(const std::string& key, const Trajectory& trajectory) {
    std::string bytes(magic, sizeof magic);
    auto put = [&](const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); };
    const std::uint64_t key_size = key.size(), bodies = trajectory.bodies, count = trajectory.values.size();
    put(&key_size, sizeof key_size);
    bytes += key;
    put(&bodies, sizeof bodies);
    put(&count, sizeof count);
    if (count > 0) put(trajectory.values.data(), count * sizeof(double));
    const std::uint64_t sum = Fnv1a().feed(bytes).value();
    put(&sum, sizeof sum);
    return bytes;
}

std::optional<Trajectory> decode_trajectory(const std::string& bytes, const std::string& key) {
    // Every size is checked against the bytes there are before anything is allocated: a
    // damaged file is a miss, never a huge allocation or a read past its end.
    std::size_t at = 0;
    const auto take = [&](void* into, std::size_t n) {
        if (bytes.size() - at < n) return false;
        if (n > 0) std::memcpy(into, bytes.data() + at, n);  // an empty trajectory's data() may be null
        at += n;
        return true;
    };
    char head[sizeof magic];
    std::uint64_t key_size = 0, bodies = 0, count = 0, sum = 0;
    if (!take(head, sizeof head) || std::memcmp(head, magic, sizeof magic) != 0) return std::nullopt;
    if (!take(&key_size, sizeof key_size) || key_size != key.size() || bytes.compare(at, key_size, key) != 0) return std::nullopt;
    at += key_size;
    if (!take(&bodies, sizeof bodies) || !take(&count, sizeof count)) return std::nullopt;
    if (bodies == 0 || count % (bodies * Trajectory::width) != 0) return std::nullopt;
    if (count > (bytes.size() - at) / sizeof(double) || bytes.size() - at != count * sizeof(double) + sizeof sum) return std::nullopt;
    Trajectory t;
    t.bodies = bodies;
    t.values.resize(count);
    take(t.values.data(), count * sizeof(double));
    take(&sum, sizeof sum);
    if (sum != Fnv1a().feed(std::string_view(bytes).substr(0, at - sizeof sum)).value()) return std::nullopt;  // a flipped bit anywhere
    return t;
}

std::optional<Trajectory> load_cached(const std::string& scene_id, const std::string& run_key) {
    const std::string key = stored_key(run_key);
    const auto path = file_for(scene_id, key);
    if (path.empty()) return std::nullopt;
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    if (error || size > max_cached_bytes + (1 << 20)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::string bytes(size, '\0');
    if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) return std::nullopt;
    auto trajectory = decode_trajectory(bytes, key);
    if (trajectory) std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), error);  // used now
    return trajectory;
}

void store_cached(const std::string& scene_id, const std::string& run_key, const Trajectory& trajectory) {
    const std::string key = stored_key(run_key);
    const auto path = file_for(scene_id, key);
    if (path.empty() || trajectory.values.size() * sizeof(double) > max_cached_bytes) return;
    try {
        std::filesystem::create_directories(path.parent_path());
        write_file_atomically(path, encode_trajectory(key, trajectory));
        trim_cache(path.parent_path(), max_cache_bytes, path);
    } catch (const std::exception&) {
        // An unwritable cache costs time, not correctness.
    }
}

}  // namespace rotbench
