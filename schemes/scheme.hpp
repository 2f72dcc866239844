// The rotation-scheme interface (DESIGN.md "Core model").
//
// A DEM step has exactly one force/torque evaluation, so a scheme has two phases:
//   predict: advance the orientation q^n -> q^{n+1} and set the angular velocity that the
//            force model will see;
//   (the harness evaluates forces and torques once, at the predicted state);
//   correct: finish the angular velocity w^{n+1} from the new torque.
// A scheme never sees the scene: it cannot evaluate forces, and the harness counts them.
// Translation is Velocity Verlet for every scheme and is done by the harness.
#pragma once

#include "harness/registry.hpp"
#include "schemes/bodies.hpp"

#include <memory>
#include <string>
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
    bool sound = true;                  // false: a deliberately wrong control (no_gyro)
};

using SchemeRegistry = Registry<RotationScheme, SchemeClaims>;

// The state one scheme kernel sees for one body: read from the arrays, written back.
struct RigidBody {
    Vec3 inertia;  // principal moments
    Quat q;        // orientation, body -> world
    Vec3 omega;    // world angular velocity
    Vec3 torque;   // world torque, from the last force evaluation
};

// Adapts a per-body kernel to the array interface. A kernel is a small type with
//   struct Memory;                                  per-body values kept between phases
//   static void start(const RigidBody&, Memory&);
//   static void predict(RigidBody&, Memory&, double dt);
//   static void correct(RigidBody&, Memory&, double dt);
// The loops below call the kernel directly: no virtual call or allocation per body.
template <class Kernel>
class BatchedScheme final : public RotationScheme {
public:
    void start(const Bodies& b) override {
        memory_.assign(b.size(), typename Kernel::Memory{});
        for (std::size_t i = 0; i < b.size(); ++i) Kernel::start(load(b, i), memory_[i]);
    }
    void predict(Bodies& b, double dt) override {
        for (std::size_t i = 0; i < b.size(); ++i) {
            RigidBody body = load(b, i);
            Kernel::predict(body, memory_[i], dt);
            store(b, i, body);
        }
    }
    void correct(Bodies& b, double dt) override {
        for (std::size_t i = 0; i < b.size(); ++i) {
            RigidBody body = load(b, i);
            Kernel::correct(body, memory_[i], dt);
            store(b, i, body);
        }
    }

private:
    static RigidBody load(const Bodies& b, std::size_t i) {
        return {b.inertia[i], b.orientation[i], b.omega[i], b.torque[i]};
    }
    static void store(Bodies& b, std::size_t i, const RigidBody& body) {
        b.orientation.set(i, body.q);
        b.omega.set(i, body.omega);
    }
    std::vector<typename Kernel::Memory> memory_;
};

// Registers a kernel under an id at static-initialisation time.
template <class Kernel>
struct RegisterScheme {
    RegisterScheme(std::string id, std::string summary, std::string source, std::string notes = "",
                   SchemeClaims claims = {}) {
        SchemeRegistry::instance().add({std::move(id), std::move(summary), std::move(source), std::move(notes),
                                        [] { return std::make_unique<BatchedScheme<Kernel>>(); }, std::move(claims)});
    }
};

}  // namespace rotbench
