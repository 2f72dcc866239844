#include "reports/cost_table.hpp"

#include "reports/escape.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace rotbench {
namespace {

std::string number(double value, const char* format, double scale = 1.0) {
    if (std::isnan(value)) return "";
    return fmt::format(fmt::runtime(format), scale * value);
}

// The largest value of a column over the rows, and the scheme it belongs to.
std::pair<double, std::string> largest(const std::vector<CostRow>& rows, const std::vector<std::string>& columns) {
    std::pair<double, std::string> worst{0.0, ""};
    for (const CostRow& r : rows)
        for (const auto& c : columns)
            if (r.value(c) > worst.first) worst = {r.value(c), r.scheme};
    return worst;
}

std::string batched_table(const std::vector<CostRow>& rows, bool thorough) {
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
    for (const CostRow& r : rows)
        md += fmt::format("| {}{} | {} | {} | {} | {} | {} | {} |\n", r.scheme,
                          std::isnan(r.value("bodies")) || r.value("bodies") == 1e6 ? "" : number(r.value("bodies"), " ({:.0e} bodies)"),
                          number(r.value("ns_batched"), "{:.1f}"), number(r.value("ns_batched_spread"), "{:.1f} %", 100.0),
                          number(r.value("ns_alone"), "{:.1f}"), number(r.value("ns_alone_spread"), "{:.1f} %", 100.0),
                          number(r.value("speedup"), "{:.2f}x"), number(r.value("ns_ratio_to_direct"), "{:.2f}"));
    return md;
}

std::string instruction_table(const std::vector<CostRow>& rows) {
    std::string md;
    md += "\n*Instruction counts* per body-step, by callgrind (1000 bodies batched, and one body), which do not depend on the "
          "machine's load. What limits a scheme: *memory share* is load_store's batched time over the scheme's (the part "
          "that moving the state alone takes); *libm* is the part of its instructions, one body at a time, spent in sin, cos "
          "and the like (the packs' are inlined and cannot be counted apart).\n\n"
          "| scheme | instr. batched | instr. one at a time | instr. / direct | libm | memory share |\n|---|--:|--:|--:|--:|--:|\n";
    for (const CostRow& r : rows) {
        if (std::isnan(r.value("instr_alone")) && std::isnan(r.value("instr_batched"))) continue;
        md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", r.scheme, number(r.value("instr_batched"), "{:.0f}"),
                          number(r.value("instr_alone"), "{:.0f}"), number(r.value("instr_ratio_to_direct"), "{:.2f}"),
                          number(r.value("libm_instr_alone") / r.value("instr_alone"), "{:.0f} %", 100.0),
                          number(r.value("memory_share"), "{:.0f} %", 100.0));
    }
    return md;
}

std::string public_table(const std::vector<CostRow>& rows) {
    std::string md;
    std::string against;
    for (const CostRow& r : rows)
        if (!r.public_code.empty())
            against += fmt::format("| {} | `{}` | {} | {} | {} |\n", r.scheme, r.public_code, number(r.value("public_ratio_batched"), "{:.2f}"),
                                   number(r.value("public_ratio_alone"), "{:.2f}"), number(r.value("public_ratio_runs_differ"), "{:.1f} %", 100.0));
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

std::string repeatability(const std::vector<CostRow>& rows, bool thorough) {
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
        for (const CostRow& r : rows)
            if (r.value("speedup_runs_differ") > 0.03 || r.value("ns_ratio_runs_differ") > 0.03) noisy += (noisy.empty() ? "" : ", ") + r.scheme;
        md += noisy.empty() ? " The machine's noise stayed within 3 % on every ratio."
                            : " The machine's noise exceeds 3 % on the ratios of " + noisy + ": read their figures as that uncertain.";
    }
    return md;
}

}  // namespace

std::string cost_section(const std::optional<CostTable>& table, const std::filesystem::path& dir) {
    std::string md = "## " + cost_heading + "\n\n"
                     "The report ranks schemes by `ns_per_step` alone (section Verdicts). The figures here are of other "
                     "kinds and appear only here: the time per body-step of 1e6 bodies stepped together, and instruction "
                     "counts.\n\n";
    if (!table) {
        return md + "No cost table here: `benchmarks/cost.py BUILD " + dir.string() + "` measures it and "
                    "`rotbench report " + dir.string() + "` then includes it (README \"Speed\").\n\n";
    }
    md += batched_table(table->rows, table->thorough) + instruction_table(table->rows) + public_table(table->rows) +
          repeatability(table->rows, table->thorough);
    md += " Instruction counts are exact: two counts of the same binary agree to the instruction.\n\n";
    // A scheme whose process crashed, threw or hung has only its id and `failure`: named once, below the tables.
    std::string not_costed;
    for (const CostRow& r : table->failed)
        not_costed += fmt::format("{}`{}` ({})", not_costed.empty() ? "" : ", ", markdown_cell(r.scheme), markdown_cell(r.failure));
    if (!not_costed.empty()) md += "Not costed, their process having failed (the others were costed without them): " + not_costed + ".\n\n";
    return md;
}

}  // namespace rotbench
