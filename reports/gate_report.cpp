#include "reports/gate_report.hpp"

#include "harness/io/output_files.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {
namespace {

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += ch;
        }
    }
    return out;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
}

std::size_t failures(const GateResult& r) {
    return std::count_if(r.outcomes.begin(), r.outcomes.end(), [](const GateOutcome& o) { return !o.passed; });
}

}  // namespace

std::string gate_summary(const std::vector<GateCheck>& checks, const GateResult& result) {
    std::string out;
    for (const auto& o : result.outcomes) {
        const GateCheck& c = checks[o.check];
        out += fmt::format("{} {}/{}: {}: {}\n", o.passed ? "PASS" : "FAIL", c.scene, o.scheme, c.name, o.detail);
        if (!o.passed && !c.why.empty()) out += fmt::format("     why it matters: {}\n", c.why);
    }
    const std::size_t failed = failures(result);
    out += fmt::format("{} of {} checks passed", result.outcomes.size() - failed, result.outcomes.size());
    if (failed) {
        std::vector<std::string> schemes;
        for (const auto& o : result.outcomes)
            if (!o.passed && std::find(schemes.begin(), schemes.end(), o.scheme) == schemes.end()) schemes.push_back(o.scheme);
        std::string list;
        for (const auto& s : schemes) list += (list.empty() ? "" : ", ") + s;
        out += fmt::format("; failing: {}", list);
    }
    return out + "\n";
}

std::string gate_junit(const std::vector<GateCheck>& checks, const GateResult& result) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += fmt::format("<testsuites name=\"rotbench gate\" tests=\"{}\" failures=\"{}\">\n", result.outcomes.size(),
                       failures(result));
    out += fmt::format("  <testsuite name=\"rotbench gate\" tests=\"{}\" failures=\"{}\">\n", result.outcomes.size(),
                       failures(result));
    for (const auto& o : result.outcomes) {
        const GateCheck& c = checks[o.check];
        out += fmt::format("    <testcase classname=\"{}.{}\" name=\"{}\" file=\"{}\"", xml_escape(c.scene), xml_escape(o.scheme),
                           xml_escape(c.name), xml_escape(c.location));
        if (o.passed) {
            out += fmt::format(">\n      <system-out>{}</system-out>\n    </testcase>\n", xml_escape(o.detail));
        } else {
            const std::string message = o.detail + (c.why.empty() ? "" : ". Why it matters: " + c.why);
            out += fmt::format(">\n      <failure message=\"{}\" type=\"{}\">{}</failure>\n    </testcase>\n",
                               xml_escape(message), xml_escape(c.criterion), xml_escape(message));
        }
    }
    return out + "  </testsuite>\n</testsuites>\n";
}

std::string gate_csv(const std::vector<GateCheck>& checks, const GateResult& result) {
    std::string out = "scene,scheme,check,criterion,metric,bound,measured,passed,detail\n";
    for (const auto& o : result.outcomes) {
        const GateCheck& c = checks[o.check];
        out += fmt::format("{},{},{},{},{},{},{},{},{}\n", c.scene, o.scheme, csv_field(c.name), c.criterion, c.metric,
                           format_number(c.bound), format_number(o.measured), o.passed ? 1 : 0, csv_field(o.detail));
    }
    return out;
}

}  // namespace rotbench
