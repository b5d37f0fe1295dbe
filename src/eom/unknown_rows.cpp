// SPDX-License-Identifier: MIT
// Speeds and the driving loads of specified motions as road-map unknowns.
#include "unknown_rows.hpp"

#include <algorithm>

#include "alembert/eom/zero_test.hpp"

namespace alembert::detail {

std::vector<TimeVariable> calc_driven_quantities(const System& sys,
                                                 const std::vector<TimeVariable>& coordinates) {
    const SymbolTable& st = sys.symbols();
    std::vector<TimeVariable> out;
    for (const ex& s : st.symbols(SymbolKind::specified)) {
        if (st.derivative_order(s) != 0) continue;
        TimeVariable v = st.variable(st.name(s));
        if (v.order() < 1) continue;  // an input without derivatives moves nothing
        const bool listed = std::any_of(coordinates.begin(), coordinates.end(),
                                        [&](const TimeVariable& q) { return q.symbol().is_equal(s); });
        if (!listed) out.push_back(v);
    }
    return out;
}

int calc_speed_of(const ex& x, const std::vector<TimeVariable>& coordinates) {
    for (std::size_t j = 0; j < coordinates.size(); ++j)
        for (int d = 1; d < coordinates[j].order(); ++d)
            if (x.is_equal(coordinates[j].d(d))) return static_cast<int>(j);
    return -1;
}

std::vector<ex> calc_other_rates(const ex& x, const std::vector<TimeVariable>& coordinates) {
    std::vector<ex> out;
    for (const TimeVariable& q : coordinates)
        for (int d = 1; d <= q.order(); ++d)
            if (!x.is_equal(q.d(d))) out.push_back(q.d(d));
    return out;
}

bool acts_only_along(const System& sys, const ex& x, Motion motion, const Vector& u) {
    const LoadKind kind = motion == Motion::rotate ? LoadKind::torque : LoadKind::force;
    bool found = false;
    // each vector tested in a frame it is written in (no orientation the rows did not need)
    auto zero = [&](const Vector& v) {
        return v.is_zero() || is_zero_at_random_states(sys.symbols(), v, *v.components().front().first);
    };
    for (const Load& L : sys.loads()) {
        const Vector c = L.vector.diff(x);
        if (zero(c)) continue;
        if (L.kind != kind || !zero(cross(c, u))) return false;
        found = true;
    }
    return found;
}

}  // namespace alembert::detail
