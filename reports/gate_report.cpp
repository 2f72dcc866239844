#include "reports/gate_report.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "reports/escape.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <nlohmann/json.hpp>

namespace rotbench {
namespace {

std::string tag(const Verdict& v) {
    const std::string o = v.outcome();
    return o == "pass" ? "PASS" : o == "fail" ? "FAIL" : o == "expected failure" ? "XFAIL" : "XPASS";
}

std::string counts(const GateResult& r) {
    return fmt::format("{} checks: {} passed, {} failed, {} expected failures, {} unexpected passes", r.verdicts.size(),
                       r.count("pass"), r.count("fail"), r.count("expected failure"), r.count("unexpected pass"));
}

// The schemes in the order they first appear, and whether each is clean (every verdict ok).
std::vector<std::pair<std::string, bool>> schemes(const GateResult& r) {
    std::vector<std::pair<std::string, bool>> out;
    for (const auto& v : r.verdicts) {
        auto it = std::find_if(out.begin(), out.end(), [&](const auto& s) { return s.first == v.of.scheme; });
        if (it == out.end()) out.push_back({v.of.scheme, v.ok()});
        else it->second = it->second && v.ok();
    }
    return out;
}

// "file:line" split for JUnit and annotations.
std::pair<std::string, std::string> file_and_line(const std::string& location) {
    const auto colon = location.rfind(':');
    if (colon == std::string::npos) return {location, "1"};
    return {location.substr(0, colon), location.substr(colon + 1)};
}

}  // namespace

std::string gate_summary(const GateResult& result) {
    std::string out;
    for (const auto& w : result.warnings) out += "WARNING " + terminal_line(w) + "\n";
    for (const auto& v : result.verdicts) {
        out += terminal_line(fmt::format("{} {}/{}: {}", tag(v), v.of.scene, v.of.scheme, v.message)) + "\n";
        if (v.of.expected_to_fail) out += "     expected to fail: " + terminal_line(v.of.expected_reason) + "\n";
    }
    out += counts(result);
    std::vector<std::string> failing;
    for (const auto& [scheme, ok] : schemes(result))
        if (!ok) failing.push_back(scheme);
    if (!failing.empty()) out += "; failing: " + join(failing, ", ");
    return out + "\n";
}

std::string gate_junit(const GateResult& result, const std::string& gate_file) {
    const auto failures = result.count("fail") + result.count("unexpected pass");
    double seconds = 0;
    for (const auto& v : result.verdicts) seconds += v.seconds;
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += fmt::format("<testsuites name=\"rotbench gate\" tests=\"{}\" failures=\"{}\" skipped=\"{}\" time=\"{:.3f}\">\n",
                       result.verdicts.size(), failures, result.count("expected failure"), seconds);
    for (const auto& [scheme, ok] : schemes(result)) {
        std::vector<const Verdict*> mine;
        for (const auto& v : result.verdicts)
            if (v.of.scheme == scheme) mine.push_back(&v);
        const auto failed = std::count_if(mine.begin(), mine.end(), [](const Verdict* v) { return !v->ok(); });
        const auto skipped = std::count_if(mine.begin(), mine.end(), [](const Verdict* v) { return v->outcome() == "expected failure"; });
        double time = 0;
        for (const Verdict* v : mine) time += v->seconds;
        out += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" skipped=\"{}\" time=\"{:.3f}\">\n",
                           xml_attribute(scheme), mine.size(), failed, skipped, time);
        // What judged what: the gate file and, for a plug-in's scheme, the library (its hash and build).
        std::vector<std::pair<std::string, std::string>> properties = {{"gate_file", gate_file}, {"gate_file_fnv1a", result.gate_file_hash}};
        if (const auto it = result.schemes.find(scheme); it != result.schemes.end() && !it->second.plugin_path.empty())
            properties.insert(properties.end(), {{"plugin", it->second.plugin_path},
                                                 {"plugin_fnv1a", it->second.plugin_hash},
                                                 {"plugin_build", it->second.plugin_build}});
        out += "    <properties>\n";
        for (const auto& [name, value] : properties)
            out += fmt::format("      <property name=\"{}\" value=\"{}\"/>\n", name, xml_attribute(value));
        out += "    </properties>\n";
        for (const Verdict* v : mine) {
            const auto [file, line] = file_and_line(v->of.location.empty() ? gate_file : v->of.location);
            out += fmt::format("    <testcase classname=\"rotbench.gate.{}\" name=\"{}\" file=\"{}\" line=\"{}\" time=\"{:.3f}\"",
                               xml_attribute(scheme), xml_attribute(v->of.id + " on " + v->of.scene), xml_attribute(file),
                               xml_attribute(line), v->seconds);
            const std::string o = v->outcome();
            if (o == "pass") {
                out += fmt::format(">\n      <system-out>{}</system-out>\n    </testcase>\n", xml_text(v->message));
            } else if (o == "expected failure") {
                out += fmt::format(">\n      <skipped message=\"{}\"/>\n      <system-out>{}</system-out>\n    </testcase>\n",
                                   xml_attribute("expected failure: " + v->of.expected_reason), xml_text(v->message));
            } else {
                const std::string message = (o == "unexpected pass" ? "unexpected pass (expected to fail: " + v->of.expected_reason + "): " : "") +
                                            v->message;
                out += fmt::format(">\n      <failure message=\"{}\" type=\"{}\">{}</failure>\n    </testcase>\n",
                                   xml_attribute(message), xml_attribute(v->of.criterion), xml_text(message));
            }
        }
        std::string warnings;
        for (const auto& w : result.warnings)
            if (w.rfind(scheme + " ", 0) == 0) warnings += w + "\n";
        if (!warnings.empty()) out += "    <system-err>" + xml_text(warnings) + "</system-err>\n";
        out += "  </testsuite>\n";
    }
    return out + "</testsuites>\n";
}

