// The state of N rigid bodies, stored as a structure of arrays so that one scheme
// kernel serves a one-body scene and a million-body batch alike.
#pragma once

#include "schemes/simd.hpp"

#include <cstddef>
#include <vector>

namespace rotbench {

using Vec3 = Vec3T<double>;
using Quat = QuatT<double>;

// One 3-vector per body, one array per component.
struct Vec3Array {
    std::vector<double> x, y, z;

    void resize(std::size_t n, double fill = 0.0) { x.assign(n, fill); y.assign(n, fill); z.assign(n, fill); }
    Vec3 operator[](std::size_t i) const { return {x[i], y[i], z[i]}; }
    void set(std::size_t i, const Vec3& v) { x[i] = v.x(); y[i] = v.y(); z[i] = v.z(); }
};

// One quaternion per body (w, x, y, z), one array per component.
struct QuatArray {
    std::vector<double> w, x, y, z;

    void resize(std::size_t n) { w.assign(n, 1.0); x.assign(n, 0.0); y.assign(n, 0.0); z.assign(n, 0.0); }
    Quat operator[](std::size_t i) const { return Quat(w[i], x[i], y[i], z[i]); }
    void set(std::size_t i, const Quat& q) { w[i] = q.w(); x[i] = q.x(); y[i] = q.y(); z[i] = q.z(); }
};

// Body properties and state. The body frame is the principal frame, so the inertia
// tensor is the diagonal `inertia` (I'1, I'2, I'3). `orientation` maps body to world.
struct Bodies {
    std::vector<double> mass;
    Vec3Array inertia;       // principal moments, kg m^2
    Vec3Array position;      // world, m
    Vec3Array velocity;      // world, m/s
    QuatArray orientation;   // unit quaternion, body -> world
    Vec3Array omega;         // angular velocity, world frame, rad/s
    Vec3Array force;         // world, N; written by the scene's force evaluation
    Vec3Array torque;        // world, N m, about the centre of mass; written likewise

    std::size_t size() const { return mass.size(); }

    void resize(std::size_t n) {
        mass.assign(n, 1.0);
        inertia.resize(n, 1.0);
        position.resize(n);
        velocity.resize(n);
        orientation.resize(n);
        omega.resize(n);
        force.resize(n);
        torque.resize(n);
    }
};

}  // namespace rotbench
