#include "cli_helpers.hpp"
#include "harness/cli/config.hpp"
#include "harness/gate/gate_file.hpp"
#include "harness/exec/export.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rotbench;
using namespace rotbench::test;
namespace fs = std::filesystem;

namespace {

std::string write_temp(const std::string& name, const std::string& text) {
    static const RemovedAtExit folder{fresh_dir("config")};
    fs::create_directories(folder.path);
    const fs::path path = folder.path / name;
    std::ofstream(path) << text;
    return path.string();
}

std::string error_of(const std::string& toml) {
    try {
        load_config(write_temp("bad.toml", toml));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a TOML config selects runs and sets scene parameters") {
    const SweepSpec spec = load_config(write_temp("good.toml",
                                                  "[run]\nscenes = [\"dipole_top\"]\nschemes = [\"direct\", \"zvw\"]\n"
                                                  "dt = [1e-2, 0.005]\nt_end = 2\n[dipole_top]\nfield = [0, 0, 2]\n"));
    CHECK(spec.scenes == std::vector<std::string>{"dipole_top"});
    CHECK(spec.schemes == std::vector<std::string>{"direct", "zvw"});
    CHECK(spec.dts == std::vector<double>{1e-2, 0.005});
    CHECK(spec.t_end == 2.0);
    REQUIRE(spec.params.at("dipole_top").size() == 1);
    CHECK(spec.params.at("dipole_top")[0].second == std::vector<double>{0, 0, 2});
}

TEST_CASE("config errors name the file, line and column, and the key") {
    CHECK_THAT(error_of("[run\n"), Catch::Contains("bad.toml:1:"));
    CHECK_THAT(error_of("[run]\nbogus = 1\n"), Catch::Contains(":2:") && Catch::Contains("unknown key 'bogus'"));
    CHECK_THAT(error_of("[run]\ndt = [1e-3, -1]\n"), Catch::Contains(":2:") && Catch::Contains("greater than 0"));
    CHECK_THAT(error_of("[run]\nschemes = [\"verlet\"]\n"), Catch::Contains(":2:") && Catch::Contains("valid schemes"));
    CHECK_THAT(error_of("[nowhere]\nx = 1\n"), Catch::Contains(":1:") && Catch::Contains("unknown table [nowhere]"));
    CHECK_THAT(error_of("[dipole_top]\nfield = [0, 0]\n"), Catch::Contains(":2:") && Catch::Contains("dipole_top.field: expects 3 values"));
    CHECK_THAT(error_of("[dipole_top]\nfield = \"up\"\n"), Catch::Contains(":2:") && Catch::Contains("'field' must be a number"));
    CHECK_THAT(error_of("[dipole_top]\nmass = 3\n"), Catch::Contains("unknown parameter 'dipole_top.mass'"));
}

TEST_CASE("the option --set SCENE.KEY=VALUE") {
    SweepSpec spec;
    add_setting(spec, "torqued_cylinder.omega0=1,-2.5,3");
    CHECK(spec.params.at("torqued_cylinder")[0].second == std::vector<double>{1, -2.5, 3});
    CHECK_THROWS_WITH(add_setting(spec, "torqued_cylinder.omega0"), Catch::Contains("expected SCENE.KEY=VALUE"));
    CHECK_THROWS_WITH(add_setting(spec, "nope.x=1"), Catch::Contains("unknown scene 'nope'"));
    CHECK_THROWS_WITH(add_setting(spec, "torqued_cylinder.torque=abc"), Catch::Contains("'abc' is not a number"));
    CHECK_THROWS_WITH(add_setting(spec, "torqued_cylinder.torque=inf"), Catch::Contains("must be a finite number"));
}

TEST_CASE("reference and trajectory exports have the contract columns") {
    const fs::path dir = fresh_dir("exports");
    fs::create_directories(dir);
    const Cli reference = cli({"reference", "--scene", "asymmetric_free", "--samples", "10", "--out", (dir / "ref.csv").string()});
    INFO(reference.err);
    REQUIRE(reference.status == 0);
    std::istringstream lines(read(dir / "ref.csv"));
    std::string header, line;
    std::getline(lines, header);
    CHECK(header == trajectory_header);
    int rows = 0;
    double first_energy = 0, worst = 0;
    while (std::getline(lines, line)) {
        const double energy = std::stod(line.substr(line.rfind(',') + 1));
        if (rows++ == 0) first_energy = energy;
        worst = std::max(worst, std::abs(energy / first_energy - 1.0));
    }
    CHECK(rows == 11);
    CHECK(worst < 1e-14);  // the closed form conserves energy to round-off

    REQUIRE(cli({"trajectory", "--scene", "asymmetric_free", "--scheme", "zvw", "--dt", "1e-2", "--samples", "40", "--out",
                 (dir / "run.csv").string()}).status == 0);
    const std::string run = read(dir / "run.csv");
    CHECK(run.rfind(std::string(trajectory_header) + "\n", 0) == 0);
    CHECK(std::count(run.begin(), run.end(), '\n') == 42);  // header + t = 0 + 40 rows (2000 steps, every 50th)
    fs::remove_all(dir);
}

TEST_CASE("a reference Odeint cannot compute is one line and exit 1, and nothing is written") {
    const fs::path dir = fresh_dir("no_reference");
    fs::create_directories(dir);
    // 1e-300 kg with moments of order 1: contact periods of 1e-153 s, past the reference's budget of steps.
    const Cli r = cli({"reference", "--scene", "particle_contact", "--set", "mass=1e-300", "--set", "inertia=1,2,3", "--t-end", "2.7e-152",
                       "--samples", "48", "--out", (dir / "ref.csv").string()});
    CHECK(r.status == 1);
    CHECK(one_line(r.err));
    CHECK_THAT(r.err, Catch::Contains("no reference for particle_contact: Odeint reference: more than"));
    CHECK_FALSE(fs::exists(dir / "ref.csv"));
    fs::remove_all(dir);
}

TEST_CASE("TOML text is made ASCII before Debian's toml++ 3.3.0 reads it, or refused with line and column") {
    const auto message = [](const std::string& text) -> std::string {
        try {
            parse_config(text, "c.toml");
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    // Inputs the fuzzer found or upstream reported (harness/toml_ascii.hpp).
    CHECK(message("d\xef\xb9\xbf") == "c.toml:1:2: a non-ASCII character outside a string or comment");
    CHECK(message("\xcc\xaa") == "c.toml:1:1: a non-ASCII character outside a string or comment");  // upstream #295
    CHECK(message("\xcc") == "c.toml:1:1: the file is not valid UTF-8");
    CHECK(message("[run]\nt_end = 1\n\xff") == "c.toml:3:1: the file is not valid UTF-8");
    CHECK(message("[run]\nt_end = 1 # \xed\xa0\x80\n") == "c.toml:2:13: the file is not valid UTF-8");  // a surrogate
    CHECK_THAT(message("s = '\xc2\xa7'\n"), Catch::StartsWith("c.toml:1:6: a non-ASCII character in a literal string"));
    // b=1e1"...: toml++ reads on past the number into what looks like a string (fuzzer).
    CHECK_THAT(message("b=1e1\"+ye\xd2\x93\xd2\x93\xd0\xb1" "a\xd2\x93" "a\":e\"\":"), Catch::StartsWith("c.toml:1:"));
    // Where TOML allows non-ASCII text, the meaning is kept: comments, and basic strings
    // (escaped), also right after a line-ending backslash (upstream #190).
    CHECK(message("\xef\xbb\xbf# \xce\x94t \xe2\x86\x92 0\n[run]\nt_end = 1\n").empty());
    CHECK_THAT(message("[dipole_top]\nfield = \"\xce\xbc \\t\xf0\x9f\x98\x80\"\n"), Catch::Contains("c.toml:2:9: 'field' must be a number"));
    CHECK_THAT(message("[dipole_top]\nfield = \"\"\"\\\n\xc2\xa7\"\"\"\n"), Catch::Contains("c.toml:2:9: 'field' must be a number"));
}

TEST_CASE("a gate's why, written with non-ASCII text, reads back unchanged") {
    const auto checks = parse_gate("[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"direct\"]\nmin_order = 1\n"
                                   "why = \"\xce\x94t \xe2\x86\x92 0: \xcf\x89 error ~ \xce\x94t \xf0\x9f\x98\x80\"  # \xce\xb1\n",
                                   "g.toml").checks;
    REQUIRE(checks.size() == 1);
    CHECK(checks[0].why == "\xce\x94t \xe2\x86\x92 0: \xcf\x89 error ~ \xce\x94t \xf0\x9f\x98\x80");
}

TEST_CASE("a gate's except leaves schemes out of \"*\", and means nothing without it") {
    const std::string check = "[[check]]\nscene = \"cylinder_free\"\nmax_cost_ratio = 8\ndt = 1e-4\n";
    const auto checks = parse_gate(check + "schemes = [\"*\"]\nexcept = [\"exact_splitting\", \"direct\"]\n", "g.toml").checks;
    REQUIRE(checks.size() == 1);
    CHECK(std::find(checks[0].schemes.begin(), checks[0].schemes.end(), "exact_splitting") == checks[0].schemes.end());
    CHECK(std::find(checks[0].schemes.begin(), checks[0].schemes.end(), "direct") == checks[0].schemes.end());
    CHECK(std::find(checks[0].schemes.begin(), checks[0].schemes.end(), "omelyan") != checks[0].schemes.end());
    CHECK_THROWS_WITH(parse_gate(check + "schemes = [\"direct\"]\nexcept = [\"direct\"]\n", "g.toml"),
                      Catch::Contains("'except' applies to schemes = [\"*\"] only"));
    CHECK_THROWS_WITH(parse_gate(check + "schemes = [\"*\"]\nexcept = [\"nope\"]\n", "g.toml"), Catch::Contains("nope"));
}
