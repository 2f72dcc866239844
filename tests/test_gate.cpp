// `rotbench gate`: every scheme held to its own claims, controls expected to fail, and the
// outputs CI reads. The default gate runs in the real binary, which holds none of the
// test-only schemes this test program registers.
#include "harness/gate/gate.hpp"
#include "reports/gate_report.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/misbehaving_schemes.hpp"

#include <algorithm>
#include "schemes/plugin_abi.hpp"

#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <sys/resource.h>
#include <csignal>
#include <set>
#include <sstream>

using namespace rotbench;
using namespace rotbench::test;

namespace {

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

// A strict XML parser's verdict on a file: Python's expat refuses anything not well-formed.
bool well_formed_xml(const fs::path& file) {
    return run_program({"python3", "-c", "import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])", file.string()}) == 0;
}

// Python's json module in strict mode: UTF-8, no bare control characters.
bool valid_json(const fs::path& file) {
    return run_program({"python3", "-c", "import sys, json; json.load(open(sys.argv[1], encoding='utf-8', errors='strict'))",
                        file.string()}) == 0;
}

// The default gate without its cost checks, as a file.
std::string default_gate_without_timing() {
    static const RemovedAtExit file{[] {
        const fs::path file = fs::temp_directory_path() / ("rotbench_default_gate_" + std::to_string(::getpid()) + ".toml");
        write(file, default_gate_checks(false));
        return file;
    }()};
    return file.path.string();
}

}  // namespace

TEST_CASE("the default gate without its cost checks leaves no check of the others out") {
    const std::string text = read(default_gate_without_timing());
    CHECK(text.find("max_cost_ratio") == std::string::npos);
    CHECK(count_of(text, "[[check]]") == count_of(read(DEFAULT_GATE), "[[check]]") - count_of(read(DEFAULT_GATE), "max_cost_ratio"));
    CHECK_THAT(text, Catch::Contains("[claims]"));
}

TEST_CASE("the default gate exits 0 on a sound build, with no_gyro's failures listed as expected") {
    const fs::path dir = fresh_dir("gate_default");
    fs::create_directories(dir);
    const Cli r = binary({"gate", default_gate_without_timing(), "--junit", (dir / "gate.xml").string()});
    INFO(r.out << r.err);
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("0 failed"));
    CHECK_THAT(r.out, Catch::Contains("0 unexpected passes"));
    // no_gyro, a control, fails the sanity checks it is held to: expected.
    CHECK(count_of(r.out, "XFAIL asymmetric_free/no_gyro") == 2);
    CHECK(count_of(r.out, "XFAIL dipole_top/no_gyro") == 1);
    CHECK(count_of(r.out, "\nFAIL ") == 0);
    // Every claim of every scheme is checked: orders on the two free scenes and the torqued one.
    CHECK_THAT(r.out, Catch::Contains("PASS tumbling_brick/zvw: zvw: order_without_torque"));
    CHECK_THAT(r.out, Catch::Contains("PASS dipole_top/no_squish: no_squish: time_reversible"));
    CHECK_THAT(r.out, Catch::Contains("PASS asymmetric_free/exact_splitting: exact_splitting: exact_without_torque"));
    const std::string xml = read(dir / "gate.xml");
    CHECK(count_of(xml, "<skipped message=\"expected failure: no_gyro is a control") == 5);
    CHECK(count_of(xml, "<failure ") == 0);
    CHECK(well_formed_xml(dir / "gate.xml"));
    CHECK(valid_json(dir / "summary.json"));
    fs::remove_all(dir);
}

TEST_CASE("a plug-in that claims zvw's second order and delivers first fails the default gate on the order claim") {
    const Cli r = binary({"gate", default_gate_without_timing(), "--plugin", PLUGIN_END_VELOCITY_ZVW, "--schemes", "zvw_end_velocity"});
    CHECK(r.status == 1);
    CHECK_THAT(r.out, Catch::Contains("FAIL asymmetric_free/zvw_end_velocity: zvw_end_velocity: order_without_torque on "
                                      "asymmetric_free: observed order 1.00"));
    CHECK_THAT(r.out, Catch::Contains("claimed 2: more than 0.2 away"));
    CHECK_THAT(r.out, Catch::Contains("FAIL tumbling_brick/zvw_end_velocity"));
    CHECK_THAT(r.out, Catch::EndsWith("failing: zvw_end_velocity\n"));
}

