// SPDX-License-Identifier: MIT
// Rotate rows of large systems: moments of the loads on S accumulated along the point tree.
#include "accumulated_moment.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>
#include <vector>

#include "alembert/eom/inertia_forces.hpp"

namespace alembert::detail {

struct InertiaLoadsMemo::Entry {
    InertiaLoads loads, at_zero;  // as formed, and with the solve-level symbols at zero
};

namespace {

thread_local InertiaLoadsMemo* active_memo = nullptr;

using GiNaC::is_a;

bool member(const BodySet& S, const Body* b) {
    return b && std::find(S.begin(), S.end(), b) != S.end();
}

// the frame a point's sums are written in: that of the first body with a frame met going
// from the point towards the root (N for points of the surroundings)
const Frame& frame_of(const Point* p, const Frame& N) {
    for (; p; p = p->located_from())
        if (p->owner() && p->owner()->frame()) return *p->owner()->frame();
    return N;
}

bool is_solve_level_in(const SymbolTable& st, const ex& e) {
    for (const ex& s : symbols_of(e))
        if (st.is_solve_level(s)) return true;
    return false;
}

bool holds_solve_level(const SymbolTable& st, const Vector& v) {
    for (const auto& part : v.components())
        for (int i = 0; i < 3; ++i)
            if (is_solve_level_in(st, part.second[i])) return true;
    return false;
}

// The points below O that carry items, and the points between them and O.
class PointTree {
public:
    struct Node {
        const Point* point = nullptr;
        int parent = -1;  // index of the node the point is located from; -1 for O
        const Frame* frame = nullptr;
        Vector force[2], couple[2];  // the items at the point: [0] as formed, [1] with x = 0
    };

    PointTree(const Point& O, const Frame& N) : N_(N) { make_node(&O, -1); }

    /// The index of P's node, made with the path from O if new; -1 if P is not located
    /// (through other points) from O.
    int node(const Point* P) {
        std::vector<const Point*> path;
        int top = -1;
        for (const Point* p = P;; p = p->located_from()) {
            if (!p) {
                for (const Point* q : path) index_[q] = -1;
                return -1;
            }
            if (auto it = index_.find(p); it != index_.end()) {
                top = it->second;
                break;
            }
            path.push_back(p);
        }
        if (top < 0) {
            for (const Point* q : path) index_[q] = -1;
            return -1;
        }
        for (std::size_t i = path.size(); i-- > 0;) top = make_node(path[i], top);
        return top;
    }

    Node& at(int i) { return nodes_[static_cast<std::size_t>(i)]; }

    /// The moment about O of the items (pass 0: as formed, 1: with x = 0), in O's frame.
    Vector moment_about_O(SymbolTable& st, int pass) const {
        const std::size_t n = nodes_.size();
        std::vector<Col3> F(n), M(n);
        auto name = [&](const Col3& c) {
            return c.map([&](const ex& e) {
                return is_a<GiNaC::numeric>(e) || is_a<GiNaC::symbol>(e) ? e
                                                                         : st.name_subexpression(e);
            });
        };
        // children are made after their parents: from the last node back, each node's sums are
        // complete when it is reached
        for (std::size_t i = n; i-- > 0;) {
            const Node& nd = nodes_[i];
            const Frame& E = *nd.frame;
            F[i] = name(F[i] + nd.force[pass].components_in(E));
            M[i] = name(M[i] + nd.couple[pass].components_in(E));
            if (nd.parent < 0) continue;
            const auto p = static_cast<std::size_t>(nd.parent);
            const Frame& EP = *nodes_[p].frame;
            const Col3 Fp = &EP == &E ? F[i] : Vector(E, F[i]).components_in(EP);
            const Col3 Mp = &EP == &E ? M[i] : Vector(E, M[i]).components_in(EP);
            const Col3 r = nd.point->pos_from(*nodes_[p].point).components_in(EP);
            F[p] = F[p] + Fp;
            M[p] = M[p] + Mp + cross(r, Fp);
        }
        return Vector(*nodes_[0].frame, M[0]);
    }

private:
    int make_node(const Point* p, int parent) {
        Node nd;
        nd.point = p;
        nd.parent = parent;
        nd.frame = &frame_of(p, N_);
        nodes_.push_back(std::move(nd));
        const int i = static_cast<int>(nodes_.size()) - 1;
        index_[p] = i;
        return i;
    }