std::string gate_csv(const GateResult& result) {
    std::string out = "scene,scheme,check,family,criterion,outcome,measured,lo,hi,bound,message\n";
    for (const auto& v : result.verdicts)
        out += csv_record({v.of.scene, v.of.scheme, v.of.id, v.of.family, v.of.criterion, v.outcome(), format_number(v.measured),
                           format_number(v.lo), format_number(v.hi), format_number(v.bound), v.message});
    return out;
}

std::string gate_summary_json(const GateResult& result, const std::string& gate_file, const Provenance& p) {
    using json = nlohmann::ordered_json;  // "format" first: the file says what it is
    const auto number_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    json checks = json::array();
    std::map<std::string, json> by_scheme;  // filled in the order of the verdicts below
    for (const auto& v : result.verdicts) {
        checks.push_back({{"check", valid_utf8(v.of.id)},
                          {"family", v.of.family},
                          {"criterion", v.of.criterion},
                          {"scene", v.of.scene},
                          {"scheme", v.of.scheme},
                          {"outcome", v.outcome()},
                          {"ok", v.ok()},
                          {"expected_to_fail", v.of.expected_to_fail},
                          {"expected_reason", valid_utf8(v.of.expected_reason)},
                          {"measured", number_or_null(v.measured)},
                          {"interval", {number_or_null(v.lo), number_or_null(v.hi)}},
                          {"bound", number_or_null(v.bound)},
                          {"message", valid_utf8(v.message)},
                          {"location", valid_utf8(v.of.location)},
                          {"seconds", v.seconds}});
        json& s = by_scheme[v.of.scheme];
        if (s.is_null()) s = {{"scheme", v.of.scheme}, {"ok", true}, {"checks", 0}, {"failed", 0}, {"expected_failures", 0},
                              {"observed_orders", json::object()}};
        s["checks"] = s["checks"].get<int>() + 1;
        if (!v.ok()) s["ok"] = false, s["failed"] = s["failed"].get<int>() + 1;
        if (v.outcome() == "expected failure") s["expected_failures"] = s["expected_failures"].get<int>() + 1;
        if ((v.of.id == "order_without_torque" || v.of.id == "order_with_torque") && std::isfinite(v.measured))
            s["observed_orders"][v.of.id + " on " + v.of.scene] = {{"order", v.measured}, {"interval", {v.lo, v.hi}}, {"claimed", v.bound}};
    }
    // The cost of each scheme where the gate timed it: ns per step of its timed runs.
    for (const auto& r : result.runs)
        if (r.spec.timed && std::isfinite(r.value(metric::ns_per_step)) && by_scheme.count(r.spec.scheme))
            by_scheme[r.spec.scheme][metric::ns_per_step][r.spec.scene + " dt=" + format_number(r.spec.dt)] = r.value(metric::ns_per_step);
    json schemes_json = json::array();
    for (const auto& [scheme, ok] : schemes(result)) {
        json& s = by_scheme[scheme];
        const auto it = result.schemes.find(scheme);
        s["plugin"] = it == result.schemes.end() || it->second.plugin_path.empty()
                          ? json(nullptr)
                          : json{{"path", valid_utf8(it->second.plugin_path)}, {"fnv1a", it->second.plugin_hash}, {"build", it->second.plugin_build}};
        schemes_json.push_back(s);
    }
    json warnings = json::array();
    for (const auto& w : result.warnings) warnings.push_back(valid_utf8(w));
    const json summary = {{"format", "rotbench-gate-summary 1"},
                          {"gate_file", valid_utf8(gate_file)},
                          {"gate_file_fnv1a", result.gate_file_hash},
                          {"passed", result.passed()},
                          {"counts",
                           {{"checks", result.verdicts.size()},
                            {"pass", result.count("pass")},
                            {"fail", result.count("fail")},
                            {"expected_failure", result.count("expected failure")},
                            {"unexpected_pass", result.count("unexpected pass")}}},
                          {"provenance",
                           {{"version", p.version},
                            {"commit", p.commit},
                            {"compiler", p.compiler},
                            {"build_type", p.build_type},
                            {"flags", p.flags},
                            {"cpu", p.cpu},
                            {"date", p.date}}},
                          {"warnings", warnings},
                          {"schemes", schemes_json},
                          {"checks", checks}};
    return summary.dump(2) + "\n";
}

