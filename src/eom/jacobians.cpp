// SPDX-License-Identifier: MIT
// Point and frame Jacobians from positions and angular velocities, by partial derivatives
// with respect to the coordinates' rates.
#include "alembert/eom/jacobians.hpp"

#include <string>

#include "alembert/error.hpp"

namespace alembert {

namespace {

void check_coordinates(const std::vector<TimeVariable>& q, const char* who) {
    for (const TimeVariable& v : q)
        if (v.order() < 2)
            throw ArgumentError(std::string(who) + ": the coordinate '" + v.name() +
                                "' has no second derivative; declare it with order 2");
}

// rows x n entries d(x_i)/dq'_j, and per row sum_j d(x_i)/dq_j q'_j (x linear in q')
void append_rows(SymbolTable& st, const std::vector<TimeVariable>& q, const Col3& x,
                 KinematicJacobian& out) {
    GiNaC::exmap no_accelerations;
    for (const TimeVariable& v : q) no_accelerations[v.d(2)] = 0;
    for (int i = 0; i < 3; ++i) {
        for (const TimeVariable& v : q) out.jacobian.push_back(st.diff(x[i], v.d(1)));
        // x' at q'' = 0 (the intermediates expanded where a q'' hides in one)
        ex a = st.dt(x[i]).subs(no_accelerations);
        for (const TimeVariable& v : q)
            if (st.depends_on(a, v.d(2)))
                a = st.expand_intermediates(st.dt(x[i])).subs(no_accelerations);
        out.jacobian_dot_rates.push_back(a);
    }
}

}  // namespace

KinematicJacobian form_point_jacobian(const System& sys, const std::vector<TimeVariable>& q,
                                      const Point& P) {
    check_coordinates(q, "form_point_jacobian()");
    SymbolTable& st = sys.newtonian().symbols();
    const Frame& N = sys.newtonian();
    KinematicJacobian out;
    // position from N_o in N, its rate by the chain rule: linear in q'
    const Col3 p = P.pos_from(sys.origin()).components_in(N);
    for (int i = 0; i < 3; ++i) out.position.push_back(p[i]);
    append_rows(st, q, p.map([&](const ex& e) { return st.dt(e); }), out);
    return out;
}

KinematicJacobian form_frame_jacobian(const System& sys, const std::vector<TimeVariable>& q,
                                      const Frame& B, const Point& O) {
    check_coordinates(q, "form_frame_jacobian()");
    SymbolTable& st = sys.newtonian().symbols();
    const Frame& N = sys.newtonian();
    KinematicJacobian out;
    // orientation R_NB and origin; the angular rows from ^N w^B in N, linear in q'
    const Mat3 R = B.rotation_in(N);
    for (const ex& e : R.m) out.position.push_back(e);
    const Col3 p = O.pos_from(sys.origin()).components_in(N);
    for (int i = 0; i < 3; ++i) out.position.push_back(p[i]);
    append_rows(st, q, B.ang_vel_in(N).components_in(N), out);
    append_rows(st, q, p.map([&](const ex& e) { return st.dt(e); }), out);
    return out;
}

}  // namespace alembert
