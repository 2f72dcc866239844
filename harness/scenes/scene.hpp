// A scene: bodies, initial state, force/torque model, duration, observables and, where it
// has one, a reference solution. A scene models only the physics it needs.
#pragma once

#include "harness/scenes/params.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "references/dynamics.hpp"
#include "schemes/bodies.hpp"
#include "schemes/quaternion.hpp"
#include "schemes/registry.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rotbench {

// A scene's own measurements (the granular scenes' discharge and shear curves): the probe sees
// the state after every step of the measured run and gives the scene's metrics at its end,
// and, for the report's pictures, a curve and snapshots of the bodies.
class SceneProbe {
public:
    virtual ~SceneProbe() = default;
    virtual void observe(double t, const Bodies& bodies) = 0;
    virtual std::vector<std::pair<std::string, double>> metrics() const = 0;
    // The run's curve: column names (the abscissa first) and rows (mass left against time,
    // shear stress against displacement); none by default.
    struct Curve {
        std::vector<std::string> columns;
        std::vector<std::vector<double>> rows;
    };
    virtual Curve curve() const { return {}; }
    // Pictures at a few instants: the spheres of every body, as rows {t, x, y, z, radius}, and
    // the walls seen along +y, as segments {t, x0, z0, x1, z1}; none by default.
    struct Snapshots {
        std::vector<std::vector<double>> spheres, walls;
    };
    virtual Snapshots snapshots() const { return {}; }
};

// Where a scene's reference solution comes from: a closed form, or Boost.Odeint on the
// scene's own equations of motion (references/odeint_reference.hpp).
enum class ReferenceKind { none, closed_form, odeint };

// What a scene is, whatever its parameters: stated once by its class (`static constexpr
// SceneTraits traits{...}`, inherited from its base where not), held by its registry entry,
// so that planning and listing read them without building the scene.
struct SceneTraits {
    ReferenceKind reference = ReferenceKind::none;
    bool conserves_angular_momentum = false;     // no external torque
    bool torque_depends_on_orientation = false;  // the torque seen in the body frame changes with q (dipole_top): the
                                                 // class of scenes where the "with torque" orders apply
    bool in_default_suite = true;                // in `rotbench run`'s default selection (false: run only when named)
    bool times_in_run = false;  // runs too long to be repeated for timing (the granular scenes): their cost is measured
                                // in the run itself, the scheme's share of each step included (timed_scheme.hpp)
    bool stability = false;     // a StabilityProbe (stability_probe.hpp): a scene of the stability study; set by type
};

// A one-body scene's torque as data, for a program outside rotbench that integrates the scene
// (a client, harness/exec/client_run.hpp): its law by name and its parameters, each a 3-vector.
//   none           no torque;
//   body_constant  a constant torque `torque_body` in the body frame;
//   dipole         T = R mu' x B: a dipole `dipole_body` in a uniform field `field_world`.
struct TorqueLaw {
    std::string law = "none";
    std::vector<std::pair<std::string, Vec3>> parameters;
};

// The bodies, their initial state and their force/torque model come from Dynamics
// (references/dynamics.hpp), which the Odeint reference integrates.
class Scene : public Dynamics {
public:
    using ReferenceKind = rotbench::ReferenceKind;
    static constexpr SceneTraits traits{};

    // Declared by the scene's constructor (with `t_end` always), then overridden by the
    // user, then `prepare` validates them (InputError naming the key) and builds what
    // depends on them.
    Params params;
    virtual void prepare() {}

    double t_end() const { return params.number("t_end"); }
    // The default suite's time steps (a ladder by halving, plus any published ones) and
    // the quick suite's (a few coarse rungs, for CI).
    virtual std::vector<double> default_dts() const = 0;
    virtual std::vector<double> quick_dts() const = 0;
    // What `--quick` sets besides the ladder (a smaller granular scene), before the user's keys.
    virtual ParamOverrides quick_params() const { return {}; }