std::string gate_markdown(const GateResult& result, const std::string& verb, const std::string& against) {
    std::string md = fmt::format("## rotbench {}: {}\n\n`{}`: {}.\n\n", verb, result.passed() ? "passed" : "FAILED",
                                 markdown_cell(against), counts(result));
    for (const auto& w : result.warnings) md += "> **Warning:** " + markdown_cell(w) + "\n>\n";
    md += "\n| scheme | verdict | checks | failed | expected failures |\n|---|---|---:|---:|---:|\n";
    for (const auto& [scheme, ok] : schemes(result)) {
        std::size_t n = 0, failed = 0, expected = 0;
        for (const auto& v : result.verdicts)
            if (v.of.scheme == scheme) n += 1, failed += !v.ok(), expected += v.outcome() == "expected failure";
        md += fmt::format("| `{}` | {} | {} | {} | {} |\n", markdown_cell(scheme), ok ? "ok" : "**failed**", n, failed, expected);
    }
    std::string failures;
    for (const auto& v : result.verdicts)
        if (!v.ok()) failures += fmt::format("- **{}** `{}` on `{}`: {}\n", tag(v), markdown_cell(v.of.scheme), markdown_cell(v.of.scene),
                                             markdown_cell(v.message));
    if (!failures.empty()) md += "\n### Failures\n\n" + failures;
    return md + "\n";
}

std::string gate_annotations(const GateResult& result) {
    std::string out;
    for (const auto& w : result.warnings) out += "::warning title=rotbench gate::" + actions_message(w) + "\n";
    for (const auto& v : result.verdicts) {
        if (v.ok()) continue;
        const auto [file, line] = file_and_line(v.of.location);
        out += fmt::format("::error file={},line={},title={}::{}{}\n", actions_property(file), actions_property(line),
                           actions_property("rotbench gate: " + v.of.scheme + " " + v.of.id),
                           v.outcome() == "unexpected pass" ? "unexpected pass: " : "", actions_message(v.message));
    }
    return out;
}

}  // namespace rotbench