TEST_CASE("the q^n-frame Fincham leapfrog fails the default gate on its order claims") {
    const Cli r = binary({"gate", default_gate_without_timing(), "--plugin", PLUGIN_QN_FRAME_FINCHAM, "--schemes", "fincham_qn_frame"});
    CHECK(r.status == 1);
    CHECK_THAT(r.out, Catch::Contains("FAIL asymmetric_free/fincham_qn_frame: fincham_qn_frame: order_without_torque"));
    CHECK_THAT(r.out, Catch::Contains("FAIL dipole_top/fincham_qn_frame: fincham_qn_frame: order_with_torque"));
    SECTION("and the report of a run of it names the same claims and does not recommend it") {
        const fs::path dir = fresh_dir("gate_report_agree");
        const Cli run = binary({"--plugin", PLUGIN_QN_FRAME_FINCHAM, "run", "--scenes", "asymmetric_free,tumbling_brick,dipole_top",
                                "--schemes", "fincham_qn_frame", "--out", dir.string()});
        REQUIRE(run.status == 0);
        const std::string report = read(dir / "report.md");
        CHECK_THAT(report, Catch::Contains("fails its claims: order_without_torque on asymmetric_free, order_with_torque on "
                                           "dipole_top, order_without_torque on tumbling_brick"));
        CHECK_THAT(report, !Catch::Contains("**Use**"));
        CHECK_THAT(report, !Catch::Contains("**For short runs**"));
        fs::remove_all(dir);
    }
}

TEST_CASE("gate --quick: the default gate's verdicts on each ladder's finest rungs, from fewer runs, and a wrong order still fails") {
    const fs::path dir = fresh_dir("gate_quick");
    const Cli whole = binary({"gate", default_gate_without_timing(), "--out", (dir / "whole").string()});
    const Cli quick = binary({"gate", default_gate_without_timing(), "--quick", "--out", (dir / "quick").string()});
    REQUIRE(whole.status == 0);
    REQUIRE(quick.status == 0);
    const auto verdicts = [](const std::string& out) {  // each case's word and name, not its figures
        std::istringstream in(out);
        std::multiset<std::string> kept;
        for (std::string line; std::getline(in, line);)
            if (const auto name_end = line.find(" on "); line.rfind("PASS ", 0) == 0 || line.rfind("XFAIL ", 0) == 0 || line.rfind("FAIL ", 0) == 0)
                kept.insert(line.substr(0, name_end));
        return kept;
    };
    CHECK(verdicts(quick.out) == verdicts(whole.out));
    CHECK(verdicts(quick.out).size() > 100);
    // An order claim is fitted on the quick_rungs finest steps of the scene's ladder.
    CHECK_THAT(quick.out, Catch::Contains("PASS asymmetric_free/zvw: zvw: order_without_torque on asymmetric_free: observed order 2.00") &&
                              Catch::Contains("over dt 0.00313 ... 0.000781 (3 points)"));
    CHECK(count_of(read(dir / "quick" / "runs.csv"), "\n") < count_of(read(dir / "whole" / "runs.csv"), "\n") * 2 / 3);
    const Cli wrong = binary({"gate", default_gate_without_timing(), "--quick", "--plugin", PLUGIN_END_VELOCITY_ZVW, "--schemes", "zvw_end_velocity"});
    CHECK(wrong.status == 1);
    CHECK_THAT(wrong.out, Catch::Contains("FAIL asymmetric_free/zvw_end_velocity: zvw_end_velocity: order_without_torque on "
                                          "asymmetric_free: observed order 1.00"));
    fs::remove_all(dir);
}

