// One step of the torque-free flow by its Taylor series and, for a symmetric top, by its two
// constant rotations (exact_splitting's fast paths) against
// Odeint in long double (tests/odeint_free_body.hpp). The bound is the round-off the exactness
// claim allows one step: 10 eps rad (harness/analysis/round_off.hpp). The closed form itself
// is not judge enough here: built from six quaternions of O(1) angles, it is 10-16 eps off at
// the shortest steps already.
#include "benchmarks/random_bodies.hpp"
#include "schemes/detail/free_flow_series.hpp"
#include "schemes/detail/free_rigid_body.hpp"
#include "schemes/detail/symmetric_top_step.hpp"
#include "schemes/quaternion.hpp"
#include "schemes/scheme.hpp"
#include "tests/odeint_free_body.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

using namespace rotbench;

namespace {

constexpr double one_step_round_off = 10.0 * std::numeric_limits<double>::epsilon();

struct FlowCase {
    Vec3 inertia, l;  // body-frame angular momentum
    Quat q;
};

// The angle between the series and Odeint, or -1 when the series declined (the caller then
// takes the closed form).
double deviation(const FlowCase& c, double dt) {
    const FreeFlowStep<double> series = free_flow_series<double>(c.inertia, c.q, c.l, dt);
    if (!series.converged) return -1.0;
    return rotation_angle_between(series.q.normalized(), testing::odeint_orientation(c.inertia, c.q, c.l, dt));
}

std::vector<FlowCase> random_cases(std::uint64_t seed, int count, double moment_spread) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0), moment(1.0, 1.0 + moment_spread);
    std::vector<FlowCase> cases;
    for (int i = 0; i < count; ++i)
        cases.push_back({Vec3(moment(rng), moment(rng), moment(rng)), Vec3(u(rng), u(rng), u(rng)),
                         Quat(u(rng), u(rng), u(rng), u(rng)).normalized()});
    return cases;
}

// Three exact_splitting steps of `batch` together and of each of its bodies alone: the same bits.
void check_each_body_as_alone(const Bodies& batch, double dt) {
    auto stepped = [dt](Bodies b) {
        auto scheme = SchemeRegistry::instance().at("exact_splitting", "scheme").make();
        scheme->start(b);
        for (int s = 0; s < 3; ++s) scheme->predict(b, dt), scheme->correct(b, dt);
        return b;
    };
    const Bodies together = stepped(batch);
    for (std::size_t i = 0; i < batch.size(); ++i) {
        const Bodies one = stepped(body_alone(batch, i));
        INFO("body " << i << ", moments " << batch.inertia[i].transpose());
        CHECK(together.orientation[i].coeffs() == one.orientation[0].coeffs());
        CHECK(together.omega[i] == one.omega[0]);
    }
}

}  // namespace

TEST_CASE("free flow series: one step agrees with Odeint within one step's round-off") {
    const double dts[] = {1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.3, 1.0, 3.0};
    for (const double spread : {2.0, 0.1, 10.0}) {
        int accepted = 0, total = 0;
        for (const FlowCase& c : random_cases(20261202, 200, spread))
            for (const double dt : dts) {
                const double d = deviation(c, dt);
                ++total;
                if (d < 0.0) continue;
                ++accepted;
                INFO("inertia " << c.inertia.transpose() << ", l " << c.l.transpose() << ", dt " << dt << ": "
                                << d / std::numeric_limits<double>::epsilon() << " eps apart");
                // An angle rounds relative to its size: a step that turns by more than a radian
                // is allowed as many times the round-off.
                const double turn = c.l.cwiseQuotient(c.inertia).norm() * dt;
                CHECK(d <= one_step_round_off * std::max(1.0, turn));
            }
        INFO("moments spread " << spread << ": series taken " << accepted << " of " << total);
        CHECK(accepted >= total / 2);  // measured: every step with |w| dt <= 0.3, most of the longer ones
    }
}

TEST_CASE("free flow series: the hard regimes of the closed form") {
    const Quat q = Quat(0.3, -0.5, 0.7, 0.1).normalized();
    const double dts[] = {1e-4, 1e-2, 0.2};
    SECTION("near the separatrix (G^2 = 2E I_mid to 1e-12)") {
        // Body momentum on the intermediate axis's separatrix, nudged: (1, eps, 1) scaled.
        const Vec3 inertia(1.0, 2.0, 3.0);
        const double a = std::sqrt(3.0 * (3.0 - 2.0)), b = std::sqrt(1.0 * (2.0 - 1.0));
        for (const double dt : dts) CHECK(deviation({inertia, Vec3(b * (1 + 1e-12), 1e-3, a), q}, dt) <= one_step_round_off);
    }
    SECTION("nearly symmetric (moments equal to 1e-9)") {
        for (const double dt : dts)
            CHECK(deviation({Vec3(1.0, 1.0 + 1e-9, 2.0), Vec3(0.4, -0.3, 0.8), q}, dt) <= one_step_round_off);
    }
    SECTION("nearly steady (momentum 1e-7 off a principal axis)") {
        for (const double dt : dts)
            CHECK(deviation({Vec3(1.0, 2.0, 3.0), Vec3(1e-7, 2e-7, 1.0), q}, dt) <= one_step_round_off);
    }
}

