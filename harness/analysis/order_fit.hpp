// Observed order of convergence: the least-squares slope of log(error) against log(dt)
// over the asymptotic range only, with a 95 % interval.
//
// The rule that picks the range (documented in the report):
//  1. Points whose error is not finite or not > 0 (failed runs) are dropped, and so are
//     points below the round-off floor, `floor` (1e-13 by default: ~500 ulps).
//  2. Points coarser than the one of largest error are dropped: there the error still grows
//     as dt shrinks (an O(1) phase error saturates, and wanders). Going from that point to
//     the finest, the first point whose error is no longer smaller than 0.9 x the error at
//     the previous (coarser) dt starts a plateau: it and every finer point are at round-off
//     and are dropped.
//  3. The range is the longest run of points ending at the finest whose local orders all
//     lie within 0.3 of their median. Coarser points are pre-asymptotic.
//  4. Fewer than 3 points in the range: "insufficient", no number.
// The interval is slope +- t(0.975, n-2) x its standard error (Student's t, GSL).
#pragma once

#include <string>
#include <vector>

namespace rotbench {

struct OrderPoint {
    double dt, error;
};

struct OrderFit {
    bool sufficient = false;
    double order = 0, order_lo = 0, order_hi = 0;  // only when sufficient
    double dt_min = 0, dt_max = 0;                 // the range fitted
    int points = 0;                                // in the range
    // Between successive usable points, coarse to fine: (dt_coarse, dt_fine, order).
    struct Local {
        double dt_coarse, dt_fine, order;
    };
    std::vector<Local> local_orders;
};

// The rule's numbers, which the report prints from here.
inline constexpr double order_floor = 1e-13;
inline constexpr double plateau_ratio = 0.9;      // rule 2
inline constexpr double asymptotic_spread = 0.3;  // rule 3
inline constexpr int min_fit_points = 3;          // rule 4

OrderFit fit_order(std::vector<OrderPoint> points, double floor = order_floor);

}  // namespace rotbench
