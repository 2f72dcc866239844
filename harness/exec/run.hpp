// Making one run (harness/core/run.hpp): the scene it is made on, the step loop, the kinds of run.
#pragma once

#include "harness/core/run.hpp"
#include "harness/scenes/scene.hpp"
#include "schemes/scheme.hpp"

#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rotbench {

struct RunOptions {
    bool measure_time = true;  // off in tests: the timing run repeats the whole simulation
    int series_samples = 0;    // > 0: record about this many energy samples (and t = 0),
                               // in scenes that report an energy series
    // The limits of a plug-in's run in its worker process (harness/exec/isolation.hpp);
    // 0: derived from the run and the machine.
    double run_timeout = 0;
    std::size_t run_memory_mb = 0;
};

// The scene a run is made on: its parameters, and its t_end (0: the scene's own).
std::unique_ptr<Scene> scene_of(const RunSpec& spec);

// A scene probe's curve (as the run's series, unless it has one) and pictures, into the result.
void add_probe_pictures(const SceneProbe& probe, RunResult& r);

// Runs and measures; never throws for a failing scheme (the failure is recorded), but
// throws InputError for unknown ids or bad numbers. A run whose records outgrow memory fails
// with out_of_memory_failure: rotbench's limit, never counted as the scheme's blow-up.
RunResult run_one(const RunSpec& spec, const RunOptions& options = {});
inline constexpr const char* out_of_memory_failure =
    "rotbench ran out of memory for this run's records (reference, series), not the scheme's failure";
// Called in a catch (...) around `scheme`'s steps: the failure its run records. rotbench's own
// out-of-memory is rethrown to run_one (a built-in kernel allocates nothing; a plug-in's
// bad_alloc is its own failure).
std::string caught_failure(const std::string& scheme);

// One step of the seed's loop: the translation's Velocity Verlet (eqs. 18-24) around the
// scheme's two phases, the forces evaluated once, at t, between them.
inline void dem_step(const Scene& scene, RotationScheme& scheme, Bodies& bodies, double dt, double t);

// The loop shared by the measured run and the timing run. The scheme cannot reach the
// scene: the one force evaluation per step happens here, and here it is counted.
// `bodies` is the state at step `first_step`; the loop makes `steps` steps from there and
// returns the index of the last step made (the observer may stop it early).
template <class Observer>
std::int64_t simulate(const Scene& scene, RotationScheme& scheme, Bodies& bodies, double dt, std::int64_t steps,
                      std::int64_t& force_evals, Observer&& observe, std::int64_t first_step = 0);

}  // namespace rotbench

#include "harness/exec/simulate.ipp"
