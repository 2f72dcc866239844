// Every scene against its reference engine, the engine against a second stepper, and
// every registered scheme on every scene.
#include "harness/exec/run.hpp"
#include "references/odeint_reference.hpp"
#include "harness/store/reference_cache.hpp"
#include "schemes/quaternion.hpp"

#include "harness/scenes/contact_pair.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

using namespace rotbench;

namespace {

Bodies state_at(const Scene& scene, const Trajectory& trajectory, std::size_t sample) {
    Bodies b = scene.initial_state();
    const ReferenceState s = trajectory.state(sample, 0);
    b.orientation.set(0, s.q);
    b.omega.set(0, s.omega);
    b.position.set(0, trajectory.position(sample, 0));
    b.velocity.set(0, trajectory.velocity(sample, 0));
    return b;
}

const std::vector<std::string> seed_schemes = {"direct", "munjiza_rk4", "zvw", "zvw_corrected"};

}  // namespace

TEST_CASE("closed-form scenes agree with Odeint on the same equations of motion") {
    // Odeint at tolerance 1e-14 over the default duration; dzhanibekov passes near the
    // separatrix, where both solutions are ~1e3 times more sensitive to rounding.
    for (const auto& [id, tolerance] : std::vector<std::pair<std::string, double>>{
             {"cylinder_free", 1e-11}, {"asymmetric_free", 1e-11}, {"dzhanibekov", 1e-8}}) {
        INFO(id);
        const auto scene = make_scene(id);
        const auto times = equally_spaced_times(scene->t_end(), 200);
        const Trajectory odeint = integrate_scene(*scene, times, OdeMethod::fehlberg78);
        double omega_err = 0, angle = 0;
        for (std::size_t k = 0; k < times.size(); ++k) {
            const ReferenceState exact = scene->exact(0, times[k]), ode = odeint.state(k, 0);
            omega_err = std::max(omega_err, (exact.omega - ode.omega).norm() / exact.omega.norm());
            angle = std::max(angle, rotation_angle_between(exact.q, ode.q.normalized()));
        }
        CHECK(omega_err < tolerance);
        CHECK(angle < tolerance);
    }
}

TEST_CASE("torqued_cylinder: the closed-form angular velocity agrees with Odeint") {
    const auto scene = make_scene("torqued_cylinder");
    const auto times = equally_spaced_times(scene->t_end(), 200);
    const Trajectory odeint = integrate_scene(*scene, times, OdeMethod::fehlberg78);
    double worst = 0;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const ReferenceState s = odeint.state(k, 0);
        const Vec3 exact = *scene->exact_omega_body(0, times[k]);
        worst = std::max(worst, (to_body(s.q, s.omega) - exact).norm() / exact.norm());
    }
    CHECK(worst < 1e-12);  // Odeint at 1e-14 over 5 s: a few hundred steps of 1e-14
}

TEST_CASE("the Odeint reference agrees with Bulirsch-Stoer") {
    SECTION("smooth scenes: to 1e-11 (both run at tolerance 1e-14)") {
        for (const char* id : {"cylinder_free", "asymmetric_free", "torqued_cylinder", "dipole_top"}) {
            INFO(id);
            const auto scene = make_scene(id);
            const CrossCheck c = cross_check(*scene, scene->t_end());
            CHECK(c.omega_relative < 1e-11);
            CHECK(c.angle < 1e-11);
        }
    }
    SECTION("fibre_bounce: to 1e-6 rad, 1e-7 in w, 1e-8 in position") {
        // Each bounce magnifies a difference between the two methods; what the two must
        // share is the physics (energy, next test) and the trajectory to these bounds.
        const auto scene = make_scene("fibre_bounce");
        const CrossCheck c = cross_check(*scene, scene->t_end());
        CHECK(c.omega_relative < 1e-7);
        CHECK(c.angle < 1e-6);
        CHECK(c.position < 1e-8);
    }
}

