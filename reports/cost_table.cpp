#include "reports/cost_table.hpp"

#include "reports/output_files.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <sstream>
#include <vector>

namespace rotbench {
namespace {

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
}

std::string number(const std::string& text, const char* format, double scale = 1.0) {
    if (text.empty()) return "";
    return fmt::format(fmt::runtime(format), scale * std::stod(text));
}

}  // namespace

std::string cost_section(const std::filesystem::path& dir) {
    std::string md = "## Cost per body-step\n\n";
    const auto text = read_file(dir / "cost.csv");
    if (!text) {
        return md + "No cost table here: `benchmarks/cost.sh BUILD " + dir.string() + "` measures it (about 2 min) and "
                    "`rotbench report " + dir.string() + "` then includes it (README \"Speed\").\n\n";
    }
    std::stringstream in(*text);
    std::string line;
    std::getline(in, line);
    const auto header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const auto cells = split(line);
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
        rows.push_back(std::move(row));
    }
    md += "Each scheme stepping 1e6 bodies with random states and torques read from memory (`rotbench_bench`, "
          "Google Benchmark, median of 5 repetitions; spread = (max - min) / median), batched and one body at a time "
          "through the scheme interface, and its instructions per body-step counted by callgrind (1000 bodies "
          "batched, and one body), which do not depend on the machine's load. `load_store` reads and writes the "
          "same state and computes nothing: the floor of the batched loops. The seed schemes step packs of four "
          "bodies (AVX2, `schemes/simd.hpp`); the others one body at a time in both columns.\n\n"
          "| scheme | ns batched | spread | ns one at a time | spread | speed-up | instr. batched | instr. one at a time "
          "| ns / direct | instr. / direct |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    double worst_spread = 0;
    for (auto& r : rows) {
        for (const char* s : {"ns_batched_spread", "ns_alone_spread"})
            if (!r[s].empty()) worst_spread = std::max(worst_spread, std::stod(r[s]));
        md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r["scheme"], number(r["ns_batched"], "{:.1f}"),
                          number(r["ns_batched_spread"], "{:.1f} %", 100.0), number(r["ns_alone"], "{:.1f}"),
                          number(r["ns_alone_spread"], "{:.1f} %", 100.0), number(r["speedup"], "{:.2f}x"),
                          number(r["instr_batched"], "{:.0f}"), number(r["instr_alone"], "{:.0f}"),
                          number(r["ns_ratio_to_direct"], "{:.2f}"), number(r["instr_ratio_to_direct"], "{:.2f}"));
    }
    md += fmt::format("\nLargest spread of a time over its repetitions: {:.1f} %. Instruction counts are exact: two "
                      "counts of the same binary agree to the instruction.\n\n",
                      100.0 * worst_spread);
    return md;
}

}  // namespace rotbench
