// A scheme whose phases are timed on the thread's CPU clock as it runs: for the granular
// scenes, whose runs are too long to repeat for timing, the cost of a whole DEM step and the
// rotation's share of it come from the measured run itself (the counterpart of seed Table 4).
// Four clock reads per step cost about a microsecond, well under 1 % of such a step.
#pragma once

#include "harness/exec/timing.hpp"
#include "schemes/scheme.hpp"

#include <memory>

namespace rotbench {

class TimedScheme final : public RotationScheme {
public:
    explicit TimedScheme(std::unique_ptr<RotationScheme> inner) : inner_(std::move(inner)) {}
    void start(const Bodies& b) override { inner_->start(b); }
    void predict(Bodies& b, double dt) override {
        const double t0 = thread_cpu_seconds();
        inner_->predict(b, dt);
        seconds_ += thread_cpu_seconds() - t0;
    }
    void correct(Bodies& b, double dt) override {
        const double t0 = thread_cpu_seconds();
        inner_->correct(b, dt);
        seconds_ += thread_cpu_seconds() - t0;
    }
    std::size_t lanes() const override { return inner_->lanes(); }
    double seconds() const { return seconds_; }  // in predict and correct so far

private:
    std::unique_ptr<RotationScheme> inner_;
    double seconds_ = 0;
};

}  // namespace rotbench
