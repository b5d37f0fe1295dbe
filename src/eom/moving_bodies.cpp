// SPDX-License-Identifier: MIT
// Which bodies a speed moves, told at random states once per model and speed.
#include "alembert/eom/moving_bodies.hpp"

#include <algorithm>

namespace alembert {

MovingBodies::MovingBodies(const System& sys) : sys_(sys), at_(sys.symbols()) {}

const std::pair<std::vector<Col3>, std::vector<Col3>>& MovingBodies::measured() const {
    if (!wv_) {
        const Frame& N = sys_.newtonian();
        std::pair<std::vector<Col3>, std::vector<Col3>> wv;
        for (const Body* b : sys_.bodies()) {
            wv.first.push_back(b->frame() ? b->frame()->ang_vel_in(N).components_in(N) : Col3{});
            wv.second.push_back(b->cm().vel_in(N).components_in(N));
        }
        wv_ = std::move(wv);
    }
    return *wv_;
}

const std::vector<BodyMotion>& MovingBodies::calc_motions(const ex& speed) {
    auto it = motions_.find(speed);
    if (it != motions_.end()) return it->second;
    const auto& [w, v] = measured();
    std::vector<BodyMotion> m(w.size());
    for (std::size_t i = 0; i < m.size(); ++i) {
        m[i].turns = !w[i].is_zero() && at_.calc_changes_with(w[i], speed);
        m[i].slides = !v[i].is_zero() && at_.calc_changes_with(v[i], speed);
    }
    return motions_.emplace(speed, std::move(m)).first->second;
}

std::string MovingBodies::calc_coordinate_moving(const BodySet& S) {
    const SymbolTable& st = sys_.symbols();
    const std::vector<const Body*>& bodies = sys_.bodies();
    for (const ex& x : st.symbols(SymbolKind::variable)) {
        if (st.derivative_order(x) != 0) continue;
        const TimeVariable q = st.variable(st.name(x));
        if (q.order() < 1) continue;
        const std::vector<BodyMotion>& m = calc_motions(q.d(1));
        bool same = true;
        for (std::size_t i = 0; i < bodies.size() && same; ++i)
            same = m[i].moves() == (std::find(S.begin(), S.end(), bodies[i]) != S.end());
        if (same) return q.name();
    }
    return "";
}

}  // namespace alembert
