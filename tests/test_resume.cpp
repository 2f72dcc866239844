// Nothing lost (issue 8): a sweep killed or interrupted part-way keeps every run it
// finished, and `rotbench run --resume DIR` ends with the files an uninterrupted run writes.
#include "harness/io/journal.hpp"
#include "harness/io/output_dir.hpp"
#include "harness/io/run_record.hpp"
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <limits>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace rotbench;
using namespace rotbench::test;

namespace {

// 56 runs of some 10 ms (48 on the ladders, and a horizon run for each scheme on dipole_top and
// asymmetric_free, where the claims judge energy): long enough to be cut in the middle. --quiet keeps progress lines
// (one every 5 s on a loaded machine) out of the stderr whose one line is checked.
const std::vector<std::string> sweep = {"run", "--scenes", "dipole_top,asymmetric_free,torqued_cylinder", "--schemes",
                                        "direct,zvw,no_squish,cayley", "--quick", "--jobs", "2", "--quiet"};
constexpr std::size_t sweep_runs = 56;

// The whole records of the journal's runs file (harness/io/run_record.hpp): one line each.
std::size_t finished_runs(const fs::path& journal) {
    std::ifstream in(journal / "runs.jsonl");
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);)
        if (!in.eof()) ++n;  // a last line without its line break is cut short
    return n;
}

// Starts the real binary on the sweep, sends `signal` once `runs` runs are on disk, and
// returns the exit status (128 + signal when the process ended on the signal).
int interrupted_run(const fs::path& out, int signal, std::size_t runs) {
    std::vector<std::string> args = {ROTBENCH_EXE};
    args.insert(args.end(), sweep.begin(), sweep.end());
    args.insert(args.end(), {"--out", out.string()});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        freopen("/dev/null", "w", stdout);
        freopen((out.string() + ".stderr").c_str(), "w", stderr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    while (finished_runs(out / "partial") < runs) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, signal);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

void same_outputs(const fs::path& a, const fs::path& b) {
    for (const char* f : {"results.csv", "runs.csv", "orders.csv", "local_orders.csv"}) {
        INFO(f);
        CHECK(without_timing(read(a / f)) == without_timing(read(b / f)));
    }
    for (const auto& e : fs::directory_iterator(a / "series")) {
        INFO(e.path().filename());
        CHECK(read(e.path()) == read(b / "series" / e.path().filename()));
    }
}

}  // namespace

TEST_CASE("an interrupted sweep keeps its finished runs, and --resume ends with an uninterrupted run's files") {
    const fs::path dir = fresh_dir("resume");
    std::vector<std::string> whole = sweep;
    whole.insert(whole.end(), {"--out", (dir / "whole").string()});
    REQUIRE(cli(whole).status == 0);
    CHECK_FALSE(fs::exists(dir / "whole" / "partial"));  // the journal goes once the outputs are written

    for (const int signal : {SIGINT, SIGTERM, SIGKILL}) {
        const fs::path out = dir / ("cut_by_" + std::to_string(signal));
        {
            INFO("signal " << signal);
            CHECK(interrupted_run(out, signal, 4) == 128 + signal);
            CHECK_FALSE(fs::exists(out / "results.csv"));  // no outputs of a part of the sweep
            const std::size_t kept = finished_runs(out / "partial");
            CHECK(kept >= 4);
            CHECK(kept < sweep_runs);
            if (signal != SIGKILL) {  // caught: it says what is kept and how to go on
                const std::string err = read(out.string() + ".stderr");
                CHECK(one_line(err));
                CHECK_THAT(err, Catch::Contains("rotbench run --resume " + out.string()));
            }
            // A new run into the directory would throw the finished runs away: refused.
            std::vector<std::string> again = sweep;
            again.insert(again.end(), {"--out", out.string()});
            const Cli refused = cli(again);
            CHECK(refused.status == 2);
            CHECK_THAT(refused.err, Catch::Contains("holds an interrupted run"));

            const Cli resumed = cli({"run", "--resume", out.string()});
            INFO(resumed.err);  // why, should it ever fail (it did once, on a loaded machine)
            REQUIRE(resumed.status == 0);
            CHECK_THAT(resumed.out, Catch::Contains("resuming: " + std::to_string(kept) + " of " + std::to_string(sweep_runs) + " runs were finished"));
            same_outputs(dir / "whole", out);
            CHECK_FALSE(fs::exists(out / "partial"));
        }
    }
    fs::remove_all(dir);
}

TEST_CASE("run --resume: bad uses are refused with one line") {
    const fs::path dir = fresh_dir("resume_bad");
    const Cli nothing = cli({"run", "--resume", dir.string()});
    CHECK(nothing.status == 2);
    CHECK_THAT(nothing.err, Catch::Contains("no interrupted run there"));
    CHECK(interrupted_run(dir, SIGINT, 2) == 130);
    const Cli extra = cli({"run", "--resume", dir.string(), "--schemes", "direct"});
    CHECK(extra.status == 2);
    CHECK_THAT(extra.err, Catch::Contains("--resume DIR takes no other option"));
    // The sweep its command describes must be the one that was cut short.
    write(dir / "partial" / "plan", "0000000000000000/1/1 48\n");
    const Cli changed = cli({"run", "--resume", dir.string()});
    CHECK(changed.status == 2);
    CHECK(one_line(changed.err));
    CHECK_THAT(changed.err, Catch::Contains("is not the one that was interrupted"));
    fs::remove_all(dir);
}

