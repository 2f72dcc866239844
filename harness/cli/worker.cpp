// `rotbench __run`: the worker of an isolated run (harness/exec/isolation.hpp). Not for
// users: rotbench starts it with the run's spec and reads the run back from its output.
#include "harness/cli/verb.hpp"
#include "harness/exec/interrupt.hpp"
#include "harness/exec/run.hpp"
#include "harness/store/run_record.hpp"

namespace rotbench {
namespace {

class WorkerVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.group("");  // hidden from --help
        command.add_option("--spec", spec_, "the run's spec, as the run store writes it")->required();
        command.add_option("--series", series_, "energy samples")->required();
        command.add_flag("--untimed", untimed_, "no timing repeats");
    }
    int run(const Invocation& how) override {
        const RunSpec spec = parse_spec_record(spec_, "the worker's spec");
        const InterruptGuard guard;  // a signal ends the run at its next step, as in process
        const RunResult r = run_one(spec, {.measure_time = !untimed_, .series_samples = series_});
        if (r.interrupted) return 130;
        how.out << run_record(0, r);
        how.out.flush();
        return how.out ? 0 : 3;
    }

private:
    std::string spec_;
    int series_ = 0;
    bool untimed_ = false;
};

const RegisterVerb<WorkerVerb> worker_verb("__run", "(internal) make one run and print it as a record");

}  // namespace
}  // namespace rotbench
