#include "reports/gnuplot.hpp"

#include "harness/exec/isolation.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/program_path.hpp"

#include <fmt/format.h>
#include <unistd.h>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

// A plot takes gnuplot well under a second; a minute means it is stuck.
constexpr double gnuplot_seconds = 60;

// A whole SVG ends with its closing tag.
bool whole_svg(const fs::path& file) {
    const auto text = read_file(file);
    if (!text || text->size() < 6) return false;
    const auto end = text->find_last_not_of(" \n\r\t");
    return end != std::string::npos && text->compare(end + 1 >= 6 ? end + 1 - 6 : 0, 6, "</svg>") == 0;
}

}  // namespace

std::string gnuplot_output(const std::string& svg_name) {
    return "if (!exists('out')) out = '" + svg_name + "'\nset output out\n";
}

Drawn draw_with_gnuplot(const OutputDir& dir, const std::string& relative_script, const std::string& script,
                        const std::string& relative_svg) {
    dir.write(relative_script, script);
    static const std::string gnuplot = find_on_path("gnuplot");
    if (gnuplot.empty()) return {false, "gnuplot is not installed"};
    const fs::path svg = dir.claim(relative_svg);
    const auto [temporary, fd] = open_temporary(svg);  // gnuplot writes into it
    ::close(fd);
    const fs::path script_file = dir.path() / relative_script;

    // The output name is the script's string: quotes in it are escaped for gnuplot's '...'.
    std::string out_name;
    for (char c : fs::absolute(temporary).string()) out_name += c == '\'' ? std::string("''") : std::string(1, c);
    // Under a time limit, as every program rotbench starts: a gnuplot that never exits costs its
    // plot, not the command.
    const WorkerOutput ran = run_program({gnuplot, "-e", "out='" + out_name + "'", script_file.filename().string()},
                                         script_file.parent_path().string(), gnuplot_seconds, isolation_memory(1), "gnuplot");
    std::error_code ec;
    if (!ran.failure.empty() || !whole_svg(temporary)) {
        fs::remove(temporary, ec);
        release_temporary(temporary);
        return {false, fmt::format("gnuplot failed on {} ({})", relative_script, ran.failure.empty() ? "no whole SVG" : ran.failure)};
    }
    fs::rename(temporary, svg, ec);
    const std::string renamed = ec ? ec.message() : "";
    if (ec) fs::remove(temporary, ec);
    release_temporary(temporary);
    if (!renamed.empty()) throw OutputError("cannot write " + svg.string() + ": " + renamed);
    return {true, ""};
}

}  // namespace rotbench