TEST_CASE("the fibre's Odeint reference conserves energy to 1e-9 relative (issue 3)") {
    const auto scene = make_scene("fibre_bounce");
    for (int samples : {200, 20000}) {  // sample times cut the steps differently
        INFO(samples << " samples");
        const auto times = equally_spaced_times(scene->t_end(), samples);
        const Trajectory odeint = integrate_scene(*scene, times, OdeMethod::fehlberg78);
        const double e0 = scene->energy(scene->initial_state());
        double worst = 0;
        for (std::size_t k = 0; k < times.size(); ++k) {
            const Bodies b = state_at(*scene, odeint, k);
            worst = std::max(worst, std::abs(scene->energy(b) - e0) / std::abs(e0));
        }
        CHECK(worst < 1e-9);
        // The fibre starts without rotation; the bounces give it a good share of the energy.
        CHECK(rotational_energy(state_at(*scene, odeint, times.size() - 1)) > 0.1 * e0);
    }
}

TEST_CASE("a NaN or Inf in any angular velocity or orientation component makes every scene's energy non-finite") {
    // The run's blow-up test relies on it: beside the energy it tests the positions and
    // velocities only (harness/run.cpp).
    for (const auto& scene_id : SceneRegistry::instance().ids()) {
        const auto scene = make_scene(scene_id);
        for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity()}) {
            for (int component = 0; component < 7; ++component) {
                Bodies b = scene->initial_state();
                const std::size_t body = b.size() - 1;
                if (component < 3) {
                    b.omega.set(body, b.omega[body] + bad * Vec3::Unit(component));
                } else {
                    Quat q = b.orientation[body];
                    q.coeffs()[component - 3] = bad;
                    b.orientation.set(body, q);
                }
                INFO(scene_id << ", component " << component << " = " << bad);
                CHECK_FALSE(std::isfinite(scene->energy(b)));
            }
        }
    }
}

TEST_CASE("every registered scheme runs stably on every scene of issues 2 and 3") {
    // The contact pairs of the stability study are left out: there, schemes do fail
    // (see "linear contact" below).
    for (const auto& scene_id : SceneRegistry::instance().ids()) {
        const auto scene = make_scene(scene_id);
        if (dynamic_cast<const ContactPairScene*>(scene.get())) continue;
        // A short run at the scene's coarsest default step; the fibre until after its first bounce.
        const double dt = scene->default_dts().front();
        const double t_end = scene_id == "fibre_bounce" ? 0.35 : std::min(scene->t_end(), 1000 * dt);
        for (const auto& scheme_id : seed_schemes) {
            INFO(scene_id << " / " << scheme_id);
            const RunResult r = run_one({scene_id, scheme_id, dt, t_end}, {.measure_time = false});
            CHECK(r.value("unstable") == 0);
            CHECK(r.value("force_evals") == r.value("steps") + 1);
            if (scene->has_reference()) CHECK(std::isfinite(r.value("omega_rms_x")));
            if (scene->conserves_energy()) CHECK(r.value("energy_drift_max") < 0.5);
        }
    }
}

TEST_CASE("the Dzhanibekov flips are physics: no sound scheme is called unstable, and the flips happen") {
    const auto scene = make_scene("dzhanibekov");
    const ReferenceState start = scene->exact(0, 0.0);
    double min_wb_y = 1e300;
    for (int k = 0; k <= 400; ++k) min_wb_y = std::min(min_wb_y, to_body(scene->exact(0, 0.05 * k).q, scene->exact(0, 0.05 * k).omega).y());
    CHECK(to_body(start.q, start.omega).y() > 1.9);
    CHECK(min_wb_y < -1.9);  // w'2 reverses: the body has turned over
    for (const auto& scheme_id : seed_schemes) {
        INFO(scheme_id);
        CHECK(run_one({"dzhanibekov", scheme_id, 1e-2, 0.0}, {.measure_time = false}).value("unstable") == 0);
    }
}

