// Nothing lost (issue 8): a sweep killed or interrupted part-way keeps every run it
// finished, and `rotbench run --resume DIR` ends with the files an uninterrupted run writes.
#include "harness/exec/executor.hpp"
#include "harness/store/journal.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/run_record.hpp"
#include "tests/cli_helpers.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <limits>
#include <fstream>
#include <sstream>
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

// The whole records of the journal's runs file (harness/store/run_record.hpp): one line each,
// after its header line.
std::size_t finished_runs(const fs::path& journal) {
    std::ifstream in(journal / "runs.jsonl");
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);)
        if (!in.eof() && line.rfind("{\"journal\"", 0) != 0) ++n;  // a last line without its line break is cut short
    return n;
}

// Starts the real binary on the command (the sweep by default), sends `signal` once `runs` runs
// are on disk, and returns the exit status (128 + signal when the process ended on the signal).
int interrupted_run(const fs::path& out, int signal, std::size_t runs, const std::vector<std::string>& command = sweep) {
    std::vector<std::string> args = {ROTBENCH_EXE};
    args.insert(args.end(), command.begin(), command.end());
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

TEST_CASE("an interrupted stability study keeps its finished runs, and run --resume ends with the uninterrupted study's files") {
    const fs::path dir = fresh_dir("resume_stability");
    const std::vector<std::string> study = {"stability", "--scenes", "sphere_pair", "--schemes", "direct,no_squish",
                                            "--zeta", "0,0.3", "--jobs", "2", "--quiet"};
    std::vector<std::string> whole = study;
    whole.insert(whole.end(), {"--out", (dir / "whole").string()});
    REQUIRE(cli(whole).status == 0);
    const fs::path out = dir / "cut";
    REQUIRE(interrupted_run(out, SIGTERM, 3, study) == 128 + SIGTERM);
    CHECK_THAT(read(out.string() + ".stderr"), Catch::Contains("rotbench run --resume " + out.string() + " finishes the work"));
    const std::size_t kept = finished_runs(out / "partial");
    const Cli resumed = cli({"run", "--resume", out.string()});
    INFO(resumed.err);
    REQUIRE(resumed.status == 0);
    // 4 searches, 4 amplification limits and 2 spectral curves, of which some were kept.
    CHECK_THAT(resumed.out, Catch::Contains("resuming: " + std::to_string(kept) + " of 10 runs were finished"));
    CHECK(read(out / "stability.csv") == read(dir / "whole" / "stability.csv"));
    CHECK(read(out / "plots" / "spectral_radius_sphere_pair.dat") == read(dir / "whole" / "plots" / "spectral_radius_sphere_pair.dat"));
    CHECK_FALSE(fs::exists(out / "partial"));
    fs::remove_all(dir);
}

TEST_CASE("an interrupted advise keeps its finished runs, and run --resume gives the uninterrupted advice") {
    const fs::path dir = fresh_dir("resume_advise");
    const std::vector<std::string> advise = {"advise", "--inertia", "1.25e-5,2.25e-5,2.6e-5", "--mass", "0.1", "--stiffness", "1e6",
                                             "--tolerance", "1e-3", "--schemes", "fincham,direct", "--jobs", "2"};
    std::vector<std::string> whole = advise;
    whole.insert(whole.end(), {"--out", (dir / "whole").string()});
    REQUIRE(cli(whole).status == 0);
    const fs::path out = dir / "cut";
    REQUIRE(interrupted_run(out, SIGINT, 3, advise) == 128 + SIGINT);
    const Cli resumed = cli({"run", "--resume", out.string()});
    INFO(resumed.err);
    REQUIRE(resumed.status == 0);
    // The rungs depend on the runs before them: each found in the journal by its key, the same
    // ladder is climbed again, and the same dt comes out (the timings are measured anew).
    const auto dts = [](const fs::path& file) {
        std::vector<std::pair<std::string, double>> found;
        const auto advice = nlohmann::json::parse(read(file));
        for (const auto& r : advice.at("recommendations"))
            found.emplace_back(r.at("scheme").get<std::string>(), r.at("dt").get<double>());
        std::sort(found.begin(), found.end());
        return found;
    };
    CHECK(dts(out / "advice.json") == dts(dir / "whole" / "advice.json"));
    CHECK(dts(out / "advice.json").size() == 2);
    CHECK_FALSE(fs::exists(out / "partial"));
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
    fs::remove_all(dir);
    fs::remove(dir.string() + ".stderr");
}

TEST_CASE("a journal record cut short by a kill counts as not finished and is cut off on resume") {
    const fs::path dir = fresh_dir("journal_cut");
    const RunResult a = run_one({"dipole_top", "direct", 1e-3, 0.01}, {.measure_time = false, .series_samples = 10});
    const RunResult b = run_one({"asymmetric_free", "zvw", 1e-2, 0.1}, {.measure_time = false});
    REQUIRE_FALSE(a.series.empty());
    {
        const Journal journal = Journal::start(OutputDir::open(dir, {"run", "results.csv", {}}), {"run"});
        journal.record(a);
    }
    const auto whole = fs::file_size(dir / "partial" / "runs.jsonl");
    std::ofstream(dir / "partial" / "runs.jsonl", std::ios::app) << R"({"index":1,"run":{"spec":{"scene":"dipole_to)";
    const Journal resumed = Journal::reopen(OutputDir::open(dir, {"run", "results.csv", {}, false, true}));
    CHECK(fs::file_size(dir / "partial" / "runs.jsonl") == whole);  // the cut record is gone
    auto runs = resumed.finished();
    REQUIRE(runs.size() == 1);
    CHECK(runs.at(a.spec).series == a.series);  // the energy series comes back whole
    CHECK(runs.at(a.spec).value("energy_drift_max") == a.value("energy_drift_max"));
    resumed.record(b);
    runs = resumed.finished();
    REQUIRE(runs.size() == 2);
    CHECK(runs.at(b.spec).value("omega_rms_x") == b.value("omega_rms_x"));
    CHECK(read(dir / "partial" / "runs.jsonl").find(R"({"index":1,)") != std::string::npos);  // the records are counted on
    fs::remove_all(dir);
}