TEST_CASE("gate: [claims.SCENE] sets a scene's ladder and parameters for every claim judged there") {
    const fs::path dir = fresh_dir("gate_claim_scene");
    fs::create_directories(dir);
    write(dir / "g.toml", "[claims]\nschemes = [\"zvw\", \"no_squish\"]\nfree = [\"tumbling_brick\", \"cylinder_free\"]\n"
                          "torque = [\"dipole_top\"]\n[claims.cylinder_free]\ndt = [0.001, 0.004, 0.002]\n"
                          "[claims.tumbling_brick]\nparams = { t_end = 1.0 }\n");
    const Cli r = cli({"gate", (dir / "g.toml").string(), "--quick"});  // a ladder the file gives is kept under --quick
    INFO(r.out << r.err);
    CHECK(r.status == 0);
    // cylinder_free's claims on the file's three steps, coarsest first, not the scene's 500,000-step ladder.
    CHECK_THAT(r.out, Catch::Contains("zvw: order_without_torque on cylinder_free: observed order 2.0") &&
                          Catch::Contains("over dt 0.004 ... 0.001 (3 points)"));
    // tumbling_brick's every claim over its shorter duration: the ladder's, the momentum's and the reversal's.
    CHECK_THAT(r.out, Catch::Contains("no_squish: time_reversible on tumbling_brick: after 100 steps forward"));
    CHECK_THAT(r.out, Catch::Contains("no_squish: conserves_momentum on tumbling_brick: momentum drift") &&
                          Catch::Contains("for N = 800 steps"));  // at the coarsest step of its --quick ladder, over 1 s
    fs::remove_all(dir);
}

TEST_CASE("a plug-in that claims nothing gets the generic sanity checks and a warning") {
    const Cli r = binary({"gate", default_gate_without_timing(), "--plugin", PLUGIN_CLAIMS_NOTHING, "--schemes", "claims_nothing"});
    CHECK(r.status == 0);  // a sound scheme passes them
    CHECK_THAT(r.out, Catch::Contains("WARNING claims_nothing registers no claims"));
    CHECK_THAT(r.out, Catch::Contains("PASS asymmetric_free/claims_nothing: claims_nothing: sanity_order"));
    CHECK_THAT(r.out, Catch::Contains("PASS tumbling_brick/claims_nothing: claims_nothing: sanity_momentum"));
}

TEST_CASE("gate --schemes holds only the schemes named to the file's claims and checks") {
    const Cli all = binary({"gate", default_gate_without_timing()});  // the real binary: no test-only schemes
    const Cli two = binary({"gate", default_gate_without_timing(), "--schemes", "zvw,no_gyro"});
    REQUIRE(all.status == 0);
    CHECK(two.status == 0);  // no_gyro's expected failures are still expected
    // Every verdict line of the two is one of the whole gate's, and every one of the whole
    // gate's verdicts on zvw or no_gyro is there.
    const auto verdicts = [](const std::string& out, bool only_two) {
        std::vector<std::string> lines;
        std::istringstream in(out);
        for (std::string line; std::getline(in, line);) {
            const bool verdict = line.rfind("PASS ", 0) == 0 || line.rfind("FAIL ", 0) == 0 || line.rfind("XFAIL ", 0) == 0;
            const auto slash = line.find('/'), colon = line.find(':');
            if (!verdict || slash == std::string::npos || colon == std::string::npos) continue;
            const std::string scheme = line.substr(slash + 1, colon - slash - 1);
            if (!only_two || scheme == "zvw" || scheme == "no_gyro") lines.push_back(line);
        }
        std::sort(lines.begin(), lines.end());
        return lines;
    };
    const auto mine = verdicts(two.out, false);
    CHECK(mine.size() >= 6);
    CHECK(mine == verdicts(all.out, true));
    CHECK_THAT(two.out, Catch::Contains("XFAIL"));
    const Cli unknown = binary({"gate", default_gate_without_timing(), "--schemes", "zvw,nonesuch"});
    CHECK(unknown.status == 2);
    CHECK_THAT(unknown.err, Catch::Contains("unknown scheme 'nonesuch'"));
}

