// The bad-input matrix (issue 8; README "Bad input"): every row is one mistake a user can
// make on the command line or in a file. Each gives exit status 2 and one line on stderr
// that names the option, key or file (with line and column for TOML) and, for an unknown
// id, lists the valid ones; and nothing is written. Gate-file mistakes have their own
// table in test_gate.cpp, plug-ins in test_plugin.cpp, scene parameters in test_scenes.cpp.
#include "harness/cli/verb.hpp"
#include "harness/scenes/scene.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "schemes/scheme.hpp"
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>

using namespace rotbench;
using namespace rotbench::test;

namespace {

struct Row {
    std::vector<std::string> args;
    std::string message;  // a part of the one line on stderr
};

// Runs every row; `out` must not exist before or after any of them.
void check_rows(const std::vector<Row>& rows, const fs::path& out) {
    for (const auto& row : rows) {
        const Cli r = cli(row.args);
        std::string shown;
        for (const auto& a : row.args) shown += a + " ";
        INFO(shown << "-> " << r.err);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::Contains(row.message));
        CHECK_FALSE(fs::exists(out));
    }
}

// The ids a registry holds, as the error lists them (every one, in its order).
template <class R>
std::string valid(const R& registry) {
    return join(registry.ids(), ", ");
}

}  // namespace

TEST_CASE("bad input: unknown ids are named and the valid ones listed") {
    const fs::path dir = fresh_dir("bad_ids");
    const std::string out = (dir / "out").string(), file = (dir / "out" / "x.csv").string();
    const std::string scenes = valid(SceneRegistry::instance()), schemes = valid(SchemeRegistry::instance());
    std::vector<std::string> stability_scenes;
    for (const auto& id : SceneRegistry::instance().ids())
        if (dynamic_cast<const StabilityProbe*>(make_scene(id).get())) stability_scenes.push_back(id);
    check_rows(
        {
            {{"run", "--scenes", "cylinder", "--out", out}, "unknown scene 'cylinder'; valid scenes: " + scenes},
            {{"run", "--schemes", "direct,verlet", "--out", out}, "unknown scheme 'verlet'; valid schemes: " + schemes},
            {{"reference", "--scene", "nope", "--out", file}, "valid scenes: " + scenes},
            {{"trajectory", "--scene", "cylinder_free", "--scheme", "rk4", "--dt", "1e-3", "--out", file}, "valid schemes: " + schemes},
            {{"list", "--params", "nope"}, "valid scenes: " + scenes},
            {{"stability", "--scenes", "cylinder_free", "--out", out}, "not a stability scene; valid: " + join(stability_scenes, ", ")},
            {{"stability", "--schemes", "verlet", "--out", out}, "valid schemes: " + schemes},
            {{"run", "--set", "nope.mass=1", "--out", out}, "unknown scene 'nope'; valid scenes: " + scenes},
            {{"run", "--set", "cylinder_free.spin=1", "--out", out}, "unknown parameter 'cylinder_free.spin'"},
            {{"frobnicate"}, "unknown command 'frobnicate'; valid commands: " + join(user_verbs(), ", ")},
            {{"run", "--bogus", "--out", out}, "--bogus"},
        },
        dir / "out");
    // Metric ids are named in gate files: test_gate.cpp ("unknown metric 'omega_err'; valid metrics: ...").
}

