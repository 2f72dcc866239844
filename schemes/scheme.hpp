// The rotation-scheme interface (docs/plugins.md).
//
// A DEM step has exactly one force/torque evaluation, so a scheme has two phases:
//   predict: advance the orientation q^n -> q^{n+1} and set the angular velocity that the
//            force model will see;
//   (the harness evaluates forces and torques once, at the predicted state);
//   correct: finish the angular velocity w^{n+1} from the new torque.
// A scheme never sees the scene: it cannot evaluate forces, and the harness counts them.
// Translation is Velocity Verlet for every scheme and is done by the harness.
#pragma once

#include "schemes/bodies.hpp"
#include "schemes/registry.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace rotbench {

class RotationScheme {
public:
    virtual ~RotationScheme() = default;
    // Once, after the initial force evaluation (torque holds T^0).
    virtual void start(const Bodies& bodies) = 0;
    // torque holds T^n (evaluated at the end of the previous step).
    virtual void predict(Bodies& bodies, double dt) = 0;
    // torque holds T^{n+1}, evaluated at q^{n+1} and the angular velocity left by predict.
    virtual void correct(Bodies& bodies, double dt) = 0;
    // How many bodies it steps at once: the width of its packs, or 1.
    virtual std::size_t lanes() const { return 1; }
};

// What a scheme claims of itself; tests and the report check the claims against the runs.
struct OrderClaim {
    int order = 0;       // of the angular-velocity error; 0: no claim
    std::string reason;  // the argument, with the equations it rests on
};
struct SchemeClaims {
    OrderClaim without_torque;  // torque-free scenes
    OrderClaim with_torque;     // an orientation-dependent torque
    bool exact_without_torque = false;  // the torque-free motion is exact (round-off only)
    bool conserves_momentum = false;    // world angular momentum kept to round-off without torque
    bool bounded_energy = false;        // no secular energy drift in a conservative scene (symplectic or reversible)
    bool time_reversible = false;       // stepping back with -dt from the end returns to the start, to round-off
    bool sound = true;                  // false: a deliberately wrong control (no_gyro), expected to fail
    // Not a claim: the group the report draws the scheme with ("seed", "kick_drift_kick", or
    // empty for the others). RegisterScheme sets "kick_drift_kick" for a KickDriftKick kernel.
    std::string family;
    // Not a claim either: file:line of the RegisterScheme that makes them, where the gate points a
    // failed claim (a CI annotation on the candidate's source, not on the gate file).
    std::string declared_at;

    bool claims_nothing() const {
        return without_torque.order == 0 && with_torque.order == 0 && !exact_without_torque && !conserves_momentum &&
               !bounded_energy && !time_reversible;
    }
};

using SchemeRegistry = Registry<RotationScheme, SchemeClaims>;

// The state one scheme kernel sees for one body (S = double), or for a pack of bodies
// (S = Pack, schemes/simd.hpp): read from the arrays, written back.
template <class S>
struct RigidBodyT {
    Vec3T<S> inertia;  // principal moments
    QuatT<S> q;        // orientation, body -> world
    Vec3T<S> omega;    // world angular velocity
    Vec3T<S> torque;   // world torque, from the last force evaluation
};
using RigidBody = RigidBodyT<double>;

// A kernel that can step a pack of bodies: it is a template on its scalar and names its
// instantiation for any other one, `template <class T> using rebind = Kernel<..., T>`.
template <class Kernel>
concept PackKernel = bool(ROTBENCH_SIMD) && requires { typename Kernel::template rebind<double>; };

// A kernel: the step of one body, a small type with
//   struct Memory;                                  per-body values kept between phases
//   static void start(const RigidBody&, Memory&);
//   static void predict(RigidBody&, Memory&, double dt);
//   static void correct(RigidBody&, Memory&, double dt);
// and nothing else that rotbench reads, but `rebind` (PackKernel, above): the one way to step
// packs. Everything else a scheme states goes in its registration's SchemeClaims, whose
// designated initialisers do not compile when misspelt.
template <class Kernel>
concept SchemeKernel = requires { typename Kernel::Memory; } &&
                       requires(const RigidBody& c, RigidBody& b, typename Kernel::Memory& m, double dt) {
                           Kernel::start(c, m);
                           Kernel::predict(b, m, dt);
                           Kernel::correct(b, m, dt);
                       };