    // Its class's traits (the registry entry's).
    const SceneTraits& scene_traits() const { return traits_; }
    ReferenceKind reference_kind() const { return traits_.reference; }
    bool has_reference() const { return reference_kind() != ReferenceKind::none; }
    virtual ReferenceState exact(std::size_t body, double t) const;
    // An Odeint scene whose angular velocity alone has a closed form gives it here (body frame).
    virtual std::optional<Vec3> exact_omega_body(std::size_t, double) const { return std::nullopt; }

    // Total mechanical energy, and its parts by name (summing to it); the default is the
    // kinetic energy, right for free bodies.
    virtual double energy(const Bodies& bodies) const;
    virtual std::vector<std::pair<std::string, double>> energy_parts(const Bodies& bodies) const;
    // What the true motion conserves: the energy unless external work is done (then
    // energy_drift_max would measure physics, not error), the angular momentum only
    // without external torque.
    virtual bool conserves_energy() const { return true; }
    // External work feeds energy in (an applied torque): energy growth is then physics, and
    // only a NaN or Inf state counts as a blow-up. A damped scene only loses energy.
    virtual bool gains_energy() const { return false; }
    // Scenes whose report shows the energy against time (the seed's Figures 8-11 for the
    // fibre): every scene whose true motion conserves it.
    bool reports_energy_series() const { return conserves_energy(); }
    bool conserves_angular_momentum() const { return traits_.conserves_angular_momentum; }
    bool torque_depends_on_orientation() const { return traits_.torque_depends_on_orientation; }
    bool times_in_run() const { return traits_.times_in_run; }
    // Its torque as data when it is one body under one of the laws of TorqueLaw; none otherwise
    // (several bodies, contacts, walls), and then no client can take it.
    virtual std::optional<TorqueLaw> torque_law() const { return std::nullopt; }
    // A fresh probe for each measured run; none for most scenes.
    virtual std::unique_ptr<SceneProbe> make_probe() const { return nullptr; }

private:
    template <class S>
    friend struct RegisterScene;
    SceneTraits traits_;
};

using SceneRegistry = Registry<Scene, SceneTraits>;

template <class S>
struct RegisterScene {
    static constexpr SceneTraits traits_of() {
        SceneTraits t = S::traits;
        t.stability = std::is_base_of_v<StabilityProbe, S>;
        return t;
    }
    RegisterScene(std::string id, std::string summary, std::string source, std::string notes = "") {
        SceneRegistry::instance().add({id, std::move(summary), std::move(source), std::move(notes),
                                       [id] {
                                           auto scene = std::make_unique<S>();
                                           scene->params.set_owner(id);
                                           scene->traits_ = traits_of();
                                           return scene;
                                       },
                                       traits_of()});
    }
};

// The scene `id` with its parameters overridden and validated (InputError on bad input,
// including an initial energy or angular momentum beyond max_magnitude).
inline constexpr double max_magnitude = 1e100;
std::unique_ptr<Scene> make_scene(const std::string& id, const ParamOverrides& overrides = {});

// dt_max, dt_max/2, ..., rungs values in all, then `extra` (published steps) not already in.
std::vector<double> halving_ladder(double dt_max, int rungs, std::vector<double> extra = {});

// Inlined: a scene's energy() runs at every step of a run. Of body i, and of all bodies (a
// scene of one body calls the former: the loops' set-up for vectorisation costs more than
// the sum there).
ROTBENCH_INLINE double translational_energy(const Bodies& b, std::size_t i) { return 0.5 * b.mass[i] * b.velocity[i].squaredNorm(); }
ROTBENCH_INLINE double rotational_energy(const Bodies& b, std::size_t i) {
    const Vec3 w_body = to_body(b.orientation[i], b.omega[i]);
    return 0.5 * w_body.dot(b.inertia[i].cwiseProduct(w_body));
}
ROTBENCH_INLINE double translational_energy(const Bodies& b) {
    double e = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) e += translational_energy(b, i);
    return e;
}
ROTBENCH_INLINE double rotational_energy(const Bodies& b) {
    double e = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) e += rotational_energy(b, i);
    return e;
}
inline double kinetic_energy(const Bodies& b) { return translational_energy(b) + rotational_energy(b); }
Vec3 total_angular_momentum(const Bodies& bodies);  // about the origin, world frame

}  // namespace rotbench