TEST_CASE("a journal larger than any input file is read whole: no cap of its own loses a finished sweep") {
    const fs::path dir = fresh_dir("journal_big");
    const RunResult a = run_one({"asymmetric_free", "zvw", 1e-2, 0.1}, {.measure_time = false});
    Journal::start(OutputDir::open(dir, {"run", "results.csv", {}}), {"run"}).record(a);
    const fs::path runs = dir / "partial" / "runs.jsonl";
    const auto whole = fs::file_size(runs);
    fs::resize_file(runs, max_input_bytes + (1u << 20));  // a cut record past the cap (sparse: no disk)
    const Journal resumed = Journal::reopen(OutputDir::open(dir, {"run", "results.csv", {}, false, true}));
    CHECK(fs::file_size(runs) == whole);
    CHECK(resumed.finished().size() == 1);
    fs::remove_all(dir);
}

TEST_CASE("the executor takes a resumed command's finished runs from the journal, and makes only the rest") {
    const fs::path dir = fresh_dir("journal_keyed");
    const RunResult a = run_one({"asymmetric_free", "zvw", 1e-2, 0.1}, {.measure_time = false});
    RunResult forged = a;  // a finished run is taken as it is recorded: the forged value comes back
    forged.metrics = {{"omega_rms_x", 42.0}};
    {
        const Journal journal = Journal::start(OutputDir::open(dir, {"run", "results.csv", {}}), {"run"});
        journal.record(forged);
    }
    {
        std::ostringstream out, err;
        const RunSpec b{"asymmetric_free", "direct", 1e-2, 0.1};
        Executor executor(out, err, {.run = {.measure_time = false}},
                          Journal::reopen(OutputDir::open(dir, {"run", "results.csv", {}, false, true})));
        const auto runs = executor.run({b, a.spec, b});
        REQUIRE(runs.size() == 3);
        CHECK(runs[1].value("omega_rms_x") == 42.0);
        CHECK(runs[0].value("omega_rms_x") == run_one(b, {.measure_time = false}).value("omega_rms_x"));
        // A task given twice is made once: its CPU time, measured anew in every run, is the same.
        CHECK(runs[2].value("cpu_seconds_run") == runs[0].value("cpu_seconds_run"));
        CHECK_THAT(out.str(), Catch::Contains("resuming: 1 of 2 runs were finished"));
    }
    // A run recorded twice was not written by rotbench: the journal is refused, naming the record.
    Journal::start(OutputDir::open(dir, {"run", "results.csv", {}, true}), {"run"}).record(a);
    Journal::reopen(OutputDir::open(dir, {"run", "results.csv", {}, false, true})).record(a);
    CHECK_THROWS_WITH(Journal::reopen(OutputDir::open(dir, {"run", "results.csv", {}, false, true})),
                      Catch::Contains("runs.jsonl: record 1 is of asymmetric_free zvw trajectory dt=0.01, which is recorded already"));
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
