// `rotbench __stability`: the worker of a plug-in scheme's stability case (harness/engine/
// isolation.hpp). Not for users: `rotbench stability` starts it and reads its numbers back.
#include "harness/analysis/stability_study.hpp"
#include "harness/cli/verb.hpp"
#include "harness/engine/interrupt.hpp"
#include "harness/io/parse.hpp"

namespace rotbench {
namespace {

class StabilityWorkerVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.group("");  // hidden from --help
        command.add_option("--scene", scene_, "stability scene")->required();
        command.add_option("--scheme", scheme_, "scheme id")->required();
        command.add_option("--zeta", zeta_, "damping ratio (contact scenes)");
        command.add_option("--omega-max", omega_, "spin rate, rad/s (fast_spin)");
        command.add_flag("--spectral", spectral_, "the scheme's spectral curve on the scene instead");
    }
    int run(const Invocation& how) override {
        check_stability_scenes({scene_});
        const InterruptGuard guard;
        if (spectral_) {
            how.out << spectral_curve_text(scene_, scheme_);
        } else {
            StabilityRow row{scene_, scheme_};
            if (!zeta_.empty()) row.zeta = parse_finite(zeta_, "--zeta");
            if (!omega_.empty()) row.omega_max = parse_positive(omega_, "--omega-max");
            measure_stability_case(row);
            how.out << stability_case_text(row);
        }
        how.out.flush();
        return how.out ? 0 : 3;
    }

private:
    std::string scene_, scheme_, zeta_, omega_;
    bool spectral_ = false;
};

const RegisterVerb<StabilityWorkerVerb> registration("__stability", "(internal) one stability case or spectral curve, as numbers");

}  // namespace
}  // namespace rotbench
