#include "reports/panels.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {
namespace {

const std::vector<std::string> family_order = {"seed schemes", "kick-drift-kick", "others"};

}  // namespace

std::string family_title(const ResultSet& set, const std::string& scheme) {
    const SchemeInfo* info = set.scheme(scheme);
    if (!info || !info->claims.sound) return "others";
    if (info->claims.family == "seed") return "seed schemes";
    if (info->claims.family == "kick_drift_kick") return "kick-drift-kick";
    return "others";
}

std::vector<Panel> family_panels(const ResultSet& set, const std::vector<std::string>& schemes,
                                 const std::vector<std::string>& best) {
    std::vector<Panel> panels;
    for (const auto& family : family_order) {
        std::vector<std::string> members;
        for (const auto& s : schemes)
            if (family_title(set, s) == family) members.push_back(s);
        const std::size_t parts = (members.size() + max_series_per_panel - 1) / max_series_per_panel;
        for (std::size_t p = 0; p < parts; ++p) {
            const std::size_t from = p * members.size() / parts, to = (p + 1) * members.size() / parts;
            panels.push_back({parts > 1 ? fmt::format("{} ({} of {})", family, p + 1, parts) : family,
                              std::vector<std::string>(members.begin() + from, members.begin() + to)});
        }
    }
    if (best.size() > 1) panels.push_back({"best of each family", best});
    return panels;
}

std::vector<std::string> best_of_families(const ResultSet& set, const std::vector<std::string>& schemes,
                                          const std::function<double(const std::string&)>& score) {
    std::vector<std::string> best;
    for (const auto& family : family_order) {
        std::string chosen;
        double least = INFINITY;
        for (const auto& s : schemes) {
            const SchemeInfo* info = set.scheme(s);
            if (family_title(set, s) != family || (info && !info->claims.sound)) continue;
            const double v = score(s);
            if (v < least) least = v, chosen = s;
        }
        if (!chosen.empty()) best.push_back(chosen);
    }
    return best;
}

std::string panel_grid_script(const std::string& output_line, const std::string& title, const std::string& setup,
                              const std::vector<Panel>& panels, const std::function<std::string(std::size_t)>& plot) {
    const std::size_t columns = panels.size() > 1 ? 2 : 1, rows = (panels.size() + columns - 1) / columns;
    const double width = 640.0 * static_cast<double>(columns), height = 380.0 * static_cast<double>(rows) + 40.0;
    std::string s = fmt::format("set terminal svg size {:.0f},{:.0f} dynamic noenhanced font 'sans,11'\n{}{}", width, height,
                                output_line, setup);
    s += fmt::format("set termoption noenhanced\nset multiplot title '{}'\n", title);
    const double top = 1.0 - 40.0 / height, cell_h = (top - 0.0) / static_cast<double>(rows), cell_w = 1.0 / columns;
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const double x0 = cell_w * static_cast<double>(i % columns), y1 = top - cell_h * static_cast<double>(i / columns);
        // The plot area: 11 % of the cell for the y labels, 30 % for the key, which sits there.
        s += fmt::format("set lmargin at screen {:.4f}\nset rmargin at screen {:.4f}\nset tmargin at screen {:.4f}\n"
                         "set bmargin at screen {:.4f}\nset title '{}'\nset key at screen {:.4f},{:.4f} left top Left reverse\n",
                         x0 + 0.11 * cell_w, x0 + 0.70 * cell_w, y1 - 0.10 * cell_h, y1 - cell_h + 0.16 * cell_h,
                         panels[i].title, x0 + 0.72 * cell_w, y1 - 0.10 * cell_h);
        s += plot(i);
    }
    return s + "unset multiplot\n";
}

std::string series_colour(std::size_t i) {
    static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    return fmt::format("lc rgb '{}'", colours[i % 8]);
}

std::string series_style(std::size_t i) {
    static const int points[] = {7, 5, 9, 11, 13, 4, 6, 8};
    return fmt::format("{} pt {}", series_colour(i), points[i % 8]);
}

}  // namespace rotbench
