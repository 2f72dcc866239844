// Plug-in runs in a worker process (harness/exec/isolation.hpp): a scheme that segfaults,
// aborts, exits, throws what is not a std::exception, hangs, exhausts memory or leaves a
// process behind fails (or ends) its own runs, named, and the sweep goes on; an isolated run gives the numbers an in-process run
// gives; a signal stops a sweep whose plug-in hangs at once.
#include "harness/analysis/stability_study.hpp"
#include "harness/exec/isolation.hpp"
#include "harness/store/results_csv.hpp"
#include "tests/cli_helpers.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <map>
#include <thread>

using namespace rotbench;
using namespace rotbench::test;

namespace {

// The failure column of runs.csv, by scheme (one dt per scheme in these sweeps).
std::map<std::string, std::string> failures(const fs::path& dir) {
    const auto records = parse_csv(read(dir / "runs.csv"), "runs.csv");
    std::map<std::string, std::string> by_scheme;
    for (std::size_t i = 1; i < records.size(); ++i) by_scheme[records[i].fields.at(1)] = records[i].fields.at(8);
    return by_scheme;
}

// The first child process of `parent` that /proc shows, waited for up to ten seconds.
pid_t child_of(pid_t parent) {
    for (int tries = 0; tries < 2000; ++tries) {
        for (const auto& p : fs::directory_iterator("/proc")) {
            if (!p.is_directory() || !std::isdigit(static_cast<unsigned char>(p.path().filename().string()[0]))) continue;
            const std::string stat = read(p.path() / "stat");  // pid (comm) state ppid ...
            const auto close = stat.rfind(')');
            if (close == std::string::npos) continue;
            std::istringstream fields(stat.substr(close + 2));
            std::string state;
            pid_t ppid = 0;
            fields >> state >> ppid;
            if (ppid == parent) return std::stoi(p.path().filename().string());
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return -1;
}

}  // namespace

TEST_CASE("isolation: a plug-in that crashes, exits, hangs or eats memory fails only its own run, which names why") {
    const fs::path dir = fresh_dir("isolation_crashes");
    // Under AddressSanitizer a worker has no memory limit (memory_limit_enforced), so the
    // scheme that eats memory would eat the machine's; and ASan turns a SIGSEGV into its
    // report and exit status 1.
    const bool asan = !memory_limit_enforced();
    // --run-timeout 6: long enough for the worker filling its 256 MB to end on its own on a
    // loaded machine (2 s was not), short enough for bad_hang's wait.
    const Cli r = cli({"run", "--plugin", PLUGIN_CRASHING, "--scenes", "asymmetric_free", "--dt", "0.05", "--schemes",
                       std::string("bad_segfault,bad_abort,bad_exit,bad_throw42,bad_hang,") + (asan ? "" : "bad_oom,") + "direct",
                       "--run-timeout", "6", "--run-memory", "256", "--jobs", "2", "--out", dir.string()});
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto failed = failures(dir);
    CHECK_THAT(failed.at("bad_segfault"), Catch::Contains(asan ? "its worker exited with status 1 without a result"
                                                               : "crashed: signal 11 (Segmentation fault)"));
    CHECK_THAT(failed.at("bad_abort"), Catch::Contains("crashed: signal 6 (Aborted)"));
    CHECK_THAT(failed.at("bad_exit"), Catch::Equals("its worker exited with status 7 without a result"));
    CHECK_THAT(failed.at("bad_throw42"), Catch::Contains("threw an exception that is not a std::exception"));
    CHECK_THAT(failed.at("bad_hang"), Catch::Contains("exceeded the run time limit of 6 s (--run-timeout)"));
    if (!asan) CHECK_THAT(failed.at("bad_oom"), Catch::Contains("std::bad_alloc (its worker's memory is limited to 256 MB, --run-memory)"));
    CHECK(failed.at("direct").empty());  // the built-in scheme beside them ran
    CHECK_THAT(read(dir / "report.md"), Catch::Contains("bad_segfault"));
    fs::remove_all(dir);
}

TEST_CASE("isolation: a plug-in scheme's run in a worker is the in-process run, bit for bit") {
    const fs::path dir = fresh_dir("isolation_same");
    // Schemes named: a plug-in an earlier test of this process loaded stays registered.
    const std::vector<std::string> sweep = {"run", "--plugin", PLUGIN_END_VELOCITY_ZVW, "--scenes", "asymmetric_free,torqued_cylinder",
                                            "--schemes", "zvw,zvw_end_velocity", "--quick", "--jobs", "2", "--out"};
    auto isolated = sweep, in_process = sweep;
    isolated.push_back((dir / "isolated").string());
    in_process.push_back((dir / "in_process").string());
    REQUIRE(cli(isolated).status == 0);
    const std::string worker = worker_executable();
    set_worker_executable("");  // no worker: every scheme runs in this process (whose plug-in is loaded)
    in_process.erase(in_process.begin() + 1, in_process.begin() + 3);
    const Cli local = cli(in_process);
    set_worker_executable(worker);
    REQUIRE(local.status == 0);
    for (const char* f : {"results.csv", "runs.csv"}) {
        INFO(f);
        CHECK(without_timing(read(dir / "isolated" / f)) == without_timing(read(dir / "in_process" / f)));
    }
    CHECK_THAT(read(dir / "isolated" / "runs.csv"), Catch::Contains("zvw_end_velocity"));
    fs::remove_all(dir);
}

TEST_CASE("isolation: a worker that leaves a process holding its output ends its run, and the process is killed") {
    const fs::path dir = fresh_dir("isolation_orphan");
    fs::create_directories(dir);
    const fs::path pid_file = dir / "orphan.pid";
    // The worker inherits the environment: the plug-in writes its child's pid there.
    const Cli r = binary({"--plugin", PLUGIN_CRASHING, "run", "--schemes", "bad_orphan", "--scenes", "asymmetric_free", "--dt", "0.05",
                          "--run-timeout", "20", "--out", (dir / "out").string()},
                         {"ROTBENCH_TEST_ORPHAN=" + pid_file.string()});
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(failures(dir / "out").at("bad_orphan").empty());  // the run's result, not a time-out waiting for the pipe to close
    REQUIRE(fs::exists(pid_file));
    const pid_t orphan = std::stoi(read(pid_file));
    REQUIRE(orphan > 1);
    // Killed with the worker's process group: gone, or a zombie left to whoever adopted it.
    const auto alive = [&] {
        std::ifstream stat("/proc/" + std::to_string(orphan) + "/stat");
        std::string pid_text, name, state;
        return stat >> pid_text >> name >> state && state != "Z";
    };
    for (int i = 0; i < 200 && alive(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const bool survived = alive();
    CHECK_FALSE(survived);
    if (survived) ::kill(orphan, SIGKILL);  // orphan > 1, checked above
    fs::remove_all(dir);
}

TEST_CASE("isolation: SIGINT, SIGTERM or SIGHUP stops a sweep whose plug-in hangs, and kills its worker") {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        const fs::path dir = fresh_dir("isolation_signal");
        const pid_t pid = ::fork();
        if (pid == 0) {
            if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) _exit(126);
            execl(ROTBENCH_EXE, ROTBENCH_EXE, "--plugin", PLUGIN_CRASHING, "run", "--schemes", "bad_hang", "--scenes",
                  "asymmetric_free", "--dt", "0.05", "--run-timeout", "600", "--out", dir.c_str(), nullptr);
            _exit(127);
        }
        while (!fs::exists(dir / "partial" / "runs.jsonl")) std::this_thread::sleep_for(std::chrono::milliseconds(5));
        const pid_t worker = child_of(pid);  // started, and hanging
        struct Reap {  // a failed check leaves neither hanging for ten minutes
            pid_t sweep, worker;
            ~Reap() {
                if (sweep > 0 && ::kill(sweep, SIGKILL) == 0) ::waitpid(sweep, nullptr, 0);  // never kill(-1)
                if (worker > 0) ::kill(worker, SIGKILL);
            }
        } reap{pid, worker};
        REQUIRE(worker > 0);
        const auto sent = std::chrono::steady_clock::now();
        ::kill(pid, signal);
        int status = 0;
        ::waitpid(pid, &status, 0);
        reap.sweep = -1;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
        CHECK(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 128 + signal);
        // The parent looks at signals every 0.1 s; 5 s is far from the 600 s the worker would hang.
        CHECK(seconds < 5.0);
        CHECK_FALSE(fs::exists("/proc/" + std::to_string(worker)));  // killed and reaped, not left behind
        reap.worker = -1;
        fs::remove_all(dir);
    }
}

TEST_CASE("isolation: `stability` records a plug-in that crashes or hangs as a failed case, and measures the rest") {
    const fs::path dir = fresh_dir("isolation_stability");
    // --run-timeout 3: bad_hang's case and its spectral curve each wait that long.
    const Cli r = cli({"stability", "--plugin", PLUGIN_CRASHING, "--schemes", "direct,bad_segfault,bad_hang", "--scenes",
                       "sphere_pair,fast_spin", "--zeta", "0", "--omega-max", "100", "--run-timeout", "3", "--jobs", "2", "--quiet",
                       "--out", dir.string()});
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto rows = stability_study(read_results(dir, stability_store), "store").rows;  // read back as `report` reads them
    std::map<std::string, int> failed, measured;
    for (const auto& row : rows) {
        INFO(row.scheme << " on " << row.scene);
        CHECK(row.dt_peng > 0);  // the scene's own prediction, whatever the scheme did
        if (row.scheme == "direct") {
            CHECK(stability_kind(row) == "sharp");
            CHECK(row.dt_empirical > 0);
            ++measured[row.scene];
        } else {
            CHECK(stability_kind(row) == "failed");
            CHECK(std::isnan(row.dt_empirical));
            ++failed[row.scene];
        }
    }
    CHECK(measured == std::map<std::string, int>{{"fast_spin", 1}, {"sphere_pair", 1}});
    CHECK(failed == std::map<std::string, int>{{"fast_spin", 2}, {"sphere_pair", 2}});
    const std::string md = read(dir / "stability.md");
    // Under AddressSanitizer a SIGSEGV becomes ASan's report and exit status 1.
    CHECK_THAT(md, Catch::Contains("`bad_segfault` on `sphere_pair` failed: ") &&
                       (Catch::Contains("signal 11") || Catch::Contains("exited with status 1")));
    CHECK_THAT(md, Catch::Contains("`bad_hang` on `fast_spin` failed: exceeded the run time limit of 3 s"));
    CHECK_THAT(md, Catch::Contains("`bad_hang`: no spectral curve; exceeded the run time limit of 3 s"));
    CHECK(fs::exists(dir / "plots" / "spectral_radius_sphere_pair.svg"));  // drawn for direct, without the failed curves
    fs::remove_all(dir);
}

TEST_CASE("isolation: `advise` does not recommend a plug-in that crashes, says why, and advises the other schemes") {
    const fs::path dir = fresh_dir("isolation_advise");
    const Cli r = cli({"advise", "--plugin", PLUGIN_CRASHING, "--schemes", "direct,bad_sound_segfault", "--inertia", "1,2,3",
                       "--mass", "1", "--stiffness", "1e4", "--tolerance", "1e-3", "--out", dir.string()});
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string json = read(dir / "advice.json");
    CHECK_THAT(json, Catch::Contains("\"scheme\": \"direct\""));
    CHECK_THAT(r.out, Catch::Contains("bad_sound_segfault: its stability search failed: "));
    fs::remove_all(dir);
}

TEST_CASE("isolation: a plug-in's stability case in a worker gives the in-process limits, bit for bit") {
    const fs::path dir = fresh_dir("isolation_stability_same");
    const std::vector<std::string> study = {"stability", "--plugin", PLUGIN_END_VELOCITY_ZVW, "--schemes", "zvw_end_velocity",
                                            "--scenes", "sphere_pair,fast_spin", "--zeta", "0.1", "--omega-max", "100", "--quiet",
                                            "--out"};
    auto isolated = study, in_process = study;
    isolated.push_back((dir / "isolated").string());
    in_process.push_back((dir / "in_process").string());
    REQUIRE(cli(isolated).status == 0);
    const std::string worker = worker_executable();
    set_worker_executable("");  // no worker: the plug-in's cases run in this process
    in_process.erase(in_process.begin() + 1, in_process.begin() + 3);
    const Cli local = cli(in_process);
    set_worker_executable(worker);
    REQUIRE(local.status == 0);
    for (const char* f : {"stability.csv", "stability_spin.csv", "plots/spectral_radius_sphere_pair.dat"}) {
        INFO(f);
        CHECK(read(dir / "isolated" / f) == read(dir / "in_process" / f));
    }
    CHECK_THAT(read(dir / "isolated" / "stability.csv"), Catch::Contains("zvw_end_velocity,0.1,sharp"));
    fs::remove_all(dir);
}

TEST_CASE("isolation: `trajectory` of a plug-in that crashes fails in one line and writes nothing, one that throws keeps its steps") {
    const fs::path dir = fresh_dir("isolation_trajectory");
    fs::create_directories(dir);
    const auto export_of = [&](const std::string& scheme) {
        return cli({"trajectory", "--plugin", PLUGIN_CRASHING, "--scene", "asymmetric_free", "--scheme", scheme, "--dt", "1e-2", "--out",
                    (dir / (scheme + ".csv")).string()});
    };
    const Cli crashed = export_of("bad_segfault");
    CHECK(crashed.status == 1);
    // Under the sanitizers the worker reports the null dereference and exits 1 instead of dying of SIGSEGV.
    CHECK_THAT(crashed.err, Catch::StartsWith("rotbench: loaded") && Catch::EndsWith("; nothing written\n") &&
                                Catch::Contains(memory_limit_enforced() ? "rotbench: bad_segfault crashed: signal 11 (Segmentation fault) in its worker process"
                                                                        : "rotbench: bad_segfault its worker exited with status 1 without a result"));
    CHECK_FALSE(fs::exists(dir / "bad_segfault.csv"));
    const Cli threw = export_of("bad_throw42");
    CHECK(threw.status == 0);
    CHECK_THAT(threw.err, Catch::Contains("bad_throw42 threw an exception that is not a std::exception (after step 0);"));
    const std::string rows = read(dir / "bad_throw42.csv");
    CHECK(std::count(rows.begin(), rows.end(), '\n') == 2);  // the header and t = 0
    fs::remove_all(dir);
}
