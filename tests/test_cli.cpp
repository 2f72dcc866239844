#include "harness/store/parse.hpp"
#include "harness/exec/run.hpp"
#include "schemes/scheme.hpp"
#include "tests/cli_helpers.hpp"
#include "harness/store/results_csv.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <set>
#include <sys/wait.h>

using namespace rotbench;
using namespace rotbench::test;
namespace fs = std::filesystem;


TEST_CASE("rotbench list names every scheme and scene") {
    const Cli r = cli({"list"});
    CHECK(r.status == 0);
    for (const char* id : {"direct", "munjiza_rk4", "zvw", "zvw_corrected", "cylinder_free"}) CHECK_THAT(r.out, Catch::Contains(id));
}

TEST_CASE("rotbench run writes results.csv (tidy contract) and report.md, and never clobbers silently") {
    const fs::path dir = fresh_dir("run");
    const std::vector<std::string> args = {"run", "--scenes", "cylinder_free", "--schemes", "direct,zvw_corrected",
                                           "--dt", "1e-2,1e-3", "--out", dir.string()};
    const Cli r = cli(args);
    REQUIRE(r.status == 0);
    const std::string csv = read(dir / "results.csv");
    CHECK(csv.rfind("scene,scheme,dt,metric,value\n", 0) == 0);
    CHECK_THAT(csv, Catch::Contains("cylinder_free,direct,0.01,omega_rms_x,0.66"));
    CHECK_THAT(csv, Catch::Contains("cylinder_free,zvw_corrected,0.001,unstable,0\n"));
    const std::string report = read(dir / "report.md");
    CHECK_THAT(report, Catch::Contains("## Scene `cylinder_free`"));
    CHECK_THAT(report, Catch::Contains("## Seed Table 1 reproduced"));

    const Cli again = cli(args);
    CHECK(again.status == 2);
    CHECK_THAT(again.err, Catch::Contains("already holds results.csv"));
    CHECK(read(dir / "results.csv") == csv);

    std::vector<std::string> overwrite = args;
    overwrite.push_back("--overwrite");
    CHECK(cli(overwrite).status == 0);
    fs::remove_all(dir);
}

TEST_CASE("the installed binary exits with status 2 on bad input") {
    const std::string command = std::string(ROTBENCH_EXE) + " run --dt 0 > /dev/null 2>&1";
    const int raw = std::system(command.c_str());
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 2);
}

TEST_CASE("rotbench report DIR re-renders the same report from the CSVs, and writes orders.csv") {
    const fs::path dir = fresh_dir("rerender");
    REQUIRE(cli({"run", "--scenes", "dipole_top,fibre_bounce", "--schemes", "direct,zvw", "--quick", "--out", dir.string()}).status == 0);
    const std::string orders = read(dir / "orders.csv");
    CHECK(orders.rfind("scene,scheme,metric,status,order,order_lo,order_hi,dt_min,dt_max,points\n", 0) == 0);
    CHECK_THAT(orders, Catch::Contains("dipole_top,direct,omega_err_max,"));
    auto body = [](std::string md) {  // without the header paragraph: its provenance and command differ
        std::string out, line;
        std::istringstream in(md);
        while (std::getline(in, line))
            if (line.find(" UTC by `") == std::string::npos) out += line + "\n";
        return out;
    };
    const std::string first = body(read(dir / "report.md"));
    REQUIRE(cli({"report", dir.string()}).status == 0);
    CHECK(body(read(dir / "report.md")) == first);
    CHECK(cli({"report", (dir / "missing").string()}).status == 2);
    fs::remove_all(dir);
}

TEST_CASE("rotbench stability writes stability.csv with the contract header, and rejects bad input") {
    const fs::path dir = fresh_dir("stability");
    REQUIRE(cli({"stability", "--scenes", "sphere_pair", "--schemes", "direct", "--zeta", "0", "--out", dir.string()}).status == 0);
    const std::string csv = read(dir / "stability.csv");
    CHECK(csv.rfind("scene,scheme,zeta,kind,dt_empirical,dt_amplification,dt_peng,dt_verlet_normal\n", 0) == 0);
    CHECK_THAT(read(dir / "stability.md"), Catch::Contains("## Stability limits"));
    CHECK(cli({"stability", "--scenes", "cylinder_free", "--out", (dir / "x").string()}).status == 2);
    CHECK(cli({"stability", "--zeta", "-1", "--out", (dir / "y").string()}).status == 2);
    CHECK(cli({"stability", "--scenes", "sphere_pair", "--schemes", "direct", "--zeta", "0", "--out", dir.string()}).status == 2);
    fs::remove_all(dir);
}

