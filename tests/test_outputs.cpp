// Nothing lost, nothing injected (docs/outputs.md "Output directories"): rotbench writes only
// into directories that are new, empty or carry its manifest; never deletes or replaces a file
// it did not write; refuses a second process writing into a directory in use; and starts
// gnuplot without a shell, so any path works and none runs a command.
#include "harness/core/fnv1a.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/output_files.hpp"
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <thread>

using namespace rotbench;
using namespace rotbench::test;

namespace {

const std::vector<std::string> one_run = {"run", "--scenes", "dipole_top", "--schemes", "direct", "--dt", "0.01"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

}  // namespace

TEST_CASE("outputs: a user's files in the output directory are never deleted or replaced, --overwrite or not") {
    const fs::path dir = fresh_dir("outputs_foreign");
    fs::create_directories(dir / "partial");
    write(dir / "partial" / "notes.txt", "mine\n");
    write(dir / "notes.md", "mine\n");
    // Not ours: refused without --overwrite; with it rotbench writes beside the user's files.
    const Cli refused = cli(with(one_run, {"--out", dir.string()}));
    CHECK(refused.status == 2);
    CHECK_THAT(refused.err, Catch::Contains("holds files rotbench did not write"));
    REQUIRE(cli(with(one_run, {"--out", dir.string(), "--overwrite"})).status == 0);
    CHECK(read(dir / "partial" / "notes.txt") == "mine\n");
    CHECK(read(dir / "notes.md") == "mine\n");
    CHECK(fs::exists(dir / "report.md"));
    // Our files are ours from now on: --overwrite replaces them, and only them.
    REQUIRE(cli(with(one_run, {"--out", dir.string(), "--overwrite"})).status == 0);
    CHECK(read(dir / "notes.md") == "mine\n");
    // A user's file in the way of one rotbench writes is refused before anything runs.
    const fs::path other = fresh_dir("outputs_in_the_way");
    fs::create_directories(other);
    write(other / "report.md", "my report\n");
    const Cli blocked = cli(with(one_run, {"--out", other.string(), "--overwrite"}));
    CHECK(blocked.status == 2);
    CHECK_THAT(blocked.err, Catch::Contains("report.md exists and was not written by rotbench; it is never replaced"));
    CHECK(read(other / "report.md") == "my report\n");
    CHECK_FALSE(fs::exists(other / "results.csv"));
    // So is a user's file where rotbench writes a folder (the runs would fail at their end).
    for (const char* folder : {"plots", "series", "snapshots", "walls"}) {
        INFO(folder);
        fs::remove_all(other);
        fs::create_directories(other);
        write(other / folder, "mine\n");
        const Cli taken = cli(with(one_run, {"--out", other.string(), "--overwrite"}));
        CHECK(taken.status == 2);
        CHECK_THAT(taken.err, Catch::Contains((other / folder).string() + " is a file where rotbench writes a directory"));
        CHECK(read(other / folder) == "mine\n");
        CHECK_FALSE(fs::exists(other / "results.csv"));
    }
    fs::remove_all(dir);
    fs::remove_all(other);
}

TEST_CASE("outputs: a gate never replaces a finished run's results, and another family may write beside it") {
    const fs::path dir = fresh_dir("outputs_families");
    REQUIRE(cli(with(one_run, {"--out", dir.string()})).status == 0);
    const std::string results = read(dir / "results.csv");
    write(dir / "g.toml", "[[check]]\nscene = \"dipole_top\"\nschemes = [\"direct\"]\nmax_error = 1\ndt = 0.01\n");
    const Cli gate = cli({"gate", (dir / "g.toml").string(), "--out", dir.string(), "--overwrite"});
    CHECK(gate.status == 2);
    CHECK_THAT(gate.err, Catch::Contains("runs.jsonl was written by rotbench run; it is not replaced by gate"));
    CHECK(read(dir / "results.csv") == results);
    // The stability study writes other files: beside the run's, which stay as they were.
    REQUIRE(cli({"stability", "--scenes", "sphere_pair", "--schemes", "direct", "--zeta", "0", "--out", dir.string()}).status == 0);
    CHECK(fs::exists(dir / "stability.csv"));
    CHECK(read(dir / "results.csv") == results);
    fs::remove_all(dir);
}

TEST_CASE("outputs: a single output file is replaced only with --overwrite, and only when rotbench wrote it") {
    const fs::path dir = fresh_dir("outputs_single");
    fs::create_directories(dir);
    const std::string file = (dir / "ref.csv").string();
    const std::vector<std::string> export_args = {"reference", "--scene", "dipole_top", "--samples", "10", "--out", file};
    REQUIRE(cli(export_args).status == 0);
    const Cli again = cli(export_args);
    CHECK(again.status == 2);
    CHECK_THAT(again.err, Catch::Contains("exists; pass --overwrite to replace it"));
    CHECK(cli(with(export_args, {"--overwrite"})).status == 0);
    write(file, "my data\n");
    const Cli foreign = cli(with(export_args, {"--overwrite"}));
    CHECK(foreign.status == 2);
    CHECK_THAT(foreign.err, Catch::Contains("is not a file rotbench wrote; it is never replaced"));
    CHECK(read(file) == "my data\n");
    fs::remove_all(dir);
}

TEST_CASE("outputs: a second process writing into a directory in use is refused") {
    const fs::path dir = fresh_dir("outputs_lock");
    // A first process holds the directory (a sweep of a few seconds); a second is refused, and the
    // first finishes unharmed.
    std::vector<std::string> args = {ROTBENCH_EXE, "run", "--scenes", "dipole_top", "--dt", "1e-4", "--jobs", "1", "--out", dir.string()};
    const pid_t pid = fork();
    if (pid == 0) {
        freopen("/dev/null", "w", stdout);
        freopen("/dev/null", "w", stderr);
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    while (!fs::exists(dir / "partial" / "runs.jsonl")) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const Cli second = cli(with(one_run, {"--out", dir.string(), "--overwrite"}));
    CHECK(second.status == 2);
    CHECK_THAT(second.err, Catch::Contains("is in use by another rotbench (process " + std::to_string(pid) + ")"));
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    fs::remove_all(dir);
}

TEST_CASE("outputs: gnuplot runs without a shell: a path with quotes or a command in it draws its plots and runs nothing") {
    const fs::path base = fresh_dir("outputs_quotes");
    for (const std::string name : {"it's", "x'; touch PWNED; echo '", "$(touch PWNED)", "a\"b `touch PWNED`"}) {
        const fs::path dir = base / name;
        const Cli r = cli(with(one_run, {"--out", dir.string()}));
        INFO(name << ": " << r.err);
        REQUIRE(r.status == 0);
        CHECK(fs::exists(dir / "plots" / "convergence_dipole_top.svg"));
        CHECK(read(dir / "report.md").find("not drawn") == std::string::npos);
    }
    CHECK_FALSE(fs::exists("PWNED"));
    CHECK_FALSE(fs::exists(base / "PWNED"));
    fs::remove_all(base);
}

TEST_CASE("outputs: without gnuplot the report says it is not installed, and a failing gnuplot is named, not called missing") {
    const fs::path dir = fresh_dir("outputs_no_gnuplot");
    fs::create_directories(dir / "bin");
    const Cli missing = binary(with(one_run, {"--out", (dir / "a").string()}), {"PATH=" + (dir / "bin").string()});
    REQUIRE(missing.status == 0);
    CHECK_THAT(read(dir / "a" / "report.md"), Catch::Contains("gnuplot is not installed"));
    // A gnuplot that fails: said so, with its status.
    write(dir / "bin" / "gnuplot", "#!/bin/sh\nexit 3\n");
    fs::permissions(dir / "bin" / "gnuplot", fs::perms::owner_all);
    const Cli failing = binary(with(one_run, {"--out", (dir / "b").string()}), {"PATH=" + (dir / "bin").string()});
    REQUIRE(failing.status == 0);
    const std::string report = read(dir / "b" / "report.md");
    CHECK_THAT(report, Catch::Contains("gnuplot failed on plots/convergence_dipole_top.gp (its gnuplot exited with status 3"));
    CHECK(report.find("not installed") == std::string::npos);
    CHECK_FALSE(fs::exists(dir / "b" / "plots" / "convergence_dipole_top.svg"));  // no empty or partial SVG
    fs::remove_all(dir);
}

TEST_CASE("outputs: two outputs of one command on one file are refused before any work") {
    const fs::path dir = fresh_dir("outputs_one_file");
    fs::create_directories(dir);
    const std::string gate = (fs::path(ROTBENCH_SOURCE_DIR) / "gates" / "default.toml").string();
    const std::string junit = (dir / "r.xml").string(), same = (dir / "." / "r.xml").string();
    const Cli both = cli({"gate", gate, "--schemes", "direct", "--junit", junit, "--summary", same});
    CHECK(both.status == 2);
    CHECK(one_line(both.err));
    CHECK_THAT(both.err, Catch::Contains("--summary and --junit name one file"));
    const Cli beside = cli({"gate", gate, "--schemes", "direct", "--junit", junit, "--summary", (dir / "summary.json").string()});
    CHECK(beside.status == 2);
    CHECK_THAT(beside.err, Catch::Contains("--summary and --junit (summary.json beside it) name one file"));
    CHECK(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST_CASE("outputs: gate --out D --junit D/junit.xml, CI's layout, writes every file once and exits by its verdict") {
    const fs::path dir = fresh_dir("outputs_junit_in_out");
    const std::string gate = (fs::path(ROTBENCH_SOURCE_DIR) / "gates" / "default.toml").string();
    const std::vector<std::string> args = {"gate", gate, "--schemes", "richardson", "--out", dir.string(), "--junit", (dir / "junit.xml").string()};
    const Cli first = cli(args);
    CHECK(first.status == 0);
    CHECK(first.err.find("summary.json") == std::string::npos);
    for (const char* file : {"gate.csv", "summary.json", "junit.xml", "runs.jsonl", "results.csv", "runs.csv"})
        CHECK(fs::exists(dir / file));
    const Cli again = cli(with(args, {"--overwrite"}));  // the folder's own summary.json, replaced with it
    CHECK(again.status == 0);
    fs::remove_all(dir);
}

TEST_CASE("outputs: a signal outside a sweep ends the command by that signal, stops its gnuplot and leaves no temporary file") {
    const fs::path dir = fresh_dir("outputs_signal");
    REQUIRE(cli(with(one_run, {"--out", (dir / "o").string()})).status == 0);
    // A gnuplot that takes its time and then writes its output, as gnuplot does: the SVG's
    // temporary exists while rotbench waits for it, and a gnuplot left running would write it back.
    fs::create_directories(dir / "bin");
    write(dir / "bin" / "gnuplot", "#!/bin/sh\nout=${2#out=\\'}\nsleep 1\necho '<svg/>' > \"${out%\\'}\"\n");
    fs::permissions(dir / "bin" / "gnuplot", fs::perms::owner_all);
    const auto temporaries = [&] {
        std::size_t n = 0;
        std::error_code ec;  // rotbench makes and removes files meanwhile
        for (fs::recursive_directory_iterator it(dir / "o", ec), end; !ec && it != end; it.increment(ec))
            if (it->path().extension() == ".tmp") ++n;
        return n;
    };
    std::vector<std::string> args = {ROTBENCH_EXE, "report", (dir / "o").string()};
    const std::string path = "PATH=" + (dir / "bin").string() + ":/usr/bin:/bin";
    const pid_t pid = fork();
    if (pid == 0) {
        freopen("/dev/null", "w", stdout);
        freopen("/dev/null", "w", stderr);
        putenv(const_cast<char*>(path.c_str()));
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    while (temporaries() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGTERM);
    CHECK(temporaries() == 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // past the gnuplot's second
    CHECK(temporaries() == 0);
    fs::remove_all(dir);
}

TEST_CASE("outputs: an input read whole is held to its bound while it is read, not only by the size the file claims") {
    // Files of /proc claim 0 bytes and hold more: the bound must stop the reading itself.
    const std::string status = read_input_file("/proc/self/status", "", 1u << 20);
    CHECK_THAT(status, Catch::Contains("Pid:"));
    CHECK_THROWS_WITH(read_input_file("/proc/self/status", "", 10), "/proc/self/status: more than the 10 bytes this input may have");
    CHECK(read_file("/proc/self/status").value_or("").find("Pid:") != std::string::npos);
    CHECK_FALSE(read_file("/proc/self").has_value());  // a directory
    CHECK_THROWS_WITH(read_input_file("/proc/self", "config", 10), "config /proc/self: not a regular file (a directory)");
    // Hashed a block (64 KiB) at a time, a file of several blocks hashes as its text whole.
    const fs::path dir = fresh_dir("blocks"), file = dir / "blocks.csv";
    fs::create_directories(dir);
    std::string text;
    for (int i = 0; text.size() < 200000; ++i) text += std::to_string(i * 7919) + (i % 13 ? "," : "\n");
    write_file_atomically(file, text);
    Fnv1a blocks;
    CHECK(feed_file(file, blocks));
    CHECK(blocks.hex() == Fnv1a().feed(text).hex());
    fs::remove_all(dir);
    CHECK_FALSE(feed_file("/proc/self", blocks));  // a directory
}