TEST_CASE("free flow series: exact motions") {
    const Quat q = Quat(0.3, -0.5, 0.7, 0.1).normalized();
    SECTION("at rest it does not move") { 
        const FreeFlowStep<double> step = free_flow_series<double>(Vec3(1, 2, 3), q, Vec3::Zero(), 0.1);
        CHECK(step.converged);
        CHECK(step.q.coeffs() == q.coeffs());
     }
    SECTION("a sphere turns at constant w") {
        const Vec3 l(0.2, -0.4, 0.5);
        const Quat expected = q * rotation_from_vector(0.3 * l);
        const FreeFlowStep<double> step = free_flow_series<double>(Vec3(1, 1, 1), q, l, 0.3);
        REQUIRE(step.converged);
        CHECK(rotation_angle_between(step.q, expected) <= one_step_round_off);
    }
    SECTION("a symmetric top against its two rotations (Landau & Lifshitz sec. 33)") {
        for (const double dt : {1e-3, 0.1})
            CHECK(deviation({Vec3(2.0, 2.0, 1.0), Vec3(0.4, -0.3, 0.8), q}, dt) <= one_step_round_off);
    }
}

TEST_CASE("free flow series: a step too long for the series is declined, not approximated") {
    // About two periods of the body motion: the Taylor series of w cannot converge there.
    const FlowCase c{Vec3(1.0, 2.0, 3.0), Vec3(0.5, 0.6, 0.7), Quat::Identity()};
    const double period = FreeRigidBody(c.inertia, c.q, c.l.cwiseQuotient(c.inertia)).period();
    for (const double dt : {2.0 * period, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
        CHECK_FALSE(free_flow_series<double>(c.inertia, c.q, c.l, dt).converged);
}

TEST_CASE("exact_splitting: a pack whose bodies take the series and the closed form gets each body's bits alone") {
    // Slow bodies (|w| ~ 1) and fast ones (|w| ~ 40) at dt = 0.1: the series takes the slow
    // and declines the fast, so each pack of four mixes both.
    constexpr std::size_t n = 8;
    const double dt = 0.1;
    Bodies batch = random_bodies(n);
    int declined[2] = {0, 0};  // per pack of four
    for (std::size_t i = 0; i < n; ++i) {
        if (i % 2) batch.omega.set(i, 40.0 * batch.omega[i]);
        const Vec3 l = batch.inertia[i].cwiseProduct(to_body(batch.orientation[i], batch.omega[i]));  // before the kick
        declined[i / 4] += !free_flow_series<double>(batch.inertia[i], batch.orientation[i], l, dt).converged;
    }
    for (const int d : declined) REQUIRE((d > 0 && d < 4));
    check_each_body_as_alone(batch, dt);
}

TEST_CASE("symmetric top step: one step agrees with Odeint within one step's round-off, about each axis") {
    int symmetric = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (const FlowCase& random : random_cases(20261203 + axis, 50, 2.0)) {
            FlowCase c = random;
            c.inertia[(axis + 2) % 3] = c.inertia[(axis + 1) % 3];  // the two moments beside the axis equal
            for (const double dt : {1e-6, 1e-3, 0.1, 1.0, 3.0}) {
                const Vec3 momentum = to_world(c.q, c.l);
                const SymmetricTopStep<double> top = symmetric_top_step<double>(c.inertia, c.q, momentum, c.l, dt);
                REQUIRE(top.symmetric);
                ++symmetric;
                const double d = rotation_angle_between(top.q.normalized(), testing::odeint_orientation(c.inertia, c.q, c.l, dt));
                const double turn = c.l.cwiseQuotient(c.inertia).norm() * dt;
                INFO("axis " << axis << ", inertia " << c.inertia.transpose() << ", l " << c.l.transpose() << ", dt " << dt
                             << ": " << d / std::numeric_limits<double>::epsilon() << " eps apart");
                CHECK(d <= one_step_round_off * std::max(1.0, turn));
            }
        }
    CHECK(symmetric == 3 * 50 * 5);
    // Three different moments: not symmetric (the caller sums the series).
    CHECK_FALSE(symmetric_top_step<double>(Vec3(1, 2, 3), Quat::Identity(), Vec3(1, 1, 1), Vec3(1, 1, 1), 0.1).symmetric);
}

TEST_CASE("exact_splitting: a pack of symmetric and asymmetric bodies gets each body's bits alone") {
    // Bodies symmetric about x, y and z and asymmetric ones, mixed within each pack of four.
    constexpr std::size_t n = 8;
    const double dt = 0.01;
    Bodies batch = random_bodies(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (i % 4 == 3) continue;
        Vec3 moments = batch.inertia[i];
        moments[(i + 2) % 3] = moments[(i + 1) % 3];
        batch.inertia.set(i, moments);
    }
    check_each_body_as_alone(batch, dt);
}