TEST_CASE("gate: a check marked as expected to fail is fine when it fails, and fails the gate when it passes") {
    const fs::path dir = fresh_dir("gate_expected");
    fs::create_directories(dir);
    const std::string check = "[[check]]\nname = \"tight\"\nscene = \"asymmetric_free\"\nschemes = [\"direct\", \"zvw\"]\n"
                              "max_error = 1e-3\ndt = 0.05\n";
    write(dir / "fails.toml", check + "[[expected_failure]]\ncheck = \"tight\"\nscene = \"asymmetric_free\"\nscheme = \"direct\"\n"
                                      "reason = \"first order: 0.05 is far too coarse for it\"\n");
    const Cli failing = cli({"gate", (dir / "fails.toml").string()});
    CHECK(failing.status == 0);
    CHECK_THAT(failing.out, Catch::Contains("XFAIL asymmetric_free/direct"));
    CHECK_THAT(failing.out, Catch::Contains("expected to fail: first order: 0.05 is far too coarse for it"));
    write(dir / "passes.toml", check + "[[expected_failure]]\ncheck = \"tight\"\nscene = \"asymmetric_free\"\nscheme = \"zvw\"\n"
                                       "reason = \"wrongly expected\"\n");
    const Cli passing = cli({"gate", (dir / "passes.toml").string()});
    CHECK(passing.status == 1);
    CHECK_THAT(passing.out, Catch::Contains("XPASS asymmetric_free/zvw"));
    CHECK_THAT(passing.out, Catch::Contains("1 unexpected passes"));
    fs::remove_all(dir);
}

TEST_CASE("gate: a scheme that throws or blows up fails its checks and the gate goes on") {
    const fs::path dir = fresh_dir("gate_throw");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"test_throws\", \"test_nan\", \"zvw\"]\n"
                          "min_order = 1.8\ndt = [0.02, 0.01, 0.005]\n");
    const Cli r = cli({"gate", (dir / "g.toml").string()});
    // test_throws and test_nan are controls: their failures are expected; zvw passes.
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("XFAIL asymmetric_free/test_throws"));
    CHECK_THAT(r.out, Catch::Contains("threw: plug-in bug"));
    CHECK_THAT(r.out, Catch::Contains("XFAIL asymmetric_free/test_nan"));
    CHECK_THAT(r.out, Catch::Contains("PASS asymmetric_free/zvw"));
    fs::remove_all(dir);
}

TEST_CASE("gate: the CI outputs (JUnit, summary.json, gate.csv, Markdown, annotations)") {
    const fs::path dir = fresh_dir("gate_outputs");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nname = \"a <b> & \\\"c\\\"\"\nscene = \"asymmetric_free\"\nschemes = [\"direct\", \"zvw\"]\n"
                          "max_error = 0.05\ndt = 0.05\nwhy = \"x\"\n");
    const std::string step_summary = (dir / "step_summary.md").string();
    write(step_summary, "earlier step\n");
    const Cli ok = binary({"gate", (dir / "g.toml").string(), "--junit", (dir / "j" / "gate.xml").string(), "--out",
                           (dir / "out").string(), "--summary", (dir / "summary.md").string()},
                          {"GITHUB_ACTIONS=true", "GITHUB_STEP_SUMMARY=" + step_summary});
    CHECK(ok.status == 1);  // direct is first order: 0.05 is too coarse for 5e-2 rad/s
    const std::string xml = read(dir / "j" / "gate.xml");
    CHECK(count_of(xml, "<testcase ") == 2);
    CHECK(count_of(xml, "<failure ") == 1);
    CHECK_THAT(xml, Catch::Contains("name=\"a &lt;b&gt; &amp; &quot;c&quot; on asymmetric_free\""));
    CHECK_THAT(xml, Catch::Contains(" line=\"1\" time=\""));
    CHECK(well_formed_xml(dir / "j" / "gate.xml"));
    CHECK(valid_json(dir / "j" / "summary.json"));
    const std::string json = read(dir / "j" / "summary.json");
    for (const char* field : {"\"provenance\"", "\"commit\"", "\"compiler\"", "\"flags\"", "\"cpu\"", "\"date\"", "\"schemes\"",
                              "\"checks\"", "\"outcome\": \"fail\"", "\"interval\""})
        CHECK_THAT(json, Catch::Contains(field));
    CHECK_THAT(read(dir / "out" / "gate.csv"), Catch::StartsWith("scene,scheme,check,family,criterion,outcome,measured,lo,hi,bound,message\n"));
    // The step summary is appended to, never replaced; --summary holds the same Markdown.
    const std::string appended = read(step_summary);
    CHECK_THAT(appended, Catch::StartsWith("earlier step\n## rotbench gate: FAILED"));
    CHECK_THAT(read(dir / "summary.md"), Catch::StartsWith("## rotbench gate: FAILED"));
    // Under GitHub Actions, an annotation for the failure, with the file and line of the check.
    CHECK_THAT(ok.out, Catch::Contains("::error file=" + (dir / "g.toml").string() + ",line=1,title=rotbench gate%3A direct a <b> & \"c\"::"));
    fs::remove_all(dir);
}