TEST_CASE("bad input: numbers that are negative, zero, NaN, inf, empty, duplicated or unparsable") {
    const fs::path dir = fresh_dir("bad_numbers");
    const std::string out = (dir / "out").string(), file = (dir / "out" / "x.csv").string();
    const auto run = [&](std::vector<std::string> args) {
        args.insert(args.begin(), "run");
        args.insert(args.end(), {"--out", out});
        return args;
    };
    check_rows(
        {
            {run({"--dt", "0"}), "--dt: '0' must be a finite number greater than 0"},
            {run({"--dt", "-1e-3"}), "--dt: '-1e-3' must be a finite number greater than 0"},
            {run({"--dt", "nan"}), "--dt: 'nan' must be a finite number greater than 0"},
            {run({"--dt", "inf"}), "--dt: 'inf' must be a finite number greater than 0"},
            {run({"--dt", ""}), "--dt: the value is empty"},
            {run({"--dt", "1e-3,"}), "--dt: '' is not a number"},
            {run({"--dt", "1e-3,1e-3"}), "--dt: 1e-3 is given twice"},
            {run({"--dt", "abc"}), "--dt: 'abc' is not a number"},
            {run({"--dt", "1e-3s"}), "--dt: '1e-3s' is not a number"},
            {run({"--t-end", "0"}), "--t-end: '0' must be a finite number greater than 0"},
            {run({"--t-end", "-2"}), "--t-end: '-2' must be a finite number greater than 0"},
            {run({"--t-end", "fast"}), "--t-end: 'fast' is not a number"},
            {run({"--scenes", ""}), "--scenes: the value is empty"},
            {run({"--schemes", "direct,direct"}), "given twice"},
            {run({"--set", "cylinder_free.omega0=1,2,nan"}), "--set cylinder_free.omega0: 'nan' must be a finite number"},
            {run({"--set", "cylinder_free.omega0=1,2,inf"}), "--set cylinder_free.omega0: 'inf' must be a finite number"},
            {run({"--set", "cylinder_free.omega0="}), "--set cylinder_free.omega0: '' is not a number"},
            {run({"--set", "cylinder_free.omega0=1,2"}), "cylinder_free.omega0: expects 3 values"},
            {run({"--set", "cylinder_free.inertia=-1,1,1"}), "cylinder_free.inertia"},
            {run({"--set", "cylinder_free.omega0"}), "expected SCENE.KEY=VALUE"},
            {run({"--jobs", "0"}), "--jobs: Value 0 not in range 1 to 1024"},
            {run({"--jobs", "two"}), "--jobs"},
            {run({"--energy-series", "-1"}), "--energy-series: Value -1 not in range 0 to 1000000"},
            {run({"--shard", "0/2"}), "expected K/N with integers 1 <= K <= N"},
            {{"stability", "--zeta", "-0.1", "--out", out}, "--zeta: '-0.1' must not be negative"},
            {{"stability", "--zeta", "0.1,0.1", "--out", out}, "--zeta: 0.1 is given twice"},
            {{"stability", "--zeta", "nan", "--out", out}, "--zeta: 'nan' must be a finite number"},
            {{"stability", "--omega-max", "0", "--out", out}, "--omega-max: '0' must be a finite number greater than 0"},
            {{"reference", "--scene", "cylinder_free", "--samples", "0", "--out", file}, "--samples must be 1 to 1000000, not 0"},
            {{"trajectory", "--scene", "cylinder_free", "--scheme", "direct", "--dt", "1e-3", "--samples", "2000000000", "--out", file},
             "--samples must be 1 to 1000000, not 2000000000"},
            {{"reference", "--scene", "silo_discharge", "--out", file}, "a granular scene has no reference trajectory"},
            {{"reference", "--scene", "direct_shear", "--out", file}, "a granular scene has no reference trajectory"},
            {{"trajectory", "--scene", "cylinder_free", "--scheme", "direct", "--dt", "-1", "--out", file}, "--dt: '-1' must be"},
        },
        dir / "out");
}

TEST_CASE("bad input: a duration shorter than the time step (one that is not a multiple follows the step-count rule)") {
    const fs::path dir = fresh_dir("bad_duration");
    check_rows({{{"run", "--scenes", "cylinder_free", "--dt", "1e-2", "--t-end", "1e-3", "--out", (dir / "out").string()},
                 "t-end 0.001 is shorter than the time step 0.01"}},
               dir / "out");
    // Not a multiple is not an error: N = ceil(t_end/dt) steps (README "Use"), so the run
    // covers t_end; 0.5 s at 0.3 s is 2 steps.
    REQUIRE(cli({"run", "--scenes", "cylinder_free", "--schemes", "direct", "--dt", "0.3", "--out", (dir / "ok").string()}).status == 0);
    CHECK_THAT(read(dir / "ok" / "results.csv"), Catch::Contains("cylinder_free,direct,0.3,steps,2\n"));
    fs::remove_all(dir);
}