TEST_CASE("impossible scene parameters are rejected, naming the key") {
    auto message = [](const std::string& scene, ParamOverrides overrides) -> std::string {
        try {
            make_scene(scene, overrides);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    CHECK_THAT(message("dipole_top", {{"inertia", {-1, 1, 1}}}), Catch::Contains("dipole_top.inertia") && Catch::Contains("greater than 0"));
    CHECK_THAT(message("dipole_top", {{"inertia", {1, 1, 3}}}), Catch::Contains("dipole_top.inertia") && Catch::Contains("triangle inequality"));
    CHECK_THAT(message("fibre_bounce", {{"poisson", {0.7}}}), Catch::Contains("fibre_bounce.poisson"));
    CHECK_THAT(message("torqued_cylinder", {{"radius", {0}}}), Catch::Contains("torqued_cylinder.radius"));
    CHECK_THAT(message("cylinder_free", {{"q0", {0, 0, 0, 0}}}), Catch::Contains("cylinder_free.q0"));
    CHECK_THAT(message("cylinder_free", {{"omega0", {1, 2}}}), Catch::Contains("expects 3 values"));
    CHECK_THAT(message("cylinder_free", {{"spin", {1}}}), Catch::Contains("unknown parameter 'cylinder_free.spin'") && Catch::Contains("omega0"));
    CHECK_THAT(message("dzhanibekov", {{"t_end", {0}}}), Catch::Contains("dzhanibekov.t_end"));
    // HLW's moments break the triangle inequality; asymmetric_free keeps them on purpose.
    CHECK(message("asymmetric_free", {}).empty());
}

TEST_CASE("scene parameters change the run") {
    const RunResult base = run_one({"torqued_cylinder", "direct", 1e-2, 1.0}, {.measure_time = false});
    const RunResult stronger =
        run_one({"torqued_cylinder", "direct", 1e-2, 1.0, {{"torque", {0.05}}}}, {.measure_time = false});
    CHECK(base.value("omega_rms_z") != stronger.value("omega_rms_z"));
}

TEST_CASE("a damaged reference cache file is a miss, never a wrong reference") {
    Trajectory t;
    t.bodies = 2;
    for (std::size_t k = 0; k < 3 * 2 * Trajectory::width; ++k) t.values.push_back(0.1 * k);
    const std::string bytes = encode_trajectory("key", t);
    REQUIRE(decode_trajectory(bytes, "key"));
    CHECK(decode_trajectory(bytes, "key")->values == t.values);
    CHECK_FALSE(decode_trajectory(bytes, "other key"));
    // Every single flipped bit and every truncation is detected.
    int missed = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i)
        for (int bit = 0; bit < 8; ++bit) {
            std::string damaged = bytes;
            damaged[i] = static_cast<char>(damaged[i] ^ (1 << bit));
            missed += decode_trajectory(damaged, "key").has_value();
        }
    for (std::size_t n = 0; n < bytes.size(); ++n) missed += decode_trajectory(bytes.substr(0, n), "key").has_value();
    missed += decode_trajectory(bytes + "x", "key").has_value();
    CHECK(missed == 0);
    // A count that claims more values than the file holds is refused before any allocation.
    std::string huge = bytes;
    const std::uint64_t count = std::uint64_t(1) << 60;
    std::memcpy(huge.data() + 8 + 8 + 3 + 8, &count, sizeof count);
    CHECK_FALSE(decode_trajectory(huge, "key"));
    // A trajectory of no values reads back as one (found by fuzz_reference_cache: memcpy of
    // its null data(), undefined behaviour even for no bytes).
    Trajectory empty;
    empty.bodies = 1;
    const auto back = decode_trajectory(encode_trajectory("key", empty), "key");
    REQUIRE(back);
    CHECK(back->values.empty());
}

TEST_CASE("reference trajectories are cached on disk, keyed by their inputs and the build") {
    const auto dir = std::filesystem::temp_directory_path() / ("rotbench_cache_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    ::setenv("ROTBENCH_CACHE", dir.c_str(), 1);
    Trajectory t;
    t.bodies = 1;
    t.values.assign(2 * Trajectory::width, 0.5);
    store_cached("dipole_top", "key-a", t);
    if (build_is_pinned()) {
        const auto hit = load_cached("dipole_top", "key-a");
        REQUIRE(hit);
        CHECK(hit->values == t.values);
        CHECK_FALSE(load_cached("dipole_top", "key-b"));
        // The stored key names the build: a trajectory from another build is a miss.
        REQUIRE(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);
        std::ifstream file(std::filesystem::directory_iterator(dir)->path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        CHECK(bytes.find("key-a|build=" + cache_build_key()) != std::string::npos);
        ::setenv("ROTBENCH_CACHE", "off", 1);
        CHECK_FALSE(load_cached("dipole_top", "key-a"));
    } else {  // a modified tree: the commit does not pin the code, nothing is kept
        CHECK_FALSE(std::filesystem::exists(dir));
        CHECK_FALSE(load_cached("dipole_top", "key-a"));
    }
    ::unsetenv("ROTBENCH_CACHE");
    std::filesystem::remove_all(dir);
}

TEST_CASE("a reference cache another user owns or others may write is neither read nor written") {
    const auto dir = std::filesystem::temp_directory_path() / ("rotbench_shared_cache_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    ::setenv("ROTBENCH_CACHE", dir.c_str(), 1);
    std::filesystem::permissions(dir, std::filesystem::perms::all);  // 0777: anyone could edit a file and its checksum
    CHECK_THAT(untrusted_cache_reason(), Catch::Contains("is not used: it is writable by others"));
    Trajectory t;
    t.bodies = 1;
    t.values.assign(2 * Trajectory::width, 0.5);
    store_cached("dipole_top", "key-shared", t);
    CHECK(std::filesystem::is_empty(dir));
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all);  // 0700: the user's own
    CHECK(untrusted_cache_reason().empty());
    ::unsetenv("ROTBENCH_CACHE");
    std::filesystem::remove_all(dir);
}

TEST_CASE("every scene's registry entry states its traits, the same as the scene built from it") {
    for (const auto& id : SceneRegistry::instance().ids()) {
        INFO(id);
        const SceneTraits& declared = SceneRegistry::instance().at(id, "scene").extra;
        const auto scene = make_scene(id);
        CHECK(scene->reference_kind() == declared.reference);
        CHECK(scene->conserves_angular_momentum() == declared.conserves_angular_momentum);
        CHECK(scene->torque_depends_on_orientation() == declared.torque_depends_on_orientation);
        CHECK(scene->times_in_run() == declared.times_in_run);
        CHECK((dynamic_cast<const StabilityProbe*>(scene.get()) != nullptr) == declared.stability);
        // A scene that declares a closed form has one.
        if (declared.reference == ReferenceKind::closed_form) CHECK_NOTHROW(scene->exact(0, 0.0));
    }
    // What planning and the stability study read without building anything.
    CHECK_FALSE(SceneRegistry::instance().at("silo_discharge", "scene").extra.in_default_suite);
    CHECK(SceneRegistry::instance().at("sphere_pair", "scene").extra.stability);
    CHECK(SceneRegistry::instance().at("dipole_top", "scene").extra.torque_depends_on_orientation);
}

TEST_CASE("the reference cache is trimmed to its size, least recently used first, touching nothing else") {
    namespace fs = std::filesystem;
    const auto dir = fs::temp_directory_path() / ("rotbench_cache_trim_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    Trajectory t;
    t.bodies = 1;
    t.values.assign(100 * Trajectory::width, 0.25);
    const std::string bytes = encode_trajectory("k", t);
    const auto now = fs::file_time_type::clock::now();
    const auto put = [&](const std::string& name, const std::string& content, int hours_ago) {
        std::ofstream(dir / name, std::ios::binary) << content;
        fs::last_write_time(dir / name, now - std::chrono::hours(hours_ago));
    };
    put("dipole_top-00000000000000a1.traj", bytes, 5);  // the oldest: goes first
    put("dipole_top-00000000000000a2.traj", bytes, 4);
    put("dipole_top-00000000000000a3.traj", bytes, 1);
    put("dipole_top-00000000000000a4.traj", "not a trajectory", 9);  // named like one, not one: kept
    put("notes.txt", "the user's", 9);                                // not the cache's: kept
    trim_cache(dir, 2 * bytes.size() + 100);
    CHECK_FALSE(fs::exists(dir / "dipole_top-00000000000000a1.traj"));
    CHECK(fs::exists(dir / "dipole_top-00000000000000a2.traj"));
    CHECK(fs::exists(dir / "dipole_top-00000000000000a3.traj"));
    CHECK(fs::exists(dir / "dipole_top-00000000000000a4.traj"));
    CHECK(fs::exists(dir / "notes.txt"));
    // `keep` (the file just written) survives even when it is the oldest.
    trim_cache(dir, 0, dir / "dipole_top-00000000000000a2.traj");
    CHECK(fs::exists(dir / "dipole_top-00000000000000a2.traj"));
    CHECK_FALSE(fs::exists(dir / "dipole_top-00000000000000a3.traj"));
    CHECK(fs::exists(dir / "notes.txt"));
    fs::remove_all(dir);
}
