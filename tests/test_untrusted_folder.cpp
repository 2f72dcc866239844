// An output folder is input, and may come from someone else (a CI artifact, a tarball, a
// shared disk): whatever its bookkeeping says and whatever links it holds, rotbench touches no
// file outside it, and refuses forged bookkeeping in one line (docs/outputs.md).
#include "harness/store/output_files.hpp"
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>

using namespace rotbench;
using namespace rotbench::test;

namespace {

const std::vector<std::string> one_run = {"run", "--scenes", "dipole_top", "--schemes", "direct", "--dt", "0.01", "--quiet"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// A folder outside the output folder, with a file whose content must never change.
struct Victim {
    fs::path dir;
    explicit Victim(const std::string& name) : dir(fresh_dir(name)) {
        fs::create_directories(dir);
        write(dir / "precious", "keep me\n");
    }
    bool intact() const {
        std::size_t files = 0;
        for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(dir)) ++files;
        return files == 1 && read(dir / "precious") == "keep me\n";
    }
    ~Victim() { fs::remove_all(dir); }
};

void append(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::app) << text;
}

}  // namespace

TEST_CASE("untrusted folder: a manifest that lists a name outside the folder is refused, and nothing is deleted") {
    const Victim victim("untrusted_manifest_victim");
    const fs::path out = fresh_dir("untrusted_manifest");
    REQUIRE(cli(with(one_run, {"--out", out.string()})).status == 0);
    const std::string manifest = read(out / ".rotbench" / "manifest");
    for (const std::string& forged : {(victim.dir / "precious").string(), "../" + victim.dir.filename().string() + "/precious",
                                      std::string("series/../../x"), std::string(".rotbench/lock"), std::string("./report.md")}) {
        INFO(forged);
        write(out / ".rotbench" / "manifest", manifest);
        append(out / ".rotbench" / "manifest", "run\t" + forged + "\n");
        const Cli overwrite = cli(with(one_run, {"--out", out.string(), "--overwrite"}));
        CHECK(overwrite.status == 2);
        CHECK(one_line(overwrite.err));
        CHECK_THAT(overwrite.err, Catch::Contains("which is not a name rotbench writes in its folder"));
        CHECK(victim.intact());
        CHECK(fs::exists(out / ".rotbench" / "lock"));
    }
    fs::remove_all(out);
}

TEST_CASE("untrusted folder: no link inside the output folder is written, truncated or removed through") {
    const fs::path out = fresh_dir("untrusted_links");
    REQUIRE(cli(with(one_run, {"--out", out.string()})).status == 0);
    SECTION("the lock is a link to a file: not truncated, no PID written into it") {
        const Victim victim("untrusted_lock_victim");
        fs::remove(out / ".rotbench" / "lock");
        fs::create_symlink(victim.dir / "precious", out / ".rotbench" / "lock");
        const Cli report = cli({"report", out.string()});
        CHECK(report.status == 2);
        CHECK_THAT(report.err, Catch::Contains("is a symbolic link; rotbench writes nothing through a link in its folder"));
        CHECK(victim.intact());
    }
    SECTION("a folder rotbench writes in is a link to another: nothing in the other changes") {
        for (const char* folder : {"plots", "series", "partial", ".rotbench"}) {
            INFO(folder);
            const Victim victim("untrusted_folder_victim");
            const fs::path kept = out.string() + "_kept";
            if (fs::exists(out / folder)) fs::rename(out / folder, kept);
            fs::create_symlink(victim.dir, out / folder);
            const Cli run = cli(with(one_run, {"--out", out.string(), "--overwrite"}));
            CHECK(run.status == 2);
            CHECK(one_line(run.err));
            CHECK_THAT(run.err, Catch::Contains("is a symbolic link"));
            CHECK(victim.intact());
            fs::remove(out / folder);
            if (fs::exists(kept)) fs::rename(kept, out / folder);
        }
    }
    SECTION("an output the manifest lists is a link: re-rendering refuses, --overwrite replaces the link only") {
        const Victim victim("untrusted_output_victim");
        fs::remove(out / "report.md");
        fs::create_symlink(victim.dir / "precious", out / "report.md");
        const Cli report = cli({"report", out.string()});
        CHECK(report.status == 2);
        CHECK_THAT(report.err, Catch::Contains("report.md is a symbolic link"));
        CHECK(victim.intact());
        REQUIRE(cli(with(one_run, {"--out", out.string(), "--overwrite"})).status == 0);
        CHECK(fs::is_regular_file(fs::symlink_status(out / "report.md")));
        CHECK(victim.intact());
    }
    fs::remove_all(out);
}

TEST_CASE("untrusted folder: --resume runs only a sweep, never another command read from the folder") {
    const Victim victim("untrusted_resume_victim");
    const fs::path out = fresh_dir("untrusted_resume");
    fs::create_directories(out / "partial");
    write(out / "partial" / "runs.jsonl", "{\"journal\": {\"command\": [\"reference\", \"--scene\", \"dipole_top\", \"--samples\", \"3\", "
                                          "\"--out\", \"" + (victim.dir / "written").string() + "\"], \"cwd\": \"" +
                                          fs::current_path().string() + "\", \"files\": []}}\n");
    const Cli resumed = cli({"run", "--resume", out.string()});
    CHECK(resumed.status == 2);
    CHECK(one_line(resumed.err));
    CHECK_THAT(resumed.err, Catch::Contains("the journal, partial/runs.jsonl, names 'reference', which is not a command rotbench resumes"));
    CHECK(victim.intact());
    fs::remove_all(out);
}

TEST_CASE("untrusted folder: an atomic write replaces a link with a file and never writes through it") {
    const Victim victim("untrusted_atomic_victim");
    const fs::path dir = fresh_dir("untrusted_atomic");
    fs::create_directories(dir);
    fs::create_symlink(victim.dir / "precious", dir / "out.csv");
    write_file_atomically(dir / "out.csv", "a,b\n");
    CHECK(fs::is_regular_file(fs::symlink_status(dir / "out.csv")));
    CHECK(read(dir / "out.csv") == "a,b\n");
    CHECK(victim.intact());
    std::size_t files = 0;  // no temporary left beside it
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    CHECK(files == 1);
    fs::remove_all(dir);
}
