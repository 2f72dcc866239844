#include "reports/panels.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {
namespace {

const std::vector<std::string> family_order = {"seed schemes", "kick-drift-kick", "candidates", "others"};

const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
                               "#7f7f7f", "#bcbd22", "#393b79", "#ad494a", "#637939", "#8c6d31", "#7b4173", "#3182bd"};

// A scheme's place among the schemes of the set (described, or of its runs), in id order: the
// same in every plot drawn from one set.
std::size_t scheme_index(const ResultSet& set, const std::string& scheme) {
    std::vector<std::string> ids;
    for (const auto& r : set.runs) ids.push_back(r.spec.scheme);
    for (const auto& [id, info] : set.schemes) ids.push_back(id);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return static_cast<std::size_t>(std::lower_bound(ids.begin(), ids.end(), scheme) - ids.begin());
}

std::string series_colour(std::size_t i) { return fmt::format("lc rgb '{}'", colours[i % 16]); }

}  // namespace

std::string family_title(const ResultSet& set, const std::string& scheme) {
    const SchemeInfo* info = set.scheme(scheme);
    if (!info || !info->claims.sound) return "others";
    if (!info->plugin_path.empty() || info->client) return "candidates";
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
        // The plot area: 15 % of the cell for the y tick labels and title (room for "1e-15" and
        // the title at 11 pt), 36 % for the key, which sits there (a 16-letter id and "(= id)").
        s += fmt::format("set lmargin at screen {:.4f}\nset rmargin at screen {:.4f}\nset tmargin at screen {:.4f}\n"
                         "set bmargin at screen {:.4f}\nset title '{}'\nset key at screen {:.4f},{:.4f} left top Left reverse samplen 1.5 font ',10'\n",
                         x0 + 0.15 * cell_w, x0 + 0.62 * cell_w, y1 - 0.10 * cell_h, y1 - cell_h + 0.16 * cell_h,
                         panels[i].title, x0 + 0.635 * cell_w, y1 - 0.10 * cell_h);
        s += plot(i);
    }
    return s + "unset multiplot\n";
}

std::string scheme_colour(const ResultSet& set, const std::string& scheme) { return series_colour(scheme_index(set, scheme)); }

std::string scheme_style(const ResultSet& set, const std::string& scheme, std::size_t layer) {
    static const int points[] = {7, 5, 9, 11, 13, 4, 6, 8};
    const std::size_t k = scheme_index(set, scheme);
    const double wider = static_cast<double>(max_series_per_panel - std::min(layer, max_series_per_panel - 1));
    return fmt::format("{} pt {} lw {:.2f} ps {:.2f}", series_colour(k), points[k % 8], 0.8 + 0.25 * wider, 0.4 + 0.1 * wider);
}

}  // namespace rotbench
