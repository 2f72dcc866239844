#include "harness/store/progress.hpp"

#include <fmt/format.h>
#include <iostream>
#include <numeric>
#include <unistd.h>

namespace rotbench {

Progress::Mode Progress::mode_for(const std::ostream& err, bool quiet) {
    if (quiet) return Mode::quiet;
    return &err == &std::cerr && ::isatty(STDERR_FILENO) ? Mode::terminal : Mode::lines;
}

Progress::Progress(std::ostream& err, Mode mode, std::string verb, std::vector<double> weights)
    : err_(err), mode_(mode), verb_(std::move(verb)), weights_(std::move(weights)),
      total_weight_(std::accumulate(weights_.begin(), weights_.end(), 0.0)),
      start_(std::chrono::steady_clock::now()), last_line_(start_) {}

Progress::~Progress() {
    if (mode_ == Mode::terminal && shown_) err_ << "\r\033[K" << std::flush;
}

void Progress::started(std::size_t item, std::string label) {
    std::lock_guard lock(mutex_);
    in_flight_[item] = std::move(label);
    show(false);
}

void Progress::finished(std::size_t item, bool failed) {
    std::lock_guard lock(mutex_);
    in_flight_.erase(item);
    ++done_;
    failed_ += failed ? 1 : 0;
    if (item < weights_.size()) done_weight_ += weights_[item];
    show(false);
}

void Progress::note(std::ostream& out, const std::string& line) {
    std::lock_guard lock(mutex_);
    if (mode_ == Mode::terminal && shown_) err_ << "\r\033[K" << std::flush;
    out << line << "\n" << std::flush;
    if (mode_ == Mode::terminal && shown_) show(true);
}

void Progress::show(bool force) {
    if (mode_ == Mode::quiet) return;
    const auto now = std::chrono::steady_clock::now();
    // A line every 5 s in a log; on a terminal at most ten redraws a second, and the first at once.
    const auto interval = mode_ == Mode::lines ? std::chrono::milliseconds(5000) : std::chrono::milliseconds(100);
    if (!force && (mode_ == Mode::lines || shown_) && now - last_line_ < interval) return;
    last_line_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::string text = fmt::format("{}: {} of {} done", verb_, done_, weights_.size());
    if (failed_) text += fmt::format(", {} failed", failed_);
    if (!in_flight_.empty()) text += ", running " + in_flight_.begin()->second;
    // The estimate waits for a tenth of the work: the first items say little of the rest.
    if (total_weight_ > 0 && done_weight_ >= 0.1 * total_weight_ && done_weight_ < total_weight_)
        text += fmt::format(", about {:.0f} s left", elapsed * (total_weight_ - done_weight_) / done_weight_);
    if (mode_ == Mode::terminal) err_ << "\r\033[K" << text << std::flush;
    else err_ << text << "\n" << std::flush;
    shown_ = true;
}

}  // namespace rotbench
