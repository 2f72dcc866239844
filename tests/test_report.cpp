// The report's first screen answers "which scheme, at what dt, at what cost"; its tables and
// plots stay readable; its data files are typed.
#include "cli_helpers.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/analysis/stability_csv.hpp"
#include "harness/analysis/stability_study.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <functional>
#include <fmt/format.h>
#include <map>
#include <regex>
#include <set>

using namespace rotbench;
using namespace rotbench::test;

namespace {

// A quick run on a free top, a torque T(q) and a contact pair, with its stability study, once.
const fs::path& report_dir() {
    static const RemovedAtExit dir{[] {
        const auto d = fresh_dir("report");
        const std::string schemes = "direct,exact_splitting,fincham,no_gyro,zvw";
        REQUIRE(cli({"run", "--quick", "--scenes", "asymmetric_free,dipole_top,sphere_pair", "--schemes", schemes, "--out", d.string()})
                    .status == 0);
        REQUIRE(cli({"stability", "--scenes", "sphere_pair,fast_spin", "--schemes", schemes, "--zeta", "0,0.3", "--omega-max", "100",
                     "--out", d.string()})
                    .status == 0);
        REQUIRE(cli({"report", d.string()}).status == 0);
        return d;
    }()};
    return dir.path;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

}  // namespace

// One test case, its parts as sections: the run they read is made once per process.
TEST_CASE("the report of a quick run with its stability study") {
    SECTION("the report opens with a paragraph, the recommendation, the contents, the verdicts and the answer") {
        const auto md = lines(read(report_dir() / "report.md"));
        std::vector<std::string> headings;
        for (const auto& l : md)
            if (l.rfind("## ", 0) == 0) headings.push_back(l);
        REQUIRE(headings.size() >= 5);
        CHECK(headings[0] == "## Recommendation");
        CHECK(headings[1] == "## Contents");
        CHECK(headings[2] == "## Verdicts");
        CHECK(headings[3] == "## The answer: the largest dt for a tolerance");
        CHECK(headings[4] == "## Stability limits");
        CHECK(md[2].find("runs of 5 schemes on 3 scenes") != std::string::npos);  // the one-paragraph header
        const std::string text = read(report_dir() / "report.md");
        CHECK_THAT(text, Catch::Contains("### Relative error 0.001"));
        CHECK_THAT(text, Catch::Contains("### Relative error 1e-06"));
        CHECK_THAT(text, Catch::Contains("| `no_gyro` (control) |"));
        // The exact scheme reads "exact" where it is, in the verdicts and in the answer.
        CHECK(std::regex_search(text, std::regex(R"(\| `exact_splitting` \| exact → exact \|)")));
        CHECK(std::regex_search(text, std::regex(R"(\| `exact_splitting` \| exact \(≥ [0-9.e-]+\) \|)")));
        // The stability study merged from the directory: sphere_pair's table, Peng's dt first.
        CHECK_THAT(text, Catch::Contains("### `sphere_pair`\n\n| scheme | zeta = 0 | zeta = 0.3 |"));
        CHECK_THAT(text, Catch::Contains("| *Peng's dt (s)* |"));
    }
    SECTION("the recommendation names the schemes to use and to avoid, with why, from the verdicts") {
        const std::string text = read(report_dir() / "report.md");
        // Of the five: fincham is second order and keeps momentum but its energy drifts; direct and zvw
        // are first order under torque; no_gyro is the control. exact_splitting keeps energy bounded.
        CHECK_THAT(text, Catch::Contains("- **Use** `exact_splitting` ("));
        CHECK_THAT(text, Catch::Contains("- **For short runs** `fincham` ("));
        CHECK_THAT(text, Catch::Contains("`direct` (order 1 under an orientation-dependent torque"));
        CHECK_THAT(text, Catch::Contains("`no_gyro` (a deliberately wrong control)"));
        CHECK_THAT(text, Catch::Contains("- **Peng's step is unsafe once contacts are damped**, for every scheme: at ζ = 0.3 the best limit is"));
        CHECK_THAT(text, Catch::Contains("`rotbench advise --inertia"));
    }
    SECTION("a scheme that does not converge shows how far from converged it stays") {
        // no_gyro on asymmetric_free: the verdict gives omega_err_max / omega_ref_max at its finest
        // step, so a saturated error (near 1) reads apart from round-off that does not converge.
        const RunResult* finest = nullptr;
        const std::vector<RunResult> runs = read_results(report_dir());
        for (const auto& r : runs)
            if (r.spec.scene == "asymmetric_free" && r.spec.scheme == "no_gyro" && (!finest || r.spec.dt < finest->spec.dt)) finest = &r;
        REQUIRE(finest);
        const double relative = finest->value("omega_err_max") / finest->value("omega_ref_max");
        CHECK(relative > 0.01);  // the control's error does not fall with dt: it stays of the order of w
        CHECK_THAT(read(report_dir() / "report.md"),
                   Catch::Contains(fmt::format("| `no_gyro` (control) | — → no convergence (relative error {:.2g} at the finest dt) |", relative)));
    }
    SECTION("no table of the report has more than 7 columns") {
        for (const auto& l : lines(read(report_dir() / "report.md"))) {
            if (l.rfind("|---", 0) != 0) continue;  // a table's rule line
            INFO(l);
            CHECK(std::count(l.begin(), l.end(), '|') - 1 <= 7);
        }
    }
    SECTION("orders.csv says what each row is: fit with its order, or exact, insufficient, no_convergence without one") {
        const auto rows = read_csv(report_dir() / "orders.csv", "scene,scheme,metric,status,order,order_lo,order_hi,dt_min,dt_max,points");
        std::map<std::string, std::string> status;
        for (const auto& r : rows) {
            INFO(r[0] << " " << r[1] << " " << r[2]);
            CHECK((r[3] == "fit" || r[3] == "exact" || r[3] == "insufficient" || r[3] == "no_convergence"));
            CHECK(r[4].empty() == (r[3] != "fit"));
            if (r[3] == "fit") CHECK(std::isfinite(csv_number(r[4], "order")));
            if (r[2] == "omega_err_max") status[r[0] + "/" + r[1]] = r[3];
        }
        CHECK(status["asymmetric_free/exact_splitting"] == "exact");
        CHECK(status["asymmetric_free/no_gyro"] == "no_convergence");
        CHECK(status["asymmetric_free/fincham"] == "fit");
    }
    SECTION("stability.csv carries each row's kind, and the study read back from its store gives the same files") {
        const auto rows = stability_study(read_results(report_dir(), stability_store), "store").rows;
        REQUIRE(rows.size() == 5 * 2 + 5);  // two damping ratios on sphere_pair, one spin rate on fast_spin
        std::map<std::string, std::string> kind;
        for (const auto& r : rows) kind[r.scene + "/" + r.scheme + "/" + std::to_string(r.zeta)] = stability_kind(r);
        CHECK(kind["sphere_pair/fincham/0.000000"] == "sharp");
        CHECK(kind["sphere_pair/zvw/0.000000"] == "weak");
        CHECK(stability_csv(rows) == read(report_dir() / "stability.csv"));
        CHECK(stability_spin_csv(rows) == read(report_dir() / "stability_spin.csv"));
    }
    SECTION("a scheme has one colour and one marker in every plot") {
        std::map<std::string, std::set<std::string>> styles;  // scheme -> "lc rgb '#...' pt N" seen
        const std::regex series(R"((lc rgb '#[0-9a-f]{6}')(?: pt (\d+))?.*? title '([a-z0-9_]+)')");
        for (const auto& entry : fs::directory_iterator(report_dir() / "plots")) {
            if (entry.path().extension() != ".gp" || entry.path().filename().string().rfind("granular", 0) == 0) continue;
            const std::string script = read(entry.path());
            for (auto it = std::sregex_iterator(script.begin(), script.end(), series); it != std::sregex_iterator(); ++it) {
                const auto& m = *it;
                styles[m[3]].insert(m[1].str() + (m[2].matched ? " pt " + m[2].str() : ""));
            }
        }
        REQUIRE(styles.size() == 5);
        std::set<std::string> colours;
        for (const auto& [scheme, seen] : styles) {
            INFO(scheme);
            std::set<std::string> colour;
            for (const auto& st : seen) colour.insert(st.substr(0, st.find(" pt")));
            CHECK(colour.size() == 1);
            colours.insert(*colour.begin());
        }
        CHECK(colours.size() == styles.size());
    }
    SECTION("the plots have units on their axes, at most 8 series per panel, and panels of one width") {
        int scripts = 0;
        for (const auto& entry : fs::directory_iterator(report_dir() / "plots")) {
            if (entry.path().extension() != ".gp") continue;
            ++scripts;
            const std::string script = read(entry.path());
            INFO(entry.path().filename().string());
            std::set<std::string> widths;
            double left = 0;
            for (const auto& l : lines(script)) {
                std::smatch m;
                if (std::regex_search(l, m, std::regex(R"(set [xy]label '(.*)')"))) CHECK(std::regex_search(m[1].str(), std::regex(R"(\(.+\)$)")));
                if (std::regex_search(l, m, std::regex(R"(set lmargin at screen ([0-9.]+))"))) left = std::stod(m[1]);
                if (std::regex_search(l, m, std::regex(R"(set rmargin at screen ([0-9.]+))")))
                    widths.insert(fmt::format("{:.3f}", std::stod(m[1]) - left));
            }
            CHECK(widths.size() <= 1);
            // Each plot command, continued over "\" lines, names at most 8 series.
            std::string command;
            for (const auto& l : lines(script)) {
                if (l.rfind("plot ", 0) == 0) command = l;
                else if (!command.empty()) command += l;
                if (!command.empty() && (l.empty() || l.back() != '\\')) {
                    std::size_t titles = 0;
                    for (std::size_t at = command.find(" title '"); at != std::string::npos; at = command.find(" title '", at + 1)) ++titles;
                    CHECK(titles <= 8);
                    command.clear();
                }
            }
        }
        CHECK(scripts >= 6);
    }
}

TEST_CASE("a convergence curve another one covers says which, on a key line of its own") {
    // Without torque zvw_corrected is zvw to round-off (seed eqs. 57, 63): the later curve is covered.
    const RemovedAtExit dir{fresh_dir("report_covered")};
    REQUIRE(cli({"run", "--quick", "--scenes", "asymmetric_free", "--schemes", "zvw,zvw_corrected", "--out", dir.path.string()})
                .status == 0);
    const std::string script = read(dir.path / "plots" / "convergence_asymmetric_free.gp");
    CHECK_THAT(script, Catch::Contains("title 'zvw_corrected', keyentry with lines lt nodraw title '(= zvw)'"));
    CHECK_THAT(script, !Catch::Contains("title '(= zvw_corrected)'"));
}

TEST_CASE("an energy plot is scaled to the runs that did not blow up, and says when the others did") {
    // At dt = 4e-4 s on the ellipsoid pair zvw blows up (its energy grows a millionfold) and
    // zvw_corrected stays within about 1 %: the panel they share takes zvw_corrected's scale.
    const RemovedAtExit dir{fresh_dir("report_blown")};
    REQUIRE(cli({"run", "--scenes", "ellipsoid_pair", "--schemes", "zvw,zvw_corrected,richardson", "--dt", "4e-4", "--out",
                 dir.path.string()})
                .status == 0);
    double bounded = 0;  // zvw_corrected's largest |energy error|
    for (const auto& row : parse_csv(read(dir.path / "series" / "energy_ellipsoid_pair_zvw_corrected_dt0.0004.csv"), "series"))
        if (row.fields[0] != "t") bounded = std::max(bounded, std::abs(std::stod(row.fields[1])));
    REQUIRE(bounded > 0);
    const std::string script = read(dir.path / "plots" / "energy_ellipsoid_pair_dt0.0004.gp");
    std::smatch m;
    REQUIRE(std::regex_search(script, m, std::regex(R"(set yrange \[([^:]+):([^\]]+)\]\nplot [^\n]*zvw_dt)")));
    // The range is the bounded run's, padded by 5 % of its width on each side: within 1.1 of its largest error.
    CHECK(std::abs(std::stod(m[1])) <= 1.1 * bounded);
    CHECK(std::abs(std::stod(m[2])) <= 1.1 * bounded);
    CHECK(std::regex_search(script, std::regex(R"(title 'zvw', keyentry with lines lt nodraw title '\(blew up, t = [0-9.e-]+ s\)')")));
    CHECK_THAT(script, !Catch::Contains("title 'zvw_corrected', keyentry"));
    CHECK_THAT(script, Catch::Contains("set autoscale y\nplot '../series/energy_ellipsoid_pair_richardson"));
}

TEST_CASE("a stability store holding a run no stability study makes is refused, naming the run") {
    const std::vector<RunResult> made = parse_run_store(read(report_dir() / stability_store), "made");
    REQUIRE_NOTHROW(stability_study(made, "store"));
    const auto forged = [&](const std::function<void(std::vector<RunResult>&)>& edit) {
        std::vector<RunResult> runs = made;
        edit(runs);
        return runs;
    };
    const auto first_search = [](std::vector<RunResult>& runs) -> RunResult& {
        return *std::find_if(runs.begin(), runs.end(), [](const RunResult& r) { return r.spec.kind == RunKind::stability; });
    };
    for (const auto& [runs, message] : std::vector<std::pair<std::vector<RunResult>, std::string>>{
             {forged([&](auto& runs) { first_search(runs).spec.scene = "silo_discharge"; }), "is not a stability scene"},
             {forged([&](auto& runs) { first_search(runs).spec.kind = RunKind::trajectory; }), "a trajectory run is not a stability study's"},
             {forged([&](auto& runs) { first_search(runs).spec.params = {{"zeta", {-0.1}}}; }), "zeta"},
             {forged([&](auto& runs) { first_search(runs).spec.params = {{"omega_max", {100}}}; }), "its parameters are not one zeta"},
             {forged([&](auto& runs) { first_search(runs).metrics = {{metric::dt_empirical, -1.0}}; }), "its limit -1 is not a time step"},
             {forged([&](auto& runs) { runs.push_back(first_search(runs)); }), "is there twice"},
             {forged([&](auto& runs) { runs.erase(runs.begin() + (&first_search(runs) - runs.data())); }), "has an eigenvalue limit and no search"},
         }) {
        INFO(message);
        CHECK_THROWS_AS(stability_study(runs, "store"), InputError);
        CHECK_THROWS_WITH(stability_study(runs, "store"), Catch::Contains("store") && Catch::Contains(message));
    }
}
