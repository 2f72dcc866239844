// `--plugin`: out-of-tree schemes are loaded after an ABI check; a missing, foreign or
// mismatched library is refused with one line and exit status 2; a plug-in scheme that
// throws or returns NaN is a failed run, never a crash.
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>

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
        {DEFAULT_GATE, "cannot load"},  // not a shared library at all
    };
    for (const auto& c : cases) {
        const Cli r = cli({"list", "--plugin", c.path});
        INFO(c.path);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::Contains(c.message));
    }
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
    fs::remove_all(dir);
}
