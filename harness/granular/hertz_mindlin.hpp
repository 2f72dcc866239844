// The contact law of the granular scenes (seed Table 3): Hertz in the normal direction,
// Mindlin's no-slip tangential spring with a Coulomb limit, and the viscous damping of
// Tsuji et al. (Powder Technol. 71:239, 1992) in the form DEM codes use for a restitution
// coefficient e (the "Hertz-Mindlin" model of EDEM and LIGGGHTS):
//   F_n = 4/3 E* sqrt(R* d) d - eta_n v_n,    eta_n = -2 sqrt(5/6) beta sqrt(S_n m*),  S_n = 2 E* sqrt(R* d)
//   F_t = -S_t s - eta_t v_t,                 eta_t = -2 sqrt(5/6) beta sqrt(S_t m*),  S_t = 8 G* sqrt(R* d)
//   beta = ln e / sqrt(ln^2 e + pi^2)  (beta = -1 for e = 0, its limit),
// with d the overlap, s the tangential spring (the tangential displacement accumulated over
// the contact), and |F_t| <= mu F_n: beyond it the contact slides and s is cut back to the
// limit. The damping grows as d^(1/4), which makes the restitution of a Hertz contact the
// same at every impact speed; it is not e itself, but a function of beta alone (the form was
// derived for a linear spring): 0.550 for e = 0.5, 0.902 for 0.9, and 0.135 for the seed's
// e = 0 (tests/test_granular_contacts.cpp). F_n is not allowed to pull (F_n >= 0).
// Both sides of every contact are of the same material (the seed's E, nu for all contacts).
#pragma once

#include "schemes/bodies.hpp"

namespace rotbench {

struct ContactMaterial {
    double young = 2.4e8;     // Pa
    double poisson = 0.2;
    double restitution = 0.0;
};

class HertzMindlin {
public:
    explicit HertzMindlin(const ContactMaterial& material);

    // The force on body b of a contact with body a: overlap d > 0, unit normal n from a to b,
    // v the velocity of b's contact point relative to a's, effective radius and mass, the
    // tangential spring s (updated), the time since s was last updated, and the friction
    // coefficient.
    Vec3 force(double overlap, const Vec3& normal, const Vec3& velocity, double radius, double mass, Vec3& spring,
               double elapsed, double friction) const;
    // Elastic energy stored in the normal spring, 8/15 E* sqrt(R*) d^(5/2).
    double normal_energy(double overlap, double radius) const;

    double effective_modulus() const { return modulus_; }
    double beta() const { return beta_; }

private:
    double modulus_ = 0, shear_modulus_ = 0, beta_ = 0;
};

}  // namespace rotbench
