// Plots that stay readable with any number of schemes: the schemes are grouped by family
// (the seed's, kick-drift-kick, candidates, the others) into panels of at most 8 series, 8 being what
// colours and point types keep apart, drawn on a grid of panels of one size.
#pragma once

#include "harness/analysis/result_set.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rotbench {

inline constexpr std::size_t max_series_per_panel = 8;

struct Panel {
    std::string title;
    std::vector<std::string> schemes;
};

// The family a scheme is drawn with: "seed schemes", "kick-drift-kick", "candidates" (plug-ins
// and clients, judged beside the published schemes) or "others" (controls, sound = false).
std::string family_title(const ResultSet& set, const std::string& scheme);

// The schemes' families in that order, each cut into panels of at most 8; then, when `best`
// names more than one scheme (one per family), an overview panel of them.
std::vector<Panel> family_panels(const ResultSet& set, const std::vector<std::string>& schemes,
                                 const std::vector<std::string>& best = {});

// The best of each family among `schemes`: the least `score` (NaN and controls never best).
std::vector<std::string> best_of_families(const ResultSet& set, const std::vector<std::string>& schemes,
                                          const std::function<double(const std::string&)>& score);

// A gnuplot multiplot of `panels` on a grid of two columns: every panel gets the same plot
// area (screen margins fixed, the key in a strip to its right), so no key squashes a panel.
// `setup` is the script's common head (terminal line excluded); `plot(i)` the commands of panel i
// (its `plot` line, after the title is set).
std::string panel_grid_script(const std::string& output_line, const std::string& title, const std::string& setup,
                              const std::vector<Panel>& panels, const std::function<std::string(std::size_t)>& plot);

// The gnuplot style of a scheme, the same in every plot of a report: its colour and point type,
// from its place among the schemes of the runs (16 colours, 8 point types: distinct up to 128
// schemes); its colour alone, for lines without points. `layer`, the series' place in its
// panel, widens the lines and points drawn first, so that a curve another one covers still
// shows around it.
std::string scheme_style(const ResultSet& set, const std::string& scheme, std::size_t layer);
std::string scheme_colour(const ResultSet& set, const std::string& scheme);

}  // namespace rotbench
