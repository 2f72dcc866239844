// What the granular scenes (silo_discharge, direct_shear) share: ballast stones of the six
// shapes in Hertz-Mindlin contact (harness/granular), the material keys of seed Table 3, a
// seeded random packing, and the energy the blow-up rule watches. Their true motion is
// dissipative and chaotic: no reference; their own metrics come from a SceneProbe.
#pragma once

#include "harness/granular/cluster_system.hpp"
#include "harness/granular/random_stream.hpp"
#include "harness/granular/wall_outline.hpp"
#include "harness/scenes/scene.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

namespace rotbench {

class GranularScene : public Scene {
public:
    static constexpr SceneTraits traits{.in_default_suite = false, .times_in_run = true};
    GranularScene() {
        params.declare("clusters", {200}, "-", "number of ballast stones");
        params.declare("seed", {1}, "-", "packing seed (shapes, places and orientations): one member of an ensemble");
        params.declare("density", {2700}, "kg/m^3", "density of the stones (seed Table 3)");
        params.declare("young", {2.4e8}, "Pa", "Young's modulus, all contacts (seed Table 3)");
        params.declare("poisson", {0.2}, "-", "Poisson's ratio, all contacts (seed Table 3)");
        params.declare("restitution", {0.0}, "-", "restitution coefficient of the damping law (seed Table 3: 0)");
        params.declare("friction", {0.6}, "-", "friction coefficient between stones (seed Table 3)");
        params.declare("gravity", {9.81}, "m/s^2", "gravitational acceleration (along -z)");
    }

    void evaluate_forces(Bodies& b, double t) const override {
        place_walls(t);
        system_->evaluate(b, t);
    }
    double energy(const Bodies& b) const override { return kinetic_energy(b) + system_->potential_energy(b) + system_->elastic_energy(); }
    std::vector<std::pair<std::string, double>> energy_parts(const Bodies& b) const override {
        return {{"kinetic", kinetic_energy(b)}, {"potential", system_->potential_energy(b)}, {"elastic", system_->elastic_energy()}};
    }
    bool conserves_energy() const override { return false; }  // damped and frictional
    ClusterSystem& system() const { return *system_; }

    // For a DEM code that runs the scene from a description of it (a granular client,
    // harness/exec/granular_client.hpp). The walls stand still between the times they change,
    // and place_walls(t) sets them as they stand at t; a scene whose walls move, or follow the
    // stones, cannot be so described: nullopt.
    virtual std::optional<std::vector<double>> wall_changes() const { return std::nullopt; }
    virtual void place_walls(double) const {}
    // The scene's probe looks at the stones from this time on.
    virtual double observed_from() const { return 0.0; }
    const ContactMaterial& material() const { return material_; }
    double friction() const { return friction_; }
    Vec3 gravity() const { return Vec3(0.0, 0.0, -params.number("gravity")); }

protected:
    // For the derived scene's prepare(): validates the shared keys and builds the stones.
    void prepare_material() {
        const double count = params.number("clusters"), seed = params.number("seed");
        params.require(count >= 1 && count <= 100000 && count == std::floor(count), "clusters", "must be a whole number in [1, 100000]");
        params.require(seed >= 0 && seed < 9.0e15 && seed == std::floor(seed), "seed", "must be a whole number in [0, 9e15)");
        material_.young = params.positive("young");
        material_.poisson = params.number("poisson");
        params.require(material_.poisson > -1.0 && material_.poisson < 0.5, "poisson", "must lie in (-1, 0.5)");
        material_.restitution = params.number("restitution");
        params.require(material_.restitution >= 0.0 && material_.restitution <= 1.0, "restitution", "must lie in [0, 1]");
        friction_ = params.number("friction");
        params.require(friction_ >= 0.0, "friction", "must not be negative");
        const double g = params.number("gravity");
        params.require(g >= 0.0, "gravity", "must not be negative");
        system_ = std::make_unique<ClusterSystem>(ballast_shapes(params.positive("density")), material_, friction_, gravity());
    }
    std::size_t cluster_count() const { return static_cast<std::size_t>(params.number("clusters")); }
    // The spheres of every stone at time t and the walls as they stand, as SceneProbe::Snapshots rows.
    void add_snapshot(double t, const Bodies& b, SceneProbe::Snapshots& pictures) const {
        const std::vector<Sphere> spheres = system_->world_spheres(b);
        for (const Sphere& s : spheres) pictures.spheres.push_back({t, s.centre.x(), s.centre.y(), s.centre.z(), s.radius});
        for (const auto& [x0, z0, x1, z1] : wall_segments(system_->walls, picture_frame(spheres, system_->walls)))
            pictures.walls.push_back({t, x0, z0, x1, z1});
    }
    RandomStream random() const { return RandomStream(static_cast<std::uint64_t>(params.number("seed"))); }
    // The largest distance of a stone's surface from its centre of mass.
    double largest_reach() const {
        double reach = 0;
        for (const ClusterShape& s : system_->shapes()) reach = std::max(reach, s.reach);
        return reach;
    }
    // Stones of random shapes and orientations on a jittered lattice filling the box [lo, hi],
    // row by row from its bottom, spaced so that none overlaps another.
    Bodies lattice_packing(const Vec3& lo, const Vec3& hi) const {
        RandomStream r = random();
        const double jitter = 0.05 * largest_reach(), spacing = 2.0 * (largest_reach() + jitter);
        // Counted in floating point and capped by the stones: any box a user gives fits (a row
        // wider than the stones is never needed).
        const double most = static_cast<double>(std::max<std::size_t>(cluster_count(), 1));
        const auto across = [&](int k) { return static_cast<std::size_t>(std::clamp(std::floor((hi[k] - lo[k]) / spacing), 1.0, most)); };
        const std::size_t nx = across(0), per_layer = nx * across(1);
        std::vector<int> shapes;
        std::vector<Vec3> places;
        std::vector<Quat> orientations;
        for (std::size_t i = 0; i < cluster_count(); ++i) {
            const std::size_t layer = i / per_layer, in_layer = i % per_layer;
            const Vec3 cell((static_cast<double>(in_layer % nx) + 0.5) * spacing, (static_cast<double>(in_layer / nx) + 0.5) * spacing,
                            (static_cast<double>(layer) + 0.5) * spacing);
            places.push_back(lo + cell + jitter * Vec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)));
            shapes.push_back(static_cast<int>(r.index(ballast_shape_count)));
            orientations.push_back(r.rotation());
        }
        return system_->make_bodies(shapes, places, orientations);
    }

    ContactMaterial material_;
    double friction_ = 0;
    std::unique_ptr<ClusterSystem> system_;
};

}  // namespace rotbench