TEST_CASE("run --shard K/N and merge give the outputs of the unsharded run, timings aside") {
    const fs::path dir = fresh_dir("shard");
    const std::vector<std::string> sweep = {"--scenes", "asymmetric_free,dipole_top", "--schemes", "direct,zvw,no_squish",
                                            "--quick", "--jobs", "2"};
    const auto run = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = {"run"};
        args.insert(args.end(), sweep.begin(), sweep.end());
        args.insert(args.end(), extra.begin(), extra.end());
        return cli(args);
    };
    REQUIRE(run({"--out", (dir / "full").string()}).status == 0);
    for (const char* k : {"1/3", "2/3", "3/3"}) REQUIRE(run({"--shard", k, "--out", (dir / ("s" + std::string(1, k[0]))).string()}).status == 0);
    CHECK_FALSE(fs::exists(dir / "s1" / "report.md"));  // a slice has no orders or report of its own
    const Cli merged = cli({"merge", (dir / "s3").string(), (dir / "s1").string(), (dir / "s2").string(), "--out", (dir / "m").string()});
    REQUIRE(merged.status == 0);
    for (const char* f : {"results.csv", "runs.csv", "orders.csv", "local_orders.csv"}) {
        INFO(f);
        CHECK(without_timing(read(dir / "m" / f)) == without_timing(read(dir / "full" / f)));
    }
    CHECK(fs::exists(dir / "m" / "report.md"));

    // Slices that do not make one sweep are refused.
    const Cli missing = cli({"merge", (dir / "s1").string(), (dir / "s2").string(), "--out", (dir / "m2").string()});
    CHECK(missing.status == 2);
    CHECK_THAT(missing.err, Catch::Contains("shard(s) 3 of 3 missing"));
    const Cli twice = cli({"merge", (dir / "s1").string(), (dir / "s1").string(), "--out", (dir / "m2").string()});
    CHECK(twice.status == 2);
    CHECK_THAT(twice.err, Catch::Contains("shard 1 is given twice"));
    REQUIRE(cli({"run", "--scenes", "asymmetric_free", "--schemes", "zvw", "--quick", "--shard", "2/3", "--out", (dir / "other").string()}).status == 0);
    const Cli foreign = cli({"merge", (dir / "s1").string(), (dir / "other").string(), (dir / "s3").string(), "--out", (dir / "m2").string()});
    CHECK(foreign.status == 2);
    CHECK_THAT(foreign.err, Catch::Contains("a slice of another sweep"));
    const Cli not_a_shard = cli({"merge", (dir / "s1").string(), (dir / "full").string(), "--out", (dir / "m2").string()});
    CHECK(not_a_shard.status == 2);
    CHECK_THAT(not_a_shard.err, Catch::Contains("is a whole run, not a slice"));
    for (const char* bad : {"0/2", "3/2", "1/0", "a/b", "2", "1/2/3", "-1/2"}) {
        const Cli r = cli({"run", "--scenes", "asymmetric_free", "--quick", "--shard", bad, "--out", (dir / "bad").string()});
        INFO(bad);
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Catch::Contains("expected K/N with integers 1 <= K <= N"));
    }
    CHECK_FALSE(fs::exists(dir / "bad"));
    // More shards than runs would leave a slice empty, which merge could not place.
    const Cli too_many = cli({"run", "--scenes", "torqued_cylinder", "--schemes", "zvw", "--dt", "0.1", "--shard", "1/2", "--out",
                              (dir / "bad").string()});
    CHECK(too_many.status == 2);
    CHECK_THAT(too_many.err, Catch::Contains("the sweep has only 1 run(s), so at most 1 shard(s)"));
    CHECK_FALSE(fs::exists(dir / "bad"));
    fs::remove_all(dir);
}

namespace {
// A scheme with an id longer than the list's default column, to keep the columns honest.
template <class S = double>
struct Idle {
    template <class T>
    using rebind = Idle<T>;
    struct Memory {};
    static void start(const RigidBodyT<S>&, Memory&) {}
    static void predict(RigidBodyT<S>&, Memory&, double) {}
    static void correct(RigidBodyT<S>&, Memory&, double) {}
};
const RegisterScheme<Idle<>> long_id("test_a_scheme_with_a_very_long_identifier", "test only: does nothing", "tests", "",
                                     {.sound = false});
}  // namespace

TEST_CASE("rotbench list keeps its columns aligned whatever the length of the ids") {
    const Cli r = cli({"list"});
    REQUIRE(r.status == 0);
    // Every entry is two lines, the summary and the source, both starting at one column.
    std::istringstream in(r.out);
    std::set<std::size_t> columns;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("  ", 0) != 0) continue;  // headings
        const std::size_t id_end = line.find_first_not_of(' ', 2) == 2 ? line.find(' ', 2) : 2;
        columns.insert(line.find_first_not_of(' ', id_end));
    }
    CHECK(columns.size() == 1);
    CHECK(*columns.begin() == 2 + std::string("test_a_scheme_with_a_very_long_identifier").size() + 1);
}

TEST_CASE("rotbench --version names the version, the commit, the compiler and the flags") {
    const Cli r = cli({"--version"});
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::StartsWith("rotbench 0."));
    CHECK_THAT(r.out, Catch::Contains("(commit "));
    CHECK_THAT(r.out, Catch::Contains("compiler GNU") || Catch::Contains("compiler Clang"));
    CHECK_THAT(r.out, Catch::Contains("-ffp-contract=off"));
}

TEST_CASE("merge joins whole runs, each run once, and no slice among them") {
    const fs::path dir = fresh_dir("merge_whole_run");
    const auto run = [&](const char* scheme, const char* out) {
        return binary({"run", "--schemes", scheme, "--scenes", "asymmetric_free", "--quick", "--out", (dir / out).string()}).status;
    };
    REQUIRE(run("direct", "a") == 0);
    REQUIRE(run("zvw", "b") == 0);
    REQUIRE(binary({"merge", (dir / "a").string(), (dir / "b").string(), "--out", (dir / "m").string()}).status == 0);
    const auto joined = read_results(dir / "m"), a = read_results(dir / "a"), b = read_results(dir / "b");
    REQUIRE(joined.size() == a.size() + b.size());
    CHECK(joined.front().spec == a.front().spec);
    CHECK(joined.back().spec == b.back().spec);
    CHECK_THAT(read(dir / "m" / "report.md"), Catch::Contains("| `direct` |") && Catch::Contains("| `zvw` |"));
    const Cli twice = binary({"merge", (dir / "a").string(), (dir / "a").string(), "--out", (dir / "twice").string()});
    CHECK(twice.status == 2);
    CHECK(one_line(twice.err));
    CHECK_THAT(twice.err, Catch::Contains("is in both") && Catch::Contains("--set SCENE.seed=N"));
    CHECK_FALSE(fs::exists(dir / "twice"));
    fs::remove_all(dir);
}
