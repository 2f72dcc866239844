#include "schemes/quaternion.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace rotbench;

// Round-off tolerances: a handful of floating-point operations on O(1) values.
constexpr double roundoff = 1e-14;

TEST_CASE("the increment q(w, dt) is the rotation by |w| dt about w (seed eq. 17)") {
    const Vec3 w(0.3, -1.2, 2.0);
    const double dt = 0.37;
    const Quat expected(Eigen::AngleAxisd(w.norm() * dt, w.normalized()));
    CHECK(rotation_angle_between(rotation_increment(w, dt), expected) < roundoff);
    CHECK(std::abs(rotation_increment(w, dt).norm() - 1.0) < roundoff);

    SECTION("and stays exact for tiny angles, where the series branch is used") {
        const Vec3 slow = 1e-7 * w;
        const Quat q = rotation_increment(slow, dt);
        CHECK(q.vec().isApprox(0.5 * dt * slow, 1e-15));
        CHECK(rotation_increment(Vec3::Zero(), dt).coeffs() == Quat::Identity().coeffs());
    }
}

TEST_CASE("the exponential map's series agree with sin and cos to an ulp up to its 1 rad limit and past it") {
    // Truncation error below 8e-19 (schemes/quaternion.hpp) plus Horner's and the
    // library's round-off, about an ulp each, on values between 0.87 and 1: 3 ulp.
    const double ulp3 = 3 * std::numeric_limits<double>::epsilon();
    const Vec3 axis = Vec3(0.3, -1.2, 2.0).normalized();
    for (double angle = 1e-9; angle < 3.0; angle *= 1.07) {
        INFO("angle " << angle);
        const double h = 0.5 * angle;
        const Quat q = rotation_from_vector(angle * axis);
        CHECK(std::abs(q.w() - std::cos(h)) <= ulp3);
        CHECK((q.vec() - std::sin(h) * axis).norm() <= ulp3 * std::sin(h));
    }
}

TEST_CASE("frame changes are exact rotations even when |q| has drifted from 1 (seed eqs. 11-12)") {
    const Quat unit = Quat(Eigen::AngleAxisd(1.1, Vec3(1, 2, 3).normalized()));
    const Quat drifted(unit.coeffs() * (1.0 + 1e-6));
    const Vec3 v(0.0, 1.0, 100.0);
    CHECK((to_world(drifted, v) - unit.toRotationMatrix() * v).norm() < roundoff * v.norm());
    CHECK((to_body(drifted, to_world(drifted, v)) - v).norm() < roundoff * v.norm());
    // Eigen's unit-only shortcut would be off by |q|^2 - 1 = 2e-6 here, i.e. 2e-4 on |v| = 100.
    CHECK((drifted * v - unit.toRotationMatrix() * v).norm() > 1e-5);
}

TEST_CASE("w = I(q)^-1 H inverts H = I(q) w (seed eq. 45)") {
    const Quat q = Quat(Eigen::AngleAxisd(-0.7, Vec3(0.2, 1, -0.4).normalized()));
    const Vec3 inertia(2.0, 1.0, 2.0 / 3.0);
    const Vec3 w(0.5, -3.0, 1.5);
    CHECK((omega_from_momentum(q, inertia, momentum_from_omega(q, inertia, w)) - w).norm() < roundoff * w.norm());
    // and H agrees with the world inertia tensor R I' R^T built explicitly
    const Eigen::Matrix3d r = q.toRotationMatrix();
    const Eigen::Matrix3d world_inertia = r * inertia.asDiagonal() * r.transpose();
    CHECK((momentum_from_omega(q, inertia, w) - world_inertia * w).norm() < roundoff * 10);
}

TEST_CASE("Euler's equations in the body frame (seed eq. 34)") {
    const Vec3 inertia(1.0, 2.0, 3.0);
    const Vec3 w(1.0, 2.0, 3.0), torque(0.5, 0.0, -1.0);
    // I1 a1 = T1 - (I3 - I2) w3 w2, and cyclic (seed eq. 6)
    const Vec3 expected((0.5 - (3.0 - 2.0) * 3.0 * 2.0) / 1.0, (0.0 - (1.0 - 3.0) * 1.0 * 3.0) / 2.0,
                        (-1.0 - (2.0 - 1.0) * 2.0 * 1.0) / 3.0);
    CHECK((euler_acceleration(w, torque, inertia) - expected).norm() < roundoff);
}