TEST_CASE("gate: a check's name cannot put a line of its own on stdout (a workflow command) or a control character") {
    const fs::path dir = fresh_dir("gate_injection");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nname = \"x\\n::error file=a.cpp,line=1::injected\\u001b[2J\"\nscene = \"asymmetric_free\"\n"
                          "schemes = [\"direct\"]\nmax_error = 0.05\ndt = 0.05\nwhy = \"y\\r\\n::warning::also\"\n");
    const Cli r = binary({"gate", (dir / "g.toml").string()}, {"GITHUB_ACTIONS=true"});
    CHECK(r.status == 1);
    std::istringstream out(r.out);
    for (std::string line; std::getline(out, line);) {
        INFO(line);
        CHECK(line.rfind("::error file=a.cpp", 0) != 0);
        CHECK(line.rfind("::warning::also", 0) != 0);
        CHECK(line.find('\x1b') == std::string::npos);
    }
    CHECK_THAT(r.out, Catch::Contains("x\\x0A::error file=a.cpp,line=1::injected\\x1B[2J"));
    fs::remove_all(dir);
}

TEST_CASE("gate: a step summary that cannot take the text loses only itself") {
    const fs::path dir = fresh_dir("gate_step_full");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"zvw\"]\nmax_error = 0.05\ndt = 0.05\nwhy = \"x\"\n");
    // A step summary already at the file-size limit opens for appending (the check before any work
    // passes) and refuses every byte; the gate's own files are far below the limit.
    const std::string step = (dir / "step.md").string();
    write(step, std::string(1 << 20, '#'));
    const Cli r = binary({"gate", (dir / "g.toml").string(), "--out", (dir / "out").string(), "--summary", (dir / "summary.md").string()},
                         {"GITHUB_STEP_SUMMARY=" + step}, [] {
                             std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG
                             const rlimit limit{1 << 20, 1 << 20};
                             ::setrlimit(RLIMIT_FSIZE, &limit);
                         });
    CHECK(r.status == 3);
    CHECK_THAT(r.err, Catch::Contains(step));
    CHECK_THAT(read(dir / "out" / "gate.csv"), Catch::Contains(",pass,"));
    CHECK_THAT(read(dir / "summary.md"), Catch::StartsWith("## rotbench gate: passed"));
    fs::remove_all(dir);
}

TEST_CASE("gate: a step summary that is not a regular file is refused at once, before any work") {
    const fs::path dir = fresh_dir("gate_step_fifo");
    fs::create_directories(dir);
    write(dir / "g.toml", "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"zvw\"]\nmax_error = 0.05\ndt = 0.05\nwhy = \"x\"\n");
    REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);  // no reader: opening it to write would wait for one
    for (const auto& [step, why] : std::vector<std::pair<std::string, std::string>>{
             {(dir / "fifo").string(), "not a regular file"}, {"/dev/full", "not a regular file"}, {"/dev/stdout", "a symbolic link"}}) {
        const Cli r = binary({"gate", (dir / "g.toml").string(), "--out", (dir / "out").string()}, {"GITHUB_STEP_SUMMARY=" + step});
        INFO(step);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::Contains("$GITHUB_STEP_SUMMARY: cannot write " + step + ": " + why));
        CHECK_FALSE(fs::exists(dir / "out"));
    }
    fs::remove_all(dir);
}

