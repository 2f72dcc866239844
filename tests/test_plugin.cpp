// `--plugin`: out-of-tree schemes are loaded after an ABI check; a missing, foreign or
// mismatched library is refused with one line and exit status 2; a plug-in scheme that
// throws or returns NaN is a failed run, never a crash.
#include "tests/cli_helpers.hpp"

#include "harness/exec/isolation.hpp"
#include "schemes/plugin_abi.hpp"
#include "tests/skip.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <sys/resource.h>

using namespace rotbench;
using namespace rotbench::test;

TEST_CASE("plug-in: misbehaving schemes are loaded, run, and recorded as failed runs") {
    const fs::path dir = fresh_dir("plugin_run");
    const Cli r = cli({"run", "--plugin", PLUGIN_MISBEHAVING, "--schemes", "plugin_throws,plugin_nan,zvw", "--scenes",
                       "asymmetric_free", "--dt", "0.05,0.025", "--out", dir.string(), "--jobs", "2"});
    CHECK(r.status == 0);
    CHECK_THAT(r.err, Catch::Contains("loaded plugin_nan, plugin_throws from"));
    const std::string runs = read(dir / "runs.csv");
    CHECK_THAT(runs, Catch::Contains("bug in the plug-in"));
    CHECK_THAT(read(dir / "results.csv"), Catch::Contains("asymmetric_free,zvw,0.025,omega_err_max,"));
    fs::remove_all(dir);
}

TEST_CASE("plug-in: bad plug-ins give one line on stderr and exit status 2") {
    struct Case {
        std::string path, message;
    };
    const std::vector<Case> cases = {
        {"/nonexistent/plugin.so", "--plugin /nonexistent/plugin.so: no such file"},
        {PLUGIN_NOT_A_PLUGIN, "not a rotbench plug-in"},
        {PLUGIN_WRONG_ABI, "ABI mismatch: the plug-in was built for 'rotbench-plugin-abi 0;"},
        {DEFAULT_GATE, "not a shared library (no ELF header)"},  // refused on its first bytes
        {PLUGIN_NULL_ABI, "its rotbench_plugin_abi returned no text"},  // each was a SIGSEGV or an internal error, exit 4
        {PLUGIN_NULL_SCHEMES, "its rotbench_plugin_schemes returned NULL"},
        {PLUGIN_NULL_BUILD, "its rotbench_plugin_build returned NULL"},
    };
    for (const auto& c : cases) {
        const Cli r = cli({"list", "--plugin", c.path});
        INFO(c.path);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::Contains(c.message));
    }
}

TEST_CASE("plug-in: a file of gigabytes is hashed a block at a time, not read whole before dlopen") {
    if (!memory_limit_enforced()) ROTBENCH_SKIP("no memory limit holds here (AddressSanitizer's shadow memory takes it all)");
    const fs::path dir = fresh_dir("plugin_huge");
    fs::create_directories(dir);
    {
        std::ofstream huge(dir / "huge.so", std::ios::binary);
        huge.write("\x7f" "ELF", 4);  // a library's first bytes, so that it is hashed, not refused at once
        huge.seekp((std::streamoff(3) << 29) - 1);  // 1.5 GiB, sparse: no disk taken
        huge.put('\0');
    }
    // In 1 GiB of address space: reading it whole ran out of memory (exit 3); hashed in blocks, dlopen refuses it.
    const Cli r = binary({"--plugin", (dir / "huge.so").string(), "list"}, {}, [] {
        const rlimit limit{std::uint64_t(1) << 30, std::uint64_t(1) << 30};
        ::setrlimit(RLIMIT_AS, &limit);
    });
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK_THAT(r.err, Catch::Contains("cannot load"));
    fs::remove_all(dir);
}

TEST_CASE("plug-in: a scheme id another file registered is refused, and the same file twice is loaded once") {
    const Cli twice = cli({"list", "--plugin", PLUGIN_MISBEHAVING, "--plugin", PLUGIN_MISBEHAVING});
    CHECK(twice.status == 0);
    CHECK_THAT(twice.out, Catch::Contains("plugin_nan"));
    const fs::path dir = fresh_dir("plugin_copy"), copy = dir / "copy.so";  // the same ids from another file
    fs::create_directories(dir);
    fs::copy_file(PLUGIN_MISBEHAVING, copy);
    const Cli clash = cli({"list", "--plugin", PLUGIN_MISBEHAVING, "--plugin", copy.string()});
    CHECK(clash.status == 2);
    CHECK_THAT(clash.err, Catch::Contains("scheme 'plugin_"));
    CHECK_THAT(clash.err, Catch::Contains("is already registered"));
    // The same file through a symlink is the same plug-in, loaded once.
    fs::create_symlink(PLUGIN_MISBEHAVING, dir / "link.so");
    const Cli linked = cli({"list", "--plugin", PLUGIN_MISBEHAVING, "--plugin", (dir / "link.so").string()});
    CHECK(linked.status == 0);
    fs::remove_all(dir);
}

