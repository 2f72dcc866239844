// `rotbench advise`: which scheme, at what dt, for the user's own particle and contact.
#include "harness/analysis/advice.hpp"
#include "harness/cli/outputs.hpp"
#include "harness/cli/sweep_command.hpp"
#include "harness/cli/verb.hpp"
#include "harness/exec/parallel.hpp"
#include "harness/store/parse.hpp"
#include "reports/advice_report.hpp"
#include "schemes/scheme.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

class AdviseVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("--inertia", inertia_, "principal moments I1,I2,I3 (kg m^2)")->required();
        command.add_option("--mass", mass_, "particle mass (kg)")->required();
        command.add_option("--stiffness", stiffness_, "contact stiffness, normal and tangential (N/m)")->required();
        command.add_option("--zeta", zeta_, "contact damping ratio")->capture_default_str();
        command.add_option("--omega", omega_, "typical spin rate (rad/s)")->capture_default_str();
        command.add_option("--t-end", t_end_, "simulated time (s; default: 20 periods of the fastest contact mode)");
        command.add_option("--tolerance", tolerance_, "relative angular-velocity error to meet, in (0, 1)")->required();
        command.add_option("--schemes", schemes_, "comma list of scheme ids (default: all)");
        command.add_flag("--verify", verify_, "run each recommendation at its dt against the reference");
        command.add_option("--out", out_, "output directory for advice.json")->capture_default_str();
        command.add_flag("--overwrite", overwrite_, "replace an advice.json rotbench wrote there");
        command.add_option("--jobs", jobs_, "schemes in parallel")->check(CLI::Range(1, max_jobs));
    }
    bool resumable() const override { return true; }
    int run(const Invocation& how) override {
        Particle p;
        const auto moments = split_commas(inertia_);
        if (moments.size() != 3) throw InputError("--inertia: give three principal moments I1,I2,I3, not '" + inertia_ + "'");
        for (int k = 0; k < 3; ++k) p.inertia[k] = parse_positive(moments[k], "--inertia");
        p.mass = parse_positive(mass_, "--mass");
        p.stiffness = parse_positive(stiffness_, "--stiffness");
        p.zeta = parse_finite(zeta_, "--zeta");
        if (p.zeta < 0) throw InputError("--zeta: must not be negative, not " + zeta_);
        p.omega = parse_finite(omega_, "--omega");
        if (p.omega < 0) throw InputError("--omega: must not be negative, not " + omega_);
        if (!t_end_.empty()) p.t_end = parse_positive(t_end_, "--t-end");
        const double tolerance = parse_positive(tolerance_, "--tolerance");
        if (!(tolerance < 1)) throw InputError("--tolerance: " + tolerance_ + " is not below 1 (a relative error)");
        const auto schemes = schemes_.empty() ? SchemeRegistry::instance().ids()
                                              : parse_id_list(schemes_, SchemeRegistry::instance(), "scheme");
        particle_params(p);  // the particle checked before the directory is opened
        const OutputDir dir = OutputDir::open(how.resuming ? *how.resuming : std::filesystem::path(out_),
                                              {"advise", "advice.json", {"advice.json"}, overwrite_, how.resuming.has_value()});
        Advice advice;
        {
            Executor executor = make_executor(how, &dir, {.jobs = jobs_, .quiet = true, .verb = "advise"});
            advice = advise(executor, p, tolerance, schemes, verify_);
            if (executor.signal()) return executor.interrupted();
        }
        dir.write("advice.json", advice_json(advice));
        Journal::discard(dir.path());
        how.out << advice_table(advice) << "wrote " << (dir.path() / "advice.json").string() << "\n";
        return 0;
    }

private:
    std::string inertia_, mass_, stiffness_, zeta_ = "0", omega_ = "10", t_end_, tolerance_, schemes_, out_ = "rotbench-advice";
    bool verify_ = false, overwrite_ = false;
    int jobs_ = core_count();
};

const RegisterVerb<AdviseVerb> advise_verb("advise", "which scheme at what dt for your particle and contact (advice.json)");

}  // namespace
}  // namespace rotbench