TEST_CASE("a journal record cut short by a kill counts as not finished and is cut off on resume") {
    const fs::path dir = fresh_dir("journal_cut");
    const RunResult a = run_one({"dipole_top", "direct", 1e-3, 0.01}, {.measure_time = false, .series_samples = 10});
    const RunResult b = run_one({"asymmetric_free", "zvw", 1e-2, 0.1}, {.measure_time = false});
    REQUIRE_FALSE(a.series.empty());
    const std::vector<RunSpec> plan = {a.spec, b.spec, b.spec};
    {
        const Journal journal = Journal::start(OutputDir::open(dir, {"run", "results.csv", {}}), {"run"}, "plan/1/1", plan);
        journal.record(0, a);
        journal.record(2, b);
    }
    const auto whole = fs::file_size(dir / "partial" / "runs.jsonl");
    std::ofstream(dir / "partial" / "runs.jsonl", std::ios::app) << R"({"index":1,"run":{"spec":{"scene":"dipole_to)";
    const Journal resumed = Journal::reopen(OutputDir::open(dir, {"run", "results.csv", {}, false, true}), "plan/1/1", plan);
    CHECK(fs::file_size(dir / "partial" / "runs.jsonl") == whole);  // the cut record is gone
    const auto runs = resumed.finished();
    REQUIRE(runs.size() == 2);
    CHECK(runs.at(0).spec.scheme == "direct");
    CHECK(runs.at(0).series == a.series);  // the energy series comes back whole
    CHECK(runs.at(0).value("energy_drift_max") == a.value("energy_drift_max"));
    CHECK(runs.at(2).value("omega_rms_x") == b.value("omega_rms_x"));
    resumed.record(1, b);
    CHECK(resumed.finished().size() == 3);
    fs::remove_all(dir);
}

TEST_CASE("journal records that do not belong to the plan are refused, naming the record") {
    const fs::path dir = fresh_dir("journal_foreign");
    const RunResult a = run_one({"asymmetric_free", "zvw", 1e-2, 0.1}, {.measure_time = false});
    const RunResult b = run_one({"asymmetric_free", "direct", 1e-2, 0.1}, {.measure_time = false});
    const auto refused = [&](const std::vector<RunSpec>& plan, const std::function<void(const Journal&)>& write) {
        fs::remove_all(dir);
        const Journal journal = Journal::start(OutputDir::open(dir, {"run", "results.csv", {}}), {"run"}, "p/1/1", plan);
        write(journal);
        try {
            journal.finished();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    CHECK_THAT(refused({a.spec}, [&](const Journal& j) { j.record(3, a); }), Catch::Contains("a record of run 3, and the plan has 1 runs"));
    CHECK_THAT(refused({a.spec}, [&](const Journal& j) { j.record(0, b); }), Catch::Contains("the record of run 0 is of asymmetric_free direct"));
    CHECK_THAT(refused({a.spec, a.spec}, [&](const Journal& j) { j.record(1, a), j.record(1, a); }), Catch::Contains("run 1 is recorded twice"));
    CHECK(refused({a.spec, a.spec}, [&](const Journal& j) { j.record(1, a), j.record(0, a); }).empty());
    fs::remove_all(dir);
}

TEST_CASE("the run store's record gives back every field of a run, bit for bit, NaN and infinities too") {
    RunResult a = run_one({"dipole_top", "direct", 1e-3, 0.01, {{"field", {0, 0, 2}}}}, {.measure_time = true, .series_samples = 10});
    a.spec.timed = false;
    a.metrics.emplace_back("odd", -INFINITY);
    a.metrics.emplace_back("odder", std::numeric_limits<double>::quiet_NaN());
    a.metrics.emplace_back("tiny", std::numeric_limits<double>::denorm_min());
    a.failure = "quoted \"text\", a line break\nand \x01 a control";
    a.snapshots = {{0.5, 1e-300, -0.0, 3, 4}};
    a.walls = {{0.5, 1, 2, 3, 4}};
    const RunRecords back = parse_run_records(run_record(7, a), "record");
    REQUIRE(back.runs.size() == 1);
    CHECK(back.runs[0].first == 7);
    const RunResult& b = back.runs[0].second;
    CHECK(b.spec == a.spec);
    REQUIRE(b.metrics.size() == a.metrics.size());
    for (std::size_t i = 0; i < a.metrics.size(); ++i) {
        CHECK(b.metrics[i].first == a.metrics[i].first);
        CHECK(std::memcmp(&b.metrics[i].second, &a.metrics[i].second, sizeof(double)) == 0);
    }
    CHECK(b.failure == a.failure);
    CHECK(b.series_columns == a.series_columns);
    CHECK(b.series == a.series);
    CHECK(std::signbit(b.snapshots[0][2]));
    CHECK(b.walls == a.walls);
    CHECK(b.timing_samples == a.timing_samples);
}

TEST_CASE("a journal line that is not a record ends the records, and one of the record's shape with a wrong value is refused") {
    const RunResult a = run_one({"asymmetric_free", "zvw", 1e-2, 0.1}, {.measure_time = false});
    const std::string record = run_record(0, a);
    CHECK(parse_run_records(record + "not json\n" + record, "j").runs.size() == 1);
    CHECK(parse_run_records(record + "{\"other\": 1}\n" + record, "j").runs.size() == 1);
    std::string wrong_kind = record;
    wrong_kind.replace(wrong_kind.find("\"trajectory\""), 12, "\"trajectorx\"");
    CHECK_THROWS_WITH(parse_run_records(wrong_kind, "j"), Catch::Contains("j: the record of run 0 is malformed"));
}