TEST_CASE("bad input: config files that are malformed, have unknown keys or wrong types, or are missing") {
    const fs::path dir = fresh_dir("bad_config");
    fs::create_directories(dir);
    const std::string out = (dir / "out").string();
    const auto config = [&](const std::string& name, const std::string& text) {
        write(dir / name, text);
        return std::vector<std::string>{"run", "--config", (dir / name).string(), "--out", out};
    };
    check_rows(
        {
            {config("a.toml", "[run\n"), "a.toml:1:"},
            {config("b.toml", "[run]\ndt = [1e-3,\n"), "b.toml:2:"},
            {config("c.toml", "[run]\nbogus = 1\n"), "c.toml:2:9: unknown key 'bogus' in [run]; valid keys: scenes, schemes, dt, t_end"},
            {config("d.toml", "[nowhere]\nx = 1\n"), "d.toml:1:1: unknown table [nowhere]; valid tables: run, " + valid(SceneRegistry::instance())},
            {config("e.toml", "[run]\nt_end = \"long\"\n"), "e.toml:2:9: 't_end' must be a number"},
            {config("f.toml", "[dipole_top]\nfield = \"up\"\n"), "f.toml:2:9: 'field' must be a number"},
            {config("g.toml", "[run]\ndt = [1e-3, 1e-3]\n"), "g.toml:2:6: 'dt': 0.001 is given twice"},
            {config("h.toml", "[run]\ndt = []\n"), "h.toml:2:6: 'dt' is an empty array"},
            {config("i.toml", "[run]\nt_end = nan\n"), "i.toml:2:9: 't_end' must be one finite number greater than 0"},
            {config("j.toml", "[run]\nschemes = [\"verlet\"]\n"), "j.toml:2:"},
            {config("k.toml", "[run]\ndt = 1\ndt = 2\n"), "k.toml:3:"},  // a key given twice
            {{"run", "--config", (dir / "absent.toml").string(), "--out", out}, "absent.toml: cannot read the file"},
            {{"run", "--config", dir.string(), "--out", out}, "not a regular file (a directory)"},
            {{"run", "--config", "", "--out", out}, "--config: the value is empty"},
        },
        dir / "out");
    fs::remove_all(dir);
}

TEST_CASE("bad input: missing or unreadable input files and directories") {
    const fs::path dir = fresh_dir("bad_files");
    fs::create_directories(dir / "not_results");
    write(dir / "not_results" / "runs.jsonl", "scene,scheme\n");
    const std::string out = (dir / "out").string();
    check_rows(
        {
            {{"gate", (dir / "absent.toml").string()}, "absent.toml: cannot read the file"},
            {{"gate", dir.string()}, "not a regular file (a directory)"},
            {{"report", (dir / "absent").string()}, "cannot read " + (dir / "absent" / "runs.jsonl").string()},
            {{"report", (dir / "not_results").string()}, "runs.jsonl: cut short or not a run store after 0 runs"},
            {{"merge", (dir / "absent").string(), "--out", out}, "cannot read " + (dir / "absent" / "runs.jsonl").string()},
            {{"list", "--plugin", (dir / "absent.so").string()}, "no such file"},
        },
        dir / "out");
    fs::remove_all(dir);
}

