// Progress of a long verb (run, gate, stability) on stderr: how many items are done, the one
// in flight and an estimate of the time left, from the items' weights (their step counts).
// On a terminal one status line is rewritten in place; otherwise a line is written at most
// every 5 s, as items finish; quiet writes nothing. Safe to call from several threads.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

namespace rotbench {

class Progress {
public:
    enum class Mode { quiet, terminal, lines };
    // terminal when `err` is the process's stderr and that is a terminal; lines otherwise.
    static Mode mode_for(const std::ostream& err, bool quiet);

    // One weight per item, in any unit (the ETA uses only their ratios).
    Progress(std::ostream& err, Mode mode, std::string verb, std::vector<double> weights);
    ~Progress();  // clears the status line
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void started(std::size_t item, std::string label);
    void finished(std::size_t item, bool failed = false);
    // A line that stays (a failed run) on `out`, with the status line cleared before it.
    void note(std::ostream& out, const std::string& line);

private:
    void show(bool force);  // with the mutex held

    std::ostream& err_;
    Mode mode_;
    std::string verb_;
    std::vector<double> weights_;
    double total_weight_ = 0, done_weight_ = 0;
    std::size_t done_ = 0, failed_ = 0;
    std::map<std::size_t, std::string> in_flight_;
    std::chrono::steady_clock::time_point start_, last_line_;
    bool shown_ = false;
    std::mutex mutex_;
};

}  // namespace rotbench
