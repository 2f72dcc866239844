// `rotbench gate`: the default gate passes every sound scheme and fails the negative
// control with its reason; bad gate files are answered with file, line and column.
#include "harness/gate/gate.hpp"
#include "reports/gate_report.hpp"
#include "schemes/scheme.hpp"
#include "tests/cli_helpers.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace rotbench;
using namespace rotbench::test;

namespace {

// The default gate without its cost checks: CPU-time ratios belong to the CI step that runs
// the whole gate, not to unit tests on a shared machine.
std::vector<GateCheck> default_gate_without_timing() {
    auto checks = load_gate(DEFAULT_GATE);
    checks.erase(std::remove_if(checks.begin(), checks.end(), [](const GateCheck& c) { return c.criterion == "max_cost_ratio"; }),
                 checks.end());
    return checks;
}

}  // namespace

TEST_CASE("the default gate passes every sound scheme and fails no_gyro, saying why") {
    const auto checks = default_gate_without_timing();
    REQUIRE(checks.size() >= 8);
    const GateResult result = run_gate(checks, 2);
    int no_gyro_failures = 0;
    for (const auto& o : result.outcomes) {
        const bool sound = SchemeRegistry::instance().at(o.scheme, "scheme").extra.sound;
        INFO(o.scheme << ": " << checks[o.check].name << ": " << o.detail);
        if (o.scheme == "no_gyro") no_gyro_failures += !o.passed;
        else if (sound) CHECK(o.passed);
    }
    // It fails the order checks on both tops, the error on the cylinder and the momentum drift.
    CHECK(no_gyro_failures >= 4);
    const std::string summary = gate_summary(checks, result);
    CHECK_THAT(summary, Catch::Contains("FAIL asymmetric_free/no_gyro"));
    CHECK_THAT(summary, Catch::Contains("does not fall as a power of dt"));
    CHECK_THAT(summary, Catch::Contains("gyroscopic term"));
}

TEST_CASE("gate: JUnit XML has one test case per check and scheme, and a failure element per failed one") {
    const fs::path dir = fresh_dir("gate_junit");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nname = \"a <b> & \\\"c\\\"\"\nscene = \"asymmetric_free\"\nschemes = [\"direct\", \"no_gyro\"]\n"
                          "max_error = 0.5\ndt = 0.05\nwhy = \"x\"\n");
    const Cli r = cli({"gate", (dir / "g.toml").string(), "--junit", (dir / "g.xml").string(), "--out", (dir / "out").string()});
    CHECK(r.status == 1);
    const std::string xml = read(dir / "g.xml");
    const auto count = [&](const std::string& s) {
        std::size_t n = 0;
        for (auto p = xml.find(s); p != std::string::npos; p = xml.find(s, p + 1)) ++n;
        return n;
    };
    CHECK(count("<testcase ") == 2);
    CHECK(count("<failure ") == 1);
    CHECK_THAT(xml, Catch::Contains("tests=\"2\" failures=\"1\""));
    CHECK_THAT(xml, Catch::Contains("a &lt;b&gt; &amp; &quot;c&quot;"));
    CHECK_THAT(read(dir / "out" / "gate.csv"), Catch::StartsWith("scene,scheme,check,criterion,metric,bound,measured,passed,detail\n"));
    CHECK_THAT(r.out, Catch::EndsWith("1 of 2 checks passed; failing: no_gyro\n"));
    fs::remove_all(dir);
}

TEST_CASE("gate: exit status 0 when every check passes") {
    const fs::path dir = fresh_dir("gate_pass");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"zvw\"]\nmin_order = 1.8\ndt = [0.02, 0.01, 0.005, 0.0025]\n");
    const Cli r = cli({"gate", (dir / "g.toml").string()});
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("1 of 1 checks passed"));
    fs::remove_all(dir);
}

TEST_CASE("gate: a scheme that throws or blows up fails its checks and the gate goes on") {
    const fs::path dir = fresh_dir("gate_throw");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"test_throws\", \"test_nan\", \"zvw\"]\n"
                          "min_order = 1.8\ndt = [0.02, 0.01, 0.005]\n");
    const GateResult result = run_gate(load_gate((dir / "g.toml").string()), 2);
    REQUIRE(result.outcomes.size() == 3);
    CHECK_FALSE(result.outcomes[0].passed);
    CHECK_THAT(result.outcomes[0].detail, Catch::Contains("failed"));
    CHECK_FALSE(result.outcomes[1].passed);
    CHECK(result.outcomes[2].passed);
    fs::remove_all(dir);
}

TEST_CASE("gate: bad gate files give one line with file, line and column, and exit status 2") {
    const fs::path dir = fresh_dir("gate_bad");
    fs::create_directories(dir);
    const std::string f = (dir / "g.toml").string();
    struct Case {
        std::string toml, message;
    };
    const std::string head = "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"direct\"]\n";
    const std::vector<Case> cases = {
        {head + "min_order = 1\nmax_error = 1\n", "g.toml:4:13: a check has one criterion"},
        {head + "min_ordre = 1\n", "g.toml:4:13: unknown key 'min_ordre' in [[check]]; valid keys:"},
        {head, "has no criterion (one of min_order, max_error"},
        {"[[check]]\nscene = \"asymmetric_free\"\nmin_order = 1\n", "has no 'schemes'"},
        {"[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"verlet\"]\nmin_order = 1\n", "g.toml:3:11: unknown scheme 'verlet'; valid schemes: "},
        {"[[check]]\nscene = \"cylinder\"\nschemes = [\"direct\"]\nmin_order = 1\n", "g.toml:2:9: unknown scene 'cylinder'; valid scenes: "},
        {head + "max_error = 1\n", "'max_error' needs exactly one 'dt'"},
        {head + "max_error = 1\ndt = [0.1, 0.2]\n", "'max_error' needs exactly one 'dt'"},
        {head + "min_order = 1\ndt = [0.1, 0.1, 0.05]\n", "'dt' has a duplicate value"},
        {head + "min_order = 1\ndt = [0.1, -0.05, 0.025]\n", "'dt' values must be finite numbers greater than 0"},
        {head + "min_order = \"one\"\n", "'min_order' must be a number"},
        {head + "min_stability = 0.5\n", "min_stability needs a stability scene"},
        {head + "max_error = 1\ndt = 0.1\nmetric = \"omega_err\"\n", "unknown metric 'omega_err'; valid metrics:"},
        {head + "min_order = 1\nparams = { omega = 1 }\n", "unknown parameter"},
        {head + "min_order = 1\nt_end = 0\n", "'t_end' must be one finite number greater than 0"},
        {"[[check]\n", "g.toml:1:"},
        {"[run]\n", "unknown entry 'run'; a gate file holds [[check]] tables only"},
        {"", "no [[check]] in the gate file"},
    };
    for (const auto& c : cases) {
        write(f, c.toml);
        const Cli r = cli({"gate", f});
        INFO(c.toml);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::Contains(c.message));
    }
    const Cli missing = cli({"gate", (dir / "absent.toml").string()});
    CHECK(missing.status == 2);
    CHECK_THAT(missing.err, Catch::Contains("absent.toml: cannot read the file"));
    fs::remove_all(dir);
}