    const Frame& N_;
    std::vector<Node> nodes_;
    std::unordered_map<const Point*, int> index_;  // looked up only; the order is the nodes'
};

}  // namespace

InertiaLoadsMemo::InertiaLoadsMemo() : outer_(active_memo) { active_memo = this; }

InertiaLoadsMemo::~InertiaLoadsMemo() { active_memo = outer_; }

std::optional<ex> form_accumulated_moment_row(const System& sys, const RoadmapRow& row) {
    if (row.motion != Motion::rotate || !row.about || row.system.empty()) return std::nullopt;
    const Frame& N = sys.newtonian();
    SymbolTable& st = N.symbols();
    const Point& O = *row.about;
    const BodySet& S = row.system;
    const bool dynamics = row.analysis == Analysis::dynamics;

    // the solve-level symbols the items may hold, set to zero for the second pass
    GiNaC::exmap zero;
    for (SymbolKind k : {SymbolKind::variable, SymbolKind::specified})
        for (const ex& s : st.symbols(k))
            if (st.is_solve_level(s)) zero[s] = 0;
    auto at_zero = [&](const Vector& v) { return v.map([&](const ex& e) { return e.subs(zero); }); };

    PointTree tree(O, N);
    Vector direct;  // moments formed as r^{P/O} x F, about O
    auto add = [&](const Point& P, const Vector& f, const Vector& c, const Vector& f0,
                   const Vector& c0) {
        const int i = tree.node(&P);
        if (i < 0) {
            direct += c + cross(P.pos_from(O), f);
            return false;
        }
        auto& nd = tree.at(i);
        nd.force[0] += f, nd.couple[0] += c, nd.force[1] += f0, nd.couple[1] += c0;
        return true;
    };
    // loads external to S; those with unknown measures stay explicit
    for (const Load& l : sys.loads()) {
        if (!member(S, l.on) || member(S, l.from)) continue;
        if (l.kind == LoadKind::torque) {
            direct += l.vector;
        } else if (holds_solve_level(st, l.vector)) {
            direct += cross(l.point->pos_from(O), l.vector);
        } else {
            add(*l.point, l.vector, Vector(), l.vector, Vector());
        }
    }
    // each body's weight, and its inertia force and torque (R* = -m a, T*), formed once per
    // memo
    InertiaLoadsMemo::Entry formed;
    auto inertia_loads = [&](const Body& b) -> const InertiaLoadsMemo::Entry& {
        if (active_memo)
            if (auto it = active_memo->entries_.find(&b); it != active_memo->entries_.end()) return *it->second;
        InertiaLoadsMemo::Entry e;
        e.loads = calc_inertia_loads(b, N);
        e.at_zero = {at_zero(e.loads.force), at_zero(e.loads.torque)};
        if (!active_memo) return formed = std::move(e);
        auto& kept = active_memo->entries_[&b];
        kept = std::make_unique<InertiaLoadsMemo::Entry>(std::move(e));
        return *kept;
    };
    for (const Body* b : S) {
        Vector f = b->mass() * sys.gravity(), c, f0 = f, c0;
        if (dynamics) {
            const InertiaLoadsMemo::Entry& r = inertia_loads(*b);
            f += r.loads.force, c += r.loads.torque;
            f0 += r.at_zero.force, c0 += r.at_zero.torque;
        }
        add(b->cm(), f, c, f0, c0);
    }

    const ex E_acc = dot(row.direction, tree.moment_about_O(st, 0));
    ex E = dot(row.direction, direct);
    std::vector<ex> xs;
    for (const ex& s : st.calc_leaf_symbols(E_acc))
        if (st.is_solve_level(s)) xs.push_back(s);
    if (xs.empty()) return E + E_acc;
    // E_acc = sum_x c_x x + E_acc|x=0, split through the accumulated intermediates (each
    // split once and shared by the rows that meet it)
    {
        std::map<ex, ex, GiNaC::ex_is_less> coeffs;
        ex rest = 0;
        if (st.calc_linear_form(E_acc, coeffs, rest)) {
            for (const auto& [x, c] : coeffs) {
                if (zero.find(x) == zero.end()) return std::nullopt;
                E += c * x;
            }
            return E + rest;
        }
    }
    // else by differentiation: each coefficient free of them, and the items with x = 0 free of
    // them
    for (const ex& x : xs) {
        if (zero.find(x) == zero.end()) return std::nullopt;
        const ex c = st.diff(E_acc, x);
        if (is_solve_level_in(st, c)) return std::nullopt;
        E += c * x;
    }
    const ex E0 = dot(row.direction, tree.moment_about_O(st, 1));
    if (is_solve_level_in(st, E0)) return std::nullopt;
    return E + E0;
}

}  // namespace alembert::detail