TEST_CASE("gate: JUnit XML stays well-formed for any message (control characters, invalid UTF-8, markup)") {
    GateResult result;
    Verdict v;
    v.of.id = "claim\x01 <&>\"'";
    v.of.scene = "asymmetric_free";
    v.of.scheme = "hostile";
    v.of.location = "g.toml:3";
    v.message = std::string("threw: \x00\x07\x1b[31m red \xff\xfe bad \xc3\x28 ]]> \xef\xbf\xbe end", 36) + "\nnext line\r\n";
    result.verdicts = {v};
    v.of.expected_to_fail = true;
    v.of.expected_reason = "\x02 reason \xe2\x28\xa1";
    result.verdicts.push_back(v);
    result.warnings = {"hostile warns \x03 \xf0\x28\x8c\x28"};
    const fs::path dir = fresh_dir("gate_hostile");
    fs::create_directories(dir);
    write(dir / "j.xml", gate_junit(result, "g.toml"));
    CHECK(well_formed_xml(dir / "j.xml"));
    write(dir / "s.json", gate_summary_json(result, "g\xff.toml", provenance()));
    CHECK(valid_json(dir / "s.json"));
    const std::string annotations = gate_annotations(result);
    CHECK(count_of(annotations, "\n") == 2);  // one line each: the warning and the failure (the expected failure is fine)
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
    const std::string claims = "[claims]\nschemes = [\"*\"]\nfree = [\"asymmetric_free\", \"tumbling_brick\"]\ntorque = [\"dipole_top\"]\n";
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
        {"[run]\n", "unknown entry 'run'; a gate file holds [claims], [[check]] and [[expected_failure]] tables"},
        {"", "no [claims] and no [[check]] in the gate file"},
        {"[claims]\nschemes = [\"*\"]\n", "[claims] needs 'schemes', 'free' and 'torque'"},
        {"[claims]\nschemes = [\"*\"]\nfree = [\"asymmetric_free\"]\ntorque = [\"dipole_top\"]\n", "'free' needs at least two torque-free scenes"},
        {"[claims]\nschemes = [\"*\"]\nfree = [\"asymmetric_free\", \"dipole_top\"]\ntorque = [\"dipole_top\"]\n",
         "g.toml:3:8: 'dipole_top' is not a torque-free scene with a reference"},
        {"[claims]\nschemes = [\"*\"]\nfree = [\"asymmetric_free\", \"tumbling_brick\"]\ntorque = [\"fibre_bounce\"]\n",
         "'fibre_bounce' is not a scene with a reference and an orientation-dependent torque"},
        {claims + "sideways = 1\n", "unknown key 'sideways' in [claims]"},
        {claims + "[claims.asymmetric_free]\ndt = [0.1, 0.05]\n", "an order is fitted on at least 3 time steps in 'dt'"},
        {claims + "[claims.asymmetric_free]\ndt = [0.1, 0.05, 0.1]\n", "'dt' has a duplicate value"},
        {claims + "[claims.asymmetric_free]\nladder = [0.1]\n", "unknown key 'ladder' in [claims.asymmetric_free]; valid keys: dt, params"},
        {claims + "[claims.asymmetric_free]\nparams = { omega = 1 }\n", "unknown parameter"},
        {claims + "[claims.cylinder_free]\ndt = [0.1, 0.05, 0.025]\n", "[claims.cylinder_free] is for a scene neither 'free' nor 'torque' lists"},
        {claims + "[claims.tumbling_brick]\nparams = { t_end = -1 }\n", "[claims.tumbling_brick] params: "},
        {claims + "[[expected_failure]]\ncheck = \"order_without_torque\"\nscene = \"asymmetric_free\"\nscheme = \"direct\"\n",
         "needs 'check', 'scene', 'scheme' and a 'reason'"},
        {claims + "[[expected_failure]]\ncheck = \"nonsense\"\nscene = \"asymmetric_free\"\nscheme = \"direct\"\nreason = \"r\"\n",
         "expected failure of 'nonsense', which is neither a check of this file nor a claim"},
        {claims + "[[expected_failure]]\ncheck = \"exact_without_torque\"\nscene = \"asymmetric_free\"\nscheme = \"direct\"\nreason = \"r\"\n",
         "matches no check the gate makes"},
        {head + "min_order = 1\n[[expected_failure]]\ncheck = \"min_order\"\nscene = \"dipole_top\"\nscheme = \"direct\"\nreason = \"r\"\n",
         "check 'min_order' does not run direct on dipole_top"},
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

TEST_CASE("gate: the same verdicts from slices run apart and merged (--shard, merge, --results)") {
    const fs::path dir = fresh_dir("gate_shards");
    fs::create_directories(dir);
    write(dir / "g.toml", "[claims]\nschemes = [\"zvw\", \"no_squish\", \"no_gyro\"]\nfree = [\"asymmetric_free\", \"tumbling_brick\"]\n"
                          "torque = [\"dipole_top\"]\n");
    const std::string gate = (dir / "g.toml").string();
    const Cli whole = cli({"gate", gate});
    REQUIRE(whole.status == 0);
    for (const char* k : {"1", "2"})
        REQUIRE(cli({"gate", gate, "--shard", std::string(k) + "/2", "--out", (dir / k).string()}).status == 0);
    REQUIRE(cli({"merge", (dir / "1").string(), (dir / "2").string(), "--out", (dir / "merged").string()}).status == 0);
    const Cli judged = cli({"gate", gate, "--results", (dir / "merged").string()});
    CHECK(judged.status == 0);
    const auto verdicts = [](const std::string& out) {  // without the lines of the runs made
        std::istringstream in(out);
        std::string kept;
        for (std::string line; std::getline(in, line);)
            if (line.find(" trajectory ") == std::string::npos && line.find(" reversal ") == std::string::npos &&
                line.find(" stability ") == std::string::npos)
                kept += line + "\n";
        return kept;
    };
    CHECK(verdicts(judged.out) == verdicts(whole.out));
    CHECK(count_of(verdicts(whole.out), "XFAIL") == 5);
    CHECK(cli({"gate", gate, "--shard", "1/2"}).status == 2);  // a slice needs --out
    fs::remove_all(dir);
}

TEST_CASE("the gate points a plug-in's failed claim at its registration, and names the plug-in and gate file it judged") {
    const fs::path dir = fresh_dir("gate_candidate");
    fs::create_directories(dir);
    const Cli r = binary({"--plugin", PLUGIN_END_VELOCITY_ZVW, "gate", default_gate_without_timing(), "--schemes", "zvw_end_velocity",
                          "--junit", (dir / "gate.xml").string()},
                         {"GITHUB_ACTIONS=true"});
    INFO(r.out << r.err);
    CHECK(r.status == 1);
    // The claim is made where RegisterScheme is called in the candidate's source, so that is where CI shows
    // it (relative to the working directory when below it).
    CHECK_THAT(r.out, Catch::Contains("tests/plugins/end_velocity_zvw.cpp,line="));
    const std::string xml = read(dir / "gate.xml");
    CHECK_THAT(xml, Catch::Contains("tests/plugins/end_velocity_zvw.cpp\" line=\""));
    CHECK_THAT(xml, Catch::Contains("<property name=\"plugin\" value=\"" + fs::absolute(PLUGIN_END_VELOCITY_ZVW).string() + "\"/>"));
    CHECK_THAT(xml, Catch::Contains("<property name=\"gate_file\" value=\"" + default_gate_without_timing() + "\"/>"));
    CHECK(well_formed_xml(dir / "gate.xml"));
    const std::string summary = read(dir / "summary.json");
    CHECK_THAT(summary, Catch::Contains("\"gate_file_fnv1a\": \""));
    CHECK_THAT(summary, Catch::Contains("\"build\": \"" ROTBENCH_PLUGIN_BUILD "\""));
    fs::remove_all(dir);
}

TEST_CASE("gate --schemes: a scheme the file names that is not loaded is a warning outside the selection, an error in it") {
    const fs::path dir = fresh_dir("gate_unloaded");
    fs::create_directories(dir);
    write(dir / "g.toml",
          "[claims]\nschemes = [\"richardson\", \"some_client\"]\nfree = [\"asymmetric_free\", \"tumbling_brick\"]\ntorque = [\"dipole_top\"]\n"
          "[[check]]\nname = \"brick\"\nscene = \"tumbling_brick\"\nschemes = [\"some_client\"]\nmin_order = 0.8\n"
          "[[expected_failure]]\ncheck = \"brick\"\nscene = \"tumbling_brick\"\nscheme = \"some_client\"\nreason = \"known\"\n");
    const Cli selected = cli({"gate", (dir / "g.toml").string(), "--schemes", "richardson"});
    INFO(selected.out << selected.err);
    CHECK(selected.status == 0);
    CHECK_THAT(selected.out, Catch::Contains("WARNING " + (dir / "g.toml").string() + ":") &&
                                 Catch::Contains(": scheme 'some_client' is not loaded; outside --schemes, skipped"));
    CHECK(selected.out.find("not loaded", selected.out.find("not loaded") + 1) == std::string::npos);  // said once
    const Cli all = cli({"gate", (dir / "g.toml").string()});
    CHECK(all.status == 2);
    CHECK_THAT(all.err, Catch::Contains("unknown scheme 'some_client'"));
    fs::remove_all(dir);
}