// Adapts a kernel to the array interface.
// The loops below call the kernel directly: no virtual call or allocation per body. A
// PackKernel steps whole packs of bodies with its pack instantiation, read straight from the
// arrays, and the remaining bodies (all of them in a scene of fewer bodies than a pack) one
// by one with its double instantiation.
template <SchemeKernel Kernel>
class BatchedScheme final : public RotationScheme {
public:
    void start(const Bodies& b) override {
        const std::size_t packs = pack_count(b);
#if ROTBENCH_SIMD
        if constexpr (PackKernel<Kernel>) {
            pack_memory_.clear();
            pack_memory_.resize(packs);  // built in place: a copy of a fresh Memory would copy unset packs
            for (std::size_t p = 0; p < packs; ++p) PackOf::start(load<Pack>(b, p * width), pack_memory_[p]);
        }
#endif
        memory_.clear();
        memory_.resize(b.size() - packs * width);
        for (std::size_t i = packs * width; i < b.size(); ++i) Kernel::start(load<double>(b, i), memory_[i - packs * width]);
    }
    std::size_t lanes() const override { return width; }
    void predict(Bodies& b, double dt) override { step(b, dt, [](auto& body, auto& m, double h, auto kernel) { decltype(kernel)::type::predict(body, m, h); }); }
    void correct(Bodies& b, double dt) override { step(b, dt, [](auto& body, auto& m, double h, auto kernel) { decltype(kernel)::type::correct(body, m, h); }); }

private:
    template <class K>
    struct Tag {
        using type = K;
    };
    static constexpr std::size_t pack_width() {
#if ROTBENCH_SIMD
        if constexpr (PackKernel<Kernel>) return Pack::size;
#endif
        return 1;
    }
    static constexpr std::size_t width = pack_width();
    static std::size_t pack_count(const Bodies& b) { return width > 1 ? b.size() / width : 0; }

    template <class Phase>
    void step(Bodies& b, double dt, Phase phase) {
        const std::size_t packs = pack_count(b);
#if ROTBENCH_SIMD
        if constexpr (PackKernel<Kernel>) {
            for (std::size_t p = 0; p < packs; ++p) {
                RigidBodyT<Pack> body = load<Pack>(b, p * width);
                phase(body, pack_memory_[p], dt, Tag<PackOf>{});
                store(b, p * width, body);
            }
        }
#endif
        for (std::size_t i = packs * width; i < b.size(); ++i) {
            RigidBody body = load<double>(b, i);
            phase(body, memory_[i - packs * width], dt, Tag<Kernel>{});
            store(b, i, body);
        }
    }

    template <class S>
    static S get(const std::vector<double>& v, std::size_t i) {
        if constexpr (std::is_same_v<S, double>) return v[i];
        else return S::load_unaligned(v.data() + i);
    }
    template <class S>
    static void put(std::vector<double>& v, std::size_t i, const S& x) {
        if constexpr (std::is_same_v<S, double>) v[i] = x;
        else x.store_unaligned(v.data() + i);
    }
    template <class S>
    static Vec3T<S> get(const Vec3Array& a, std::size_t i) { return {get<S>(a.x, i), get<S>(a.y, i), get<S>(a.z, i)}; }
    template <class S>
    static RigidBodyT<S> load(const Bodies& b, std::size_t i) {
        const auto& q = b.orientation;
        return {get<S>(b.inertia, i), QuatT<S>(get<S>(q.w, i), get<S>(q.x, i), get<S>(q.y, i), get<S>(q.z, i)),
                get<S>(b.omega, i), get<S>(b.torque, i)};
    }
    template <class S>
    static void store(Bodies& b, std::size_t i, const RigidBodyT<S>& body) {
        put(b.orientation.w, i, body.q.w()), put(b.orientation.x, i, body.q.x());
        put(b.orientation.y, i, body.q.y()), put(b.orientation.z, i, body.q.z());
        put(b.omega.x, i, body.omega.x()), put(b.omega.y, i, body.omega.y()), put(b.omega.z, i, body.omega.z());
    }

    std::vector<typename Kernel::Memory> memory_;
#if ROTBENCH_SIMD
    struct NoPack {
        struct Memory {};
    };
    template <class K>
    static auto pack_kernel() {
        if constexpr (PackKernel<K>) return Tag<typename K::template rebind<Pack>>{};
        else return Tag<NoPack>{};
    }
    using PackOf = typename decltype(pack_kernel<Kernel>())::type;
    std::vector<typename PackOf::Memory> pack_memory_;
#endif
};

// The report's group of a kernel's schemes (SchemeClaims::family): empty, unless the kernel's
// header specialises this (kick_drift_kick.hpp).
template <class Kernel>
inline constexpr const char* kernel_family = "";

// Registers a kernel under an id at static-initialisation time.
template <SchemeKernel Kernel>
struct RegisterScheme {
    static_assert(!requires { Kernel::family; }, "a kernel's `family` is no longer read: give .family in its SchemeClaims");
    // `file` and `line` default to the place of the registration (GCC and Clang builtins).
    RegisterScheme(std::string id, std::string summary, std::string source, std::string notes = "", SchemeClaims claims = {},
                   const char* file = __builtin_FILE(), int line = __builtin_LINE()) {
        if (claims.family.empty()) claims.family = kernel_family<Kernel>;
        claims.declared_at = std::string(file) + ":" + std::to_string(line);
        SchemeRegistry::instance().add({std::move(id), std::move(summary), std::move(source), std::move(notes),
                                        [] { return std::make_unique<BatchedScheme<Kernel>>(); }, std::move(claims)});
    }
};

}  // namespace rotbench
