#include "reports/cost_table.hpp"

#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "reports/escape.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace rotbench {
namespace {

using Row = std::map<std::string, std::string>;

std::optional<std::vector<Row>> read_rows(const std::filesystem::path& dir) {
    const std::string name = (dir / "cost.csv").string();
    const auto text = read_file(dir / "cost.csv");
    if (!text) return std::nullopt;
    const std::vector<CsvRow> records = parse_csv(*text, name);
    if (records.empty()) return std::vector<Row>{};
    const std::vector<std::string>& header = records.front().fields;
    std::vector<Row> rows;
    // A hand-edited table is input: a field that should be a number and is not is refused
    // here, with its line and column, not met later by the formatting.
    const std::set<std::string> text_columns = {"scheme", "public", "mode", "failure"};
    for (auto record = records.begin() + 1; record != records.end(); ++record) {
        if (record->size() == 1 && (*record)[0].empty()) continue;  // a blank line
        Row row;
        for (std::size_t i = 0; i < header.size() && i < record->size(); ++i) {
            if (!text_columns.count(header[i]) && !(*record)[i].empty())
                parse_finite((*record)[i], where(name, *record) + ": column " + header[i]);
            row[header[i]] = (*record)[i];
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string number(const std::string& text, const char* format, double scale = 1.0) {
    if (text.empty()) return "";
    return fmt::format(fmt::runtime(format), scale * std::stod(text));
}

// The largest value of a column over the rows, and the scheme it belongs to.
std::pair<double, std::string> largest(const std::vector<Row>& rows, const std::vector<std::string>& columns) {
    std::pair<double, std::string> worst{0.0, ""};
    for (const Row& r : rows)
        for (const auto& c : columns)
            if (r.count(c) && !r.at(c).empty() && std::stod(r.at(c)) > worst.first) worst = {std::stod(r.at(c)), r.at("scheme")};
    return worst;
}

std::string batched_table(const std::vector<Row>& rows, bool thorough) {
    std::string md;
    md += fmt::format(
        "*Batched 1e6-body time*: each scheme stepping 1e6 bodies with random states and torques read from memory "
        "(`rotbench_bench`, Google Benchmark), batched and one body at a time through the scheme interface; {}, in random "
        "interleaved order; the least time of the repetitions, since the other tenants of the shared machine only add time; "
        "spread = (max - min) / least. A scheme of more than 5000 instructions per body-step is timed at 1e5 bodies (marked "
        "so), where moving its state is well under 1 % of its step. `load_store` reads and writes the same state and "
        "computes nothing: the floor of the batched loops. Schemes written as templates on their scalar step packs of four "
        "bodies (AVX2, `schemes/simd.hpp`).\n\n"
        "| scheme | batched (ns / body-step) | spread | one at a time (ns / body-step) | spread | speed-up | batched / direct |\n"
        "|---|--:|--:|--:|--:|--:|--:|\n",
        thorough ? "10 processes of 3 repetitions (`benchmarks/cost.py --thorough`), since times differ between processes more "
                   "than repetitions average out"
                 : "two consecutive tables, one process of 2 repetitions each (`benchmarks/cost.py`; `--thorough` runs the "
                   "10-process study)");
    for (auto r : rows)
        md += fmt::format("| {}{} | {} | {} | {} | {} | {} | {} |\n", r["scheme"],
                          r["bodies"].empty() || std::stod(r["bodies"]) == 1e6 ? "" : number(r["bodies"], " ({:.0e} bodies)"),
                          number(r["ns_batched"], "{:.1f}"), number(r["ns_batched_spread"], "{:.1f} %", 100.0),
                          number(r["ns_alone"], "{:.1f}"), number(r["ns_alone_spread"], "{:.1f} %", 100.0),
                          number(r["speedup"], "{:.2f}x"), number(r["ns_ratio_to_direct"], "{:.2f}"));
    return md;
}

std::string instruction_table(const std::vector<Row>& rows) {
    std::string md;
    md += "\n*Instruction counts* per body-step, by callgrind (1000 bodies batched, and one body), which do not depend on the "
          "machine's load. What limits a scheme: *memory share* is load_store's batched time over the scheme's (the part "
          "that moving the state alone takes); *libm* is the part of its instructions, one body at a time, spent in sin, cos "
          "and the like (the packs' are inlined and cannot be counted apart).\n\n"
          "| scheme | instr. batched | instr. one at a time | instr. / direct | libm | memory share |\n|---|--:|--:|--:|--:|--:|\n";
    for (auto r : rows) {
        if (r["instr_alone"].empty() && r["instr_batched"].empty()) continue;
        const std::string libm = r["libm_instr_alone"].empty() || r["instr_alone"].empty()
                                     ? ""
                                     : fmt::format("{:.0f} %", 100.0 * std::stod(r["libm_instr_alone"]) / std::stod(r["instr_alone"]));
        md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", r["scheme"], number(r["instr_batched"], "{:.0f}"),
                          number(r["instr_alone"], "{:.0f}"), number(r["instr_ratio_to_direct"], "{:.2f}"), libm,
                          number(r["memory_share"], "{:.0f} %", 100.0));
    }
    return md;
}

std::string public_table(const std::vector<Row>& rows) {
    std::string md;
    std::string against;
    for (auto r : rows)
        if (!r["public"].empty())
            against += fmt::format("| {} | `{}` | {} | {} | {} |\n", r["scheme"], r["public"], number(r["public_ratio_batched"], "{:.2f}"),
                                   number(r["public_ratio_alone"], "{:.2f}"), number(r["public_ratio_runs_differ"], "{:.1f} %", 100.0));
    if (!against.empty())
        md += "\n*Against public codes*: each scheme beside the same algorithm as a public DEM or MD code computes it (its "
              "arithmetic read in that code's sources and written anew as the plug-in `rotbench_public_counterparts`, id "
              "`<scheme>__<code>`, built with the same flags and timed in the same runs; of several, the fastest one body at a "
              "time): the counterpart's time over the scheme's, batched at the table's size and one body at a time; above 1, "
              "rotbench's scheme is faster. *Tables "
              "differ*: how much the batched ratio differs between the two tables.\n\n"
              "| scheme | compared with | batched: public / rotbench | one at a time: public / rotbench | tables differ |\n"
              "|---|---|--:|--:|--:|\n" + against;
    return md;
}

std::string repeatability(const std::vector<Row>& rows, bool thorough) {
    std::string md;
    const auto spread = largest(rows, {"ns_batched_spread", "ns_alone_spread"});
    md += fmt::format("\nLargest spread of a time over its repetitions: {:.1f} % ({}).", 100.0 * spread.first, spread.second);
    const auto speedup = largest(rows, {"speedup_runs_differ"}), ratio = largest(rows, {"ns_ratio_runs_differ"});
    if (!speedup.second.empty() || !ratio.second.empty()) {
        md += fmt::format(" Repeatability: {} agree within {:.1f} % on every speed-up (largest difference: {}) and within {:.1f} % "
                          "on every batched / direct (largest: {}).",
                          thorough ? "the odd and the even processes, each a cost table of its own," : "the two consecutive tables",
                          100.0 * speedup.first, speedup.second, 100.0 * ratio.first, ratio.second);
        std::string noisy;
        for (const Row& r : rows) {
            const auto above = [&](const char* c) { return r.count(c) && !r.at(c).empty() && std::stod(r.at(c)) > 0.03; };
            if (above("speedup_runs_differ") || above("ns_ratio_runs_differ")) noisy += (noisy.empty() ? "" : ", ") + r.at("scheme");
        }
        md += noisy.empty() ? " The machine's noise stayed within 3 % on every ratio."
                            : " The machine's noise exceeds 3 % on the ratios of " + noisy + ": read their figures as that uncertain.";
    }
    return md;
}

}  // namespace

std::string cost_section(const std::filesystem::path& dir) {
    std::string md = "## " + cost_heading + "\n\n"
                     "The report ranks schemes by `ns_per_step` alone (section Verdicts). The figures here are of other "
                     "kinds and appear only here: the time per body-step of 1e6 bodies stepped together, and instruction "
                     "counts.\n\n";
    auto rows = read_rows(dir);
    if (!rows) {
        return md + "No cost table here: `benchmarks/cost.py BUILD " + dir.string() + "` measures it and "
                    "`rotbench report " + dir.string() + "` then includes it (README \"Speed\").\n\n";
    }
    // A scheme whose process crashed, threw or hung has only its id and `failure`: named once, below the tables.
    std::string not_costed;
    for (auto it = rows->begin(); it != rows->end();)
        if (it->count("failure") && !it->at("failure").empty()) {
            not_costed += fmt::format("{}`{}` ({})", not_costed.empty() ? "" : ", ", markdown_cell((*it)["scheme"]), markdown_cell(it->at("failure")));
            it = rows->erase(it);
        } else {
            ++it;
        }
    const bool thorough = !rows->empty() && rows->front().count("mode") && rows->front().at("mode") == "thorough";
    md += batched_table(*rows, thorough) + instruction_table(*rows) + public_table(*rows) + repeatability(*rows, thorough);
    md += " Instruction counts are exact: two counts of the same binary agree to the instruction.\n\n";
    if (!not_costed.empty()) md += "Not costed, their process having failed (the others were costed without them): " + not_costed + ".\n\n";
    return md;
}

}  // namespace rotbench
