// A disk that fills up halfway through a sweep (docs/outputs.md "A full disk"): rotbench stops
// with one line and exit status 3, leaves no half-written file, and once there is room again
// `run --resume` (or the same command, when nothing was kept) ends with the results a run on
// an empty disk gives. The disk is a small tmpfs in a private mount namespace; where the
// system refuses one, a file-size limit (RLIMIT_FSIZE, EFBIG) stands in for it.
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/resource.h>

using namespace rotbench::test;

namespace {

// This test process (each test case runs in its own) moves to a mount namespace of its own,
// where it may mount a tmpfs: as root directly, as a user through a user namespace.
bool private_mounts() {
    const uid_t uid = ::getuid();
    const gid_t gid = ::getgid();
    if (::unshare(uid == 0 ? CLONE_NEWNS : CLONE_NEWUSER | CLONE_NEWNS) != 0) return false;
    if (uid != 0) {
        const auto put = [](const char* file, const std::string& text) {
            const int fd = ::open(file, O_WRONLY);
            const bool ok = fd >= 0 && ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
            if (fd >= 0) ::close(fd);
            return ok;
        };
        if (!put("/proc/self/setgroups", "deny") || !put("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1") ||
            !put("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1"))
            return false;
    }
    return ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0;
}

std::uintmax_t bytes_under(const fs::path& dir) {
    std::uintmax_t total = 0;
    for (const auto& f : fs::recursive_directory_iterator(dir))
        if (f.is_regular_file()) total += f.file_size();
    return total;
}

std::uintmax_t largest_file(const fs::path& dir) {
    std::uintmax_t largest = 0;
    for (const auto& f : fs::recursive_directory_iterator(dir))
        if (f.is_regular_file()) largest = std::max(largest, f.file_size());
    return largest;
}

bool has_temporary_file(const fs::path& dir) {
    for (const auto& f : fs::recursive_directory_iterator(dir))
        if (f.path().filename().string().ends_with(".tmp")) return true;
    return false;
}

}  // namespace

TEST_CASE("outputs: a full disk stops the sweep with one line and status 3, and a resume ends as a run on an empty disk") {
    const fs::path base = fresh_dir("full_disk");
    const fs::path disk = base / "disk";
    fs::create_directories(disk);
    // --quiet: on a loaded machine the sweep outlives the 5 s between progress lines, which
    // would share stderr with the one line the full disk must give.
    const std::vector<std::string> sweep = {"run", "--scenes", "asymmetric_free,dipole_top", "--schemes", "direct,cayley", "--quick", "--jobs", "2", "--quiet"};
    const std::vector<std::string> environment = {"ROTBENCH_CACHE=off"};
    const auto with_out = [&](const fs::path& out) {
        auto args = sweep;
        args.insert(args.end(), {"--out", out.string()});
        return args;
    };
    const Cli reference = binary(with_out(base / "reference"), environment);
    REQUIRE(reference.status == 0);
    const std::string expected = without_timing(read(base / "reference" / "results.csv"));

    const bool tmpfs = private_mounts();
    // A tmpfs that holds a fraction of the whole output (the sweep fails at a journal record,
    // results.csv, the report or a plot), or a limit on the size of any one file.
    const std::uintmax_t whole = tmpfs ? bytes_under(base / "reference") : largest_file(base / "reference");
    if (!tmpfs) WARN("no private tmpfs here: a file-size limit stands in for the full disk");
    int stopped = 0;
    for (int eighths = 1; eighths < 8; ++eighths) {
        const std::uintmax_t room = whole * eighths / 8;
        const fs::path out = disk / ("r" + std::to_string(eighths));
        std::function<void()> limit;
        if (tmpfs) {
            REQUIRE(::mount("tmpfs", disk.c_str(), "tmpfs", 0, ("size=" + std::to_string(room)).c_str()) == 0);
        } else {
            limit = [room] {
                std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG
                const rlimit l{room, room};
                ::setrlimit(RLIMIT_FSIZE, &l);
            };
        }
        const Cli full = binary(with_out(out), environment, limit);
        INFO("room " << room << " bytes: " << full.err);
        CHECK((full.status == 0 || full.status == 3));
        if (full.status == 3) {
            ++stopped;
            CHECK_THAT(full.err, Catch::Contains(tmpfs ? "No space left on device" : "File too large"));
            CHECK(one_line(full.err));
        }
        CHECK_FALSE(has_temporary_file(out));
        // Room again: the resume (or, when not even the plan was kept, the command again) ends the sweep.
        if (tmpfs) REQUIRE(::mount("tmpfs", disk.c_str(), "tmpfs", MS_REMOUNT, "size=64m") == 0);
        const Cli resumed = binary({"run", "--resume", out.string()}, environment);
        INFO("resume: " << resumed.err);
        if (resumed.status != 0) {
            CHECK_THAT(resumed.err, Catch::Contains("no interrupted run there"));
            REQUIRE(binary(with_out(out), environment).status == 0);
        }
        CHECK(without_timing(read(out / "results.csv")) == expected);
        CHECK(fs::exists(out / "report.md"));
        if (tmpfs) REQUIRE(::umount(disk.c_str()) == 0);
    }
    CHECK(stopped == 7);  // less room than the whole output (or its largest file) never suffices
    fs::remove_all(base);
}
