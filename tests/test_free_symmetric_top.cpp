// The closed form of the free symmetric top, verified against Boost.Odeint on the same
// equations of motion (body-frame Euler equations and q' = q w'/2).
#include "references/free_symmetric_top.hpp"
#include "schemes/quaternion.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>
#include <catch2/catch.hpp>

using namespace rotbench;
namespace odeint = boost::numeric::odeint;

namespace {

using OdeState = std::array<double, 7>;  // w'x, w'y, w'z, qw, qx, qy, qz

struct FreeRigidBody {
    Vec3 inertia;
    void operator()(const OdeState& s, OdeState& ds, double) const {
        const Vec3 w(s[0], s[1], s[2]);
        const Vec3 a = euler_acceleration(w, Vec3::Zero(), inertia);
        const Quat q(s[3], s[4], s[5], s[6]);
        const Quat dq = q * Quat(0.0, w.x(), w.y(), w.z());
        ds = {a.x(), a.y(), a.z(), 0.5 * dq.w(), 0.5 * dq.x(), 0.5 * dq.y(), 0.5 * dq.z()};
    }
};

void check_against_odeint(double it, double ia, const Quat& q0, const Vec3& w0, double t_end) {
    const FreeSymmetricTop exact(it, ia, q0, w0);
    OdeState s{w0.x(), w0.y(), w0.z(), q0.w(), q0.x(), q0.y(), q0.z()};
    auto stepper = odeint::make_controlled(1e-13, 1e-13, odeint::runge_kutta_fehlberg78<OdeState>());
    double worst_w = 0.0, worst_q = 0.0;
    std::vector<double> times;
    for (int k = 0; k <= 50; ++k) times.push_back(t_end * k / 50.0);
    odeint::integrate_times(stepper, FreeRigidBody{Vec3(it, it, ia)}, s, times.begin(), times.end(), 1e-4,
                            [&](const OdeState& x, double t) {
                                worst_w = std::max(worst_w, (Vec3(x[0], x[1], x[2]) - exact.omega_body(t)).norm() / w0.norm());
                                worst_q = std::max(worst_q, rotation_angle_between(Quat(x[3], x[4], x[5], x[6]).normalized(),
                                                                                   exact.orientation(t)));
                            });
    // Odeint at tolerance 1e-13 over ~10^3 steps: errors of order 1e-11 are its own.
    CHECK(worst_w < 1e-10);
    CHECK(worst_q < 1e-10);
}

}  // namespace

TEST_CASE("free symmetric top: closed form agrees with Odeint") {
    SECTION("the seed's cylinder (prolate, I'z/I'x = 0.5), q0 = identity") {
        const double m = 1.178, it = m * 0.25, ia = m * 0.125;
        check_against_odeint(it, ia, Quat::Identity(), Vec3(0.0, 1.0, 100.0), 0.5);
    }
    SECTION("an oblate top from a general orientation") {
        const Quat q0 = Quat(Eigen::AngleAxisd(2.0, Vec3(1.0, -0.5, 0.3).normalized()));
        check_against_odeint(1.0, 1.8, q0, Vec3(2.0, -1.0, 3.0), 10.0);
    }
}

TEST_CASE("cylinder_free reference: w'x = sin 50t, w'y = cos 50t, w'z = 100 (seed eq. 65)") {
    const double m = 1.178;
    const FreeSymmetricTop exact(m * 0.25, m * 0.125, Quat::Identity(), Vec3(0.0, 1.0, 100.0));
    for (double t : {0.0, 0.013, 0.25, 0.5}) {
        const Vec3 w = exact.omega_body(t);
        CHECK(w.x() == Approx(std::sin(50.0 * t)).margin(1e-13));
        CHECK(w.y() == Approx(std::cos(50.0 * t)).margin(1e-13));
        CHECK(w.z() == Approx(100.0).epsilon(1e-15));
    }
}