TEST_CASE("plug-in: a run remembers what it ran, so report and merge describe a plug-in without --plugin") {
    const fs::path dir = fresh_dir("plugin_remembered");
    const std::string run = (dir / "run").string(), stab = (dir / "run").string();
    const std::vector<std::string> common = {"--schemes", "zvw_end_velocity,direct", "--scenes", "asymmetric_free", "--quick"};
    std::vector<std::string> args = {"--plugin", PLUGIN_END_VELOCITY_ZVW, "run", "--out", run};
    args.insert(args.end(), common.begin(), common.end());
    REQUIRE(binary(args).status == 0);
    const std::string row = "| `zvw_end_velocity` | 2 → ";  // the claimed order beside the observed one
    CHECK_THAT(read(dir / "run" / "report.md"), Catch::Contains(row));
    // The candidate is drawn in a panel of its own, not beside the control among the others.
    const std::string plot = read(dir / "run" / "plots" / "convergence_asymmetric_free.gp");
    const auto candidates = plot.find("set title 'candidates'");
    REQUIRE(candidates != std::string::npos);
    CHECK(plot.find("title 'zvw_end_velocity'", candidates) < plot.find("set title", candidates + 1));
    const std::string recorded = read(dir / "run" / "schemes.json");
    CHECK_THAT(recorded, Catch::Contains("\"hash\"") && Catch::Contains("test_plugin_end_velocity_zvw") &&
                             Catch::Contains(ROTBENCH_PLUGIN_BUILD));  // built as this rotbench was
    // A built-in's registration is named within the source tree, the same on every machine.
    CHECK_THAT(recorded, Catch::Contains("\"declared_at\": \"schemes/direct.cpp:"));
    // A stability study written into the same folder, then the report re-rendered, all without --plugin.
    REQUIRE(binary({"--plugin", PLUGIN_END_VELOCITY_ZVW, "stability", "--schemes", "zvw_end_velocity", "--scenes", "sphere_pair",
                    "--zeta", "0", "--out", stab, "--overwrite", "--quiet"})
                .status == 0);
    const Cli report = binary({"report", run});
    INFO(report.out << report.err);
    REQUIRE(report.status == 0);
    const std::string md = read(dir / "run" / "report.md");
    CHECK_THAT(md, Catch::Contains(row));
    CHECK_THAT(md, Catch::Contains("Plug-in `") && Catch::Contains("built " ROTBENCH_PLUGIN_BUILD "."));
    // Two slices of a sweep, merged without --plugin.
    for (const std::string shard : {"1/2", "2/2"}) {
        std::vector<std::string> slice = {"--plugin", PLUGIN_END_VELOCITY_ZVW, "run", "--shard", shard,
                                          "--out", (dir / ("s" + shard.substr(0, 1))).string()};
        slice.insert(slice.end(), common.begin(), common.end());
        REQUIRE(binary(slice).status == 0);
    }
    REQUIRE(binary({"merge", (dir / "s1").string(), (dir / "s2").string(), "--out", (dir / "merged").string()}).status == 0);
    CHECK_THAT(read(dir / "merged" / "report.md"), Catch::Contains(row));
    CHECK(read(dir / "merged" / "schemes.json") == recorded);
    fs::remove_all(dir);
}

TEST_CASE("plug-in: a schemes.json that is not rotbench's is refused in one line") {
    const fs::path dir = fresh_dir("plugin_bad_schemes");
    REQUIRE(binary({"run", "--schemes", "direct", "--scenes", "asymmetric_free", "--quick", "--out", dir.string()}).status == 0);
    const std::string good = read(dir / "schemes.json");
    const std::string order = "\"order\": 1,";
    REQUIRE(good.find(order) != std::string::npos);
    std::string huge = good;
    huge.replace(huge.find(order), order.size(), "\"order\": 1e300,");  // would convert to int with undefined behaviour
    for (const std::string& bad : {std::string("{\"direct\": {\"summary\": 1}}"), std::string("[1]"), huge}) {
        write(dir / "schemes.json", bad);
        const Cli r = binary({"report", dir.string()});
        INFO(bad.substr(0, 80));
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::Contains("schemes.json: not a schemes.json rotbench wrote"));
    }
    fs::remove_all(dir);
}

TEST_CASE("plug-ins: the report's 'meets its claims' agrees with the gate on a plug-in that claims 2 and shows 1") {
    const fs::path dir = fresh_dir("plugin_meets_claims");
    const std::vector<std::string> schemes = {"--scenes", "asymmetric_free,tumbling_brick", "--schemes", "zvw_end_velocity,zvw_corrected"};
    std::vector<std::string> run = {"--plugin", PLUGIN_END_VELOCITY_ZVW, "run", "--quiet", "--out", (dir / "out").string()};
    run.insert(run.end(), schemes.begin(), schemes.end());
    const Cli r = cli(run);
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string md = read(dir / "out" / "report.md");
    const auto row = [&](const std::string& id) {
        const auto at = md.find("| `" + id + "` |");
        return at == std::string::npos ? std::string() : md.substr(at, md.find('\n', at) - at);
    };
    CHECK_THAT(row("zvw_end_velocity"), Catch::EndsWith("| **no**: order_without_torque on asymmetric_free; order_without_torque on tumbling_brick |"));
    CHECK_THAT(row("zvw_corrected"), Catch::EndsWith("| yes |"));
    // The gate, on the same scenes and ladders, fails the same claims.
    const Cli g = cli({"--plugin", PLUGIN_END_VELOCITY_ZVW, "gate", DEFAULT_GATE, "--schemes", "zvw_end_velocity"});
    CHECK(g.status == 1);
    CHECK_THAT(g.out, Catch::Contains("FAIL asymmetric_free/zvw_end_velocity: zvw_end_velocity: order_without_torque") &&
                          Catch::Contains("FAIL tumbling_brick/zvw_end_velocity: zvw_end_velocity: order_without_torque"));
    fs::remove_all(dir);
}
