// Jacobi elliptic functions sn, cn, dn (u | m), computed from the complementary
// parameter m1 = 1 - m given separately.
//
// GSL's gsl_sf_elljac_e runs the same arithmetic-geometric mean, but takes m and forms
// sqrt(1 - m) itself. Near the separatrix of a free rigid body, m1 ~ 1e-8 and that
// rounding alone moves m1 by ~1e-8 relative, and the period K by ~5e-9: too much for a
// reference. Here the AGM starts from b0 = sqrt(m1) (A&S 16.4; DLMF 22.20).
#pragma once

namespace rotbench {

struct JacobiElliptic {
    double sn, cn, dn;
};

// For |u| up to about K(m); reduce larger arguments with the periods first.
JacobiElliptic jacobi_elliptic(double u, double m, double m1);

}  // namespace rotbench