TEST_CASE("bad input: output directories that hold results, are files, or cannot be written") {
    const fs::path dir = fresh_dir("bad_outputs");
    fs::create_directories(dir / "full");
    for (const char* f : {"results.csv", "stability.csv", "gate.csv"}) write(dir / "full" / f, "kept\n");
    write(dir / "file", "kept\n");
    const std::string full = (dir / "full").string(), file = (dir / "file").string(), under_file = (dir / "file" / "sub").string();
    const std::vector<std::string> one_run = {"--scenes", "cylinder_free", "--schemes", "direct", "--dt", "1e-2"};
    const auto run = [&](const std::string& out) {
        std::vector<std::string> args = {"run"};
        args.insert(args.end(), one_run.begin(), one_run.end());
        args.insert(args.end(), {"--out", out});
        return args;
    };
    check_rows(
        {
            // A directory of files rotbench did not write (no manifest): refused, and with --overwrite
            // still none of those files is replaced.
            {run(full), "--out " + full + " holds files rotbench did not write"},
            {{"stability", "--scenes", "sphere_pair", "--schemes", "direct", "--out", full}, "holds files rotbench did not write"},
            {{"gate", DEFAULT_GATE, "--out", full}, "holds files rotbench did not write"},
            {[&] {
                 auto args = run(full);
                 args.push_back("--overwrite");
                 return args;
             }(),
             full + "/results.csv exists and was not written by rotbench; it is never replaced"},
            {run(file), "--out " + file + ": cannot create the directory"},
            {run(under_file), "cannot create the directory"},
            {run("/proc/rotbench"), "cannot create the directory"},
            {run("/proc"), "--out /proc holds files rotbench did not write"},
            {[&] {
                 auto args = run("/proc");
                 args.push_back("--overwrite");
                 return args;
             }(),
             "--out /proc: the directory is not writable"},
            {{"stability", "--scenes", "sphere_pair", "--schemes", "direct", "--out", "/proc", "--overwrite"}, "not writable"},
            {{"gate", DEFAULT_GATE, "--junit", file + "/j.xml"}, "--junit " + file + "/j.xml: " + file + " is not a directory"},
            {{"reference", "--scene", "cylinder_free", "--out", file + "/sub/r.csv"}, "--out " + file + "/sub/r.csv: cannot create the directory"},
        },
        dir / "absent");
    for (const char* f : {"results.csv", "stability.csv", "gate.csv"}) CHECK(read(dir / "full" / f) == "kept\n");
    CHECK(read(dir / "file") == "kept\n");
    fs::remove_all(dir);
}

TEST_CASE("bad input found only by running is found before: the last ensemble seed, the CI step summary") {
    const fs::path dir = fresh_dir("bad_before_work");
    const std::string out = (dir / "out").string();
    // Each seed alone is valid; the ensemble's last is not (seeds stay below 9e15).
    check_rows({{{"run", "--scenes", "silo_discharge", "--schemes", "direct", "--quick", "--set", "silo_discharge.seed=8999999999999999",
                  "--ensemble", "3", "--out", out},
                 "--ensemble 3 from seed 8999999999999999: silo_discharge.seed: must be a whole number"}},
               out);
    ::setenv("GITHUB_STEP_SUMMARY", (dir / "absent" / "summary.md").c_str(), 1);
    check_rows({{{"gate", (fs::path(ROTBENCH_SOURCE_DIR) / "gates" / "default.toml").string(), "--schemes", "direct", "--out", out},
                 "$GITHUB_STEP_SUMMARY: cannot write " + (dir / "absent" / "summary.md").string()}},
               out);
    ::unsetenv("GITHUB_STEP_SUMMARY");
    fs::remove_all(dir);
}

TEST_CASE("missing folders of gate --junit and reference --out are made, as --out makes its own") {
    const fs::path dir = fresh_dir("missing_parents");
    const Cli gate = binary({"gate", DEFAULT_GATE, "--schemes", "no_gyro", "--junit", (dir / "ci" / "reports" / "gate.xml").string()});
    INFO(gate.out << gate.err);
    CHECK(fs::is_regular_file(dir / "ci" / "reports" / "gate.xml"));
    CHECK(fs::is_regular_file(dir / "ci" / "reports" / "summary.json"));
    const Cli reference = binary({"reference", "--scene", "cylinder_free", "--samples", "10", "--out", (dir / "refs" / "r.csv").string()});
    CHECK(reference.status == 0);
    CHECK(fs::is_regular_file(dir / "refs" / "r.csv"));
    // Made when written, not when checked: a command refused for another output leaves none.
    std::ofstream(dir / "notes.md") << "kept\n";
    const Cli refused = binary({"gate", DEFAULT_GATE, "--schemes", "no_gyro", "--junit", (dir / "new" / "sub" / "gate.xml").string(),
                                "--summary", (dir / "notes.md").string(), "--overwrite"});
    CHECK(refused.status == 2);
    CHECK(refused.err.find("is not a file rotbench wrote") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "new"));
    CHECK(read(dir / "notes.md") == "kept\n");
    fs::remove_all(dir);
}
