#include "harness/exec/contact_client.hpp"

#include "harness/exec/json_vec.hpp"
#include "schemes/quaternion.hpp"

#include <nlohmann/json.hpp>

namespace rotbench {
namespace {

// Body i's state from its row at step n (the contact_trajectory_header's columns).
void set_body(Bodies& b, std::size_t i, const TrajectoryRow& r) {
    b.position.set(i, Vec3(r[2], r[3], r[4]));
    b.velocity.set(i, Vec3(r[5], r[6], r[7]));
    b.orientation.set(i, Quat(r[8], r[9], r[10], r[11]).normalized());
    b.omega.set(i, Vec3(r[12], r[13], r[14]));
}

class ContactReplay final : public RotationScheme {
public:
    explicit ContactReplay(const std::vector<TrajectoryRow>& rows) : rows_(rows) {}
    void start(const Bodies&) override { next_ = 2; }
    void predict(Bodies&, double) override {}
    void correct(Bodies& b, double) override {
        for (std::size_t i = 0; i < b.size(); ++i) set_body(b, i, rows_.at(next_++));
    }

private:
    const std::vector<TrajectoryRow>& rows_;
    std::size_t next_ = 2;
};

}  // namespace

std::string contact_scene_json(const ContactPairScene& scene, const RunSpec& spec, double t_end, std::int64_t steps) {
    const Bodies b = scene.initial_state();
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < b.size(); ++i) {
        const Quat& q = b.orientation[i];
        bodies.push_back({{"mass", b.mass[i]},
                          {"inertia_body", json_vec(b.inertia[i])},
                          {"shape", {{"kind", scene.shape().kind}, {"size", scene.shape().size}}},
                          {"position", json_vec(b.position[i])},
                          {"q0", {q.w(), q.x(), q.y(), q.z()}},
                          {"velocity", json_vec(b.velocity[i])},
                          {"omega_world", json_vec(b.omega[i])},
                          {"anchor_body", json_vec(scene.anchor(i))}});
    }
    // Seed 004 eq. 29 with the damping of eq. 37: F_2 = -(k_n u_n + k_t u_t) - (c_n u'_n + c_t u'_t).
    const nlohmann::ordered_json contact = {{"law", "linear spring-dashpot, bonded"},
                                            {"normal", json_vec(Vec3::UnitX())},
                                            {"point", json_vec(b.position[0] + to_world(b.orientation[0], scene.anchor(0)))},
                                            {"normal_stiffness", scene.stiffness()},
                                            {"tangential_stiffness", scene.stiffness()},
                                            {"normal_damping", scene.damping()},
                                            {"tangential_damping", scene.damping()},
                                            {"zeta", scene.params.number("zeta")},
                                            {"a_max", scene.a_max()},
                                            {"friction", nullptr}};
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (const auto& [key, values] : spec.params) params[key] = values;
    const nlohmann::ordered_json j = {{"format", "rotbench-contact-scene 1"},
                                      {"scene", spec.scene},
                                      {"bodies", bodies},
                                      {"contact", contact},
                                      {"dt", spec.dt},
                                      {"t_end", t_end},
                                      {"steps", steps},
                                      {"columns", contact_trajectory_header},
                                      {"params", params}};
    return j.dump(2) + "\n";
}

std::unique_ptr<RotationScheme> contact_replay(const std::vector<TrajectoryRow>& rows) { return std::make_unique<ContactReplay>(rows); }

bool contact_blew_up(const ContactPairScene& scene, const std::vector<TrajectoryRow>& rows, const StabilityCriterion& criterion) {
    Bodies b = scene.initial_state();
    const double e0 = scene.energy(b);
    for (std::size_t k = b.size(); k + b.size() <= rows.size(); k += b.size()) {
        for (std::size_t i = 0; i < b.size(); ++i) set_body(b, i, rows[k + i]);
        if (energy_blew_up(scene.energy(b), e0, criterion)) return true;
    }
    return false;
}

}  // namespace rotbench
