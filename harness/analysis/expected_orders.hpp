// The order each scheme should show, and why: the claims each scheme registers with
// (schemes/scheme.hpp, SchemeClaims). Tests check the observed orders against these; the
// report prints them beside the observed ones. The orders are of the angular-velocity
// error, omega_err_max.
#pragma once

#include "schemes/scheme.hpp"

#include <string>
#include <vector>

namespace rotbench {

struct ExpectedOrder {
    std::string scheme;
    bool with_torque;  // false: torque-free scenes; true: an orientation-dependent torque
    int order;
    std::string reason;
};

// The orders one scheme claims.
inline void add_expected_orders(const std::string& id, const SchemeClaims& c, std::vector<ExpectedOrder>& table) {
    if (c.without_torque.order > 0) table.push_back({id, false, c.without_torque.order, c.without_torque.reason});
    if (c.with_torque.order > 0) table.push_back({id, true, c.with_torque.order, c.with_torque.reason});
}

// Of every registered scheme.
inline std::vector<ExpectedOrder> expected_orders() {
    std::vector<ExpectedOrder> table;
    for (const auto& id : SchemeRegistry::instance().ids()) add_expected_orders(id, SchemeRegistry::instance().at(id, "scheme").extra, table);
    return table;
}

}  // namespace rotbench
