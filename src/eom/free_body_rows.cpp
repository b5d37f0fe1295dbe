// SPDX-License-Identifier: MIT
// Free-body rows for contact forces in minimal coordinates: the planner's search over S, u, O.
#include "free_body_rows.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <tuple>

#include <Eigen/Dense>

#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/eom/kane.hpp"
#include "alembert/eom/zero_test.hpp"

namespace alembert::detail {

bool joined_at(const System& sys, const Point& P, const Body** other) {
    const Body* B = P.owner();
    if (!B || !P.located_from()) return false;
    // the first point of a body (or the root) on the way up
    const Point* anchor = P.located_from();
    while (!anchor->owner() && anchor->located_from()) anchor = anchor->located_from();
    const Body* C = anchor->owner();
    if (C == B) return false;
    const Frame& F = C && C->frame() ? *C->frame() : sys.newtonian();
    Vector offset;
    try {
        offset = P.pos_from(*anchor).dt_in(F);
    } catch (const ModelError&) {
        return false;
    }
    if (!is_zero_at_random_states(sys.symbols(), offset, sys.newtonian())) return false;
    if (other) *other = C;
    return true;
}

namespace {

// a value in +-[0.3, 1.7] drawn from a symbol's name and the state (FNV-1a): the same for
// every run, whatever the addresses
double draw(const std::string& name, unsigned state) {
    std::uint64_t h = 1469598103934665603ull ^ state;
    for (char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    const double x = static_cast<double>(h >> 11) / 9007199254740992.0;  // [0, 1)
    return (h & 1 ? -1 : 1) * (0.3 + 1.4 * x);
}

}  // namespace

bool constraint_forces_declared(const System& sys, const std::vector<TimeVariable>& coordinates,
                                const std::vector<ex>& unknowns) {
    if (sys.constraints().empty()) return true;
    // the frames' table names z' intermediates as it differentiates; it is the model's own
    SymbolTable& st = sys.newtonian().symbols();
    std::vector<ex> measures;
    for (const ex& x : unknowns)
        if (st.owns(x) && st.kind(x) == SymbolKind::unknown) measures.push_back(x);
    // F_r (linear in the measures) and each constraint at the velocity level (affine in the
    // speeds)
    const std::vector<ex> F = form_generalized_active_forces(sys, coordinates);
    std::vector<ex> C;
    for (const Constraint& c : sys.constraints())
        C.push_back(c.kind == ConstraintKind::motion ? c.residual : st.dt(c.residual));
    GiNaC::exset leaves;
    for (const std::vector<ex>* es : {&F, static_cast<const std::vector<ex>*>(&C)})
        for (const ex& e : *es)
            for (const ex& s : st.calc_leaf_symbols(e)) leaves.insert(s);
    const exmap constants = st.constant_values();
    const Eigen::Index n = static_cast<Eigen::Index>(coordinates.size());
    for (unsigned state = 1; state <= 2; ++state) {
        exmap at;
        for (const ex& s : leaves)
            if (!constants.count(s)) at[s] = draw(to_string(s), state);
        for (const ex& x : measures) at[x] = 0;
        for (const TimeVariable& q : coordinates) at[q.d(1)] = 0;
        // G(r, k): the coefficient of measure k in F_r
        Eigen::MatrixXd G(n, static_cast<Eigen::Index>(measures.size()));
        for (Eigen::Index r = 0; r < n; ++r) {
            const double base = st.evaluate(F[static_cast<std::size_t>(r)], at);
            for (std::size_t k = 0; k < measures.size(); ++k) {
                at[measures[k]] = 1;
                G(r, static_cast<Eigen::Index>(k)) = st.evaluate(F[static_cast<std::size_t>(r)], at) - base;
                at[measures[k]] = 0;
            }
        }
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(G);
        for (const ex& c : C) {
            // the constraint's direction: the coefficients of the speeds
            Eigen::VectorXd d(n);
            const double base = st.evaluate(c, at);
            for (Eigen::Index r = 0; r < n; ++r) {
                at[coordinates[static_cast<std::size_t>(r)].d(1)] = 1;
                d(r) = st.evaluate(c, at) - base;
                at[coordinates[static_cast<std::size_t>(r)].d(1)] = 0;
            }
            if (d.norm() == 0) continue;
            if (measures.empty()) return false;
            const Eigen::VectorXd rest = d - G * cod.solve(d);
            if (rest.norm() > 1e-9 * d.norm()) return false;
        }
    }
    return true;
}

namespace {

bool fb_zero(const System& sys, const Vector& v) {
    return is_zero_at_random_states(sys.symbols(), v, sys.newtonian());
}

bool fb_member(const BodySet& S, const Body* b) {
    return b && std::find(S.begin(), S.end(), b) != S.end();
}

// one line of action of an unknown force: the point and the direction of one measure
struct ForceLine {
    const Point* at;
    Vector d;
    std::string label;
};

// a candidate row: its formed equation and which unknowns of `shared` it holds
struct FbCandidate {
    RoadmapRow row;
    int coordinate = -1;  // FixedRow::coordinate, or -1 for a free-body row
    int rank = 0;         // preference among rows holding as many unknowns
    std::vector<std::size_t> holds;
};

// the unknowns of `shared` that e changes with at random states: load measures and
// accelerations whose coefficients are not zero, coordinates it depends on (a coefficient
// that cancels, sin th cos th - cos th sin th, does not count: such a row does not hold it)
std::vector<std::size_t> held_by(const System& sys, const ex& e, const std::vector<ex>& shared) {
    std::vector<std::size_t> h;
    if (e.is_zero()) return h;
    const GiNaC::exset syms = symbols_of(e);
    std::vector<std::size_t> present;
    std::vector<ex> xs;
    for (std::size_t k = 0; k < shared.size(); ++k)
        if (syms.count(shared[k])) present.push_back(k), xs.push_back(shared[k]);
    if (xs.empty()) return h;
    const std::vector<bool> changes = calc_changes_with_at_random_states(sys.symbols(), e, xs);
    for (std::size_t i = 0; i < present.size(); ++i)
        if (changes[i]) h.push_back(present[i]);
    return h;
}

// the position of a point from N_o, or false if it was never located
bool located(const System& sys, const Point& P, Vector& r) {
    try {
        r = P.pos_from(sys.origin());
        return true;
    } catch (const ModelError&) {
        return false;
    }
}

// the systems S whose free-body rows hold only declared loads: those that meet the rest
// only through declared loads (a body with every body joined to it, none joined to the
// ground), and those that meet it at one joint alone (`hinges`: the bodies beyond a joint
// whose removal parts them from the rest and the ground, turned about that joint); none
// moved by a constrained coordinate unless declared loads supply the constraints' forces
struct Hinged {
    BodySet S;
    const Point* at;
    std::vector<Vector> axes;  // the directions S turns about relative to the rest there
};
struct Systems {
    std::vector<BodySet> free;
    std::vector<Hinged> hinged;
};

void add_direction(const System& sys, std::vector<Vector>& dirs, const Vector& d);

Systems calc_systems(const System& sys, const std::vector<TimeVariable>& coordinates,
                     const std::vector<const Body*>& carriers, bool constraint_forces_are_loads) {
    const BodySet all = sys.bodies();
    const std::size_t n = all.size(), kGround = n;
    std::map<const Body*, std::size_t> index;
    for (std::size_t i = 0; i < n; ++i) index[all[i]] = i;
    // the joints whose force is not declared: (point, its body, the other body or the ground)
    struct Joint {
        const Point* at;
        std::size_t body, other;
    };
    std::vector<Joint> joints;
    for (const Point* p : sys.points()) {
        const Body* C = nullptr;
        if (!p->owner() || !joined_at(sys, *p, &C)) continue;
        if (sys.find_joint_reaction(*p, C, p->owner())) continue;  // declared: a load
        joints.push_back({p, index[p->owner()], C ? index[C] : kGround});
    }
    // the components when every joint but `skip` holds (the ground is node n)
    auto components = [&](std::size_t skip) {
        std::vector<std::size_t> root(n + 1);
        std::iota(root.begin(), root.end(), 0);
        auto find = [&](std::size_t i) {
            while (root[i] != i) i = root[i] = root[root[i]];
            return i;
        };
        for (std::size_t j = 0; j < joints.size(); ++j)
            if (j != skip) root[find(joints[j].body)] = find(joints[j].other);
        std::vector<std::size_t> comp(n + 1);
        for (std::size_t i = 0; i <= n; ++i) comp[i] = find(i);
        return comp;
    };
    // the bodies a constrained coordinate moves keep undeclared constraint forces, unless
    // declared loads supply every constraint's force
    std::vector<bool> constrained(n, false);
    for (const Constraint& c : sys.constraints()) {
        if (constraint_forces_are_loads) break;
        const GiNaC::exset syms = symbols_of(c.residual);
        for (const TimeVariable& q : coordinates) {
            if (!syms.count(q.symbol()) && !syms.count(q.d(1))) continue;
            for (std::size_t i = 0; i < n; ++i) {
                const Body* b = all[i];
                Vector w = b->frame() ? b->frame()->ang_vel_in(sys.newtonian()).diff(q.d(1)) : Vector();
                Vector v = b->cm().vel_in(sys.newtonian()).diff(q.d(1));
                if (!fb_zero(sys, w) || !fb_zero(sys, v)) constrained[i] = true;
            }
        }
    }
    // the members of the component `r` if one of them carries an unknown load and none is
    // constrained, else nothing
    auto members = [&](const std::vector<std::size_t>& comp, std::size_t r) {
        BodySet S;
        bool carries = false;
        for (std::size_t i = 0; i < n; ++i) {
            if (comp[i] != r) continue;
            if (constrained[i]) return BodySet{};
            S.push_back(all[i]);
            carries = carries || std::find(carriers.begin(), carriers.end(), all[i]) != carriers.end();
        }
        return carries ? S : BodySet{};
    };
    Systems out;
    const std::vector<std::size_t> held = components(joints.size());
    std::vector<std::size_t> seen;
    for (const Body* b : carriers) {
        const std::size_t r = held[index[b]];
        if (r == held[kGround] || std::find(seen.begin(), seen.end(), r) != seen.end()) continue;
        seen.push_back(r);
        BodySet S = members(held, r);
        if (!S.empty()) out.free.push_back(std::move(S));
    }
    const Frame& N = sys.newtonian();
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const std::vector<std::size_t> comp = components(j);
        if (comp[joints[j].body] == comp[joints[j].other]) continue;  // a loop: not parted by it
        // the directions the joint lets its two sides turn about: the partials of the relative
        // angular velocity (no torque about them unless one is declared)
        std::vector<Vector> axes;
        const Body& B = *all[joints[j].body];
        Vector w_rel = B.frame() ? B.frame()->ang_vel_in(N) : Vector();
        if (joints[j].other != kGround && all[joints[j].other]->frame())
            w_rel = w_rel - all[joints[j].other]->frame()->ang_vel_in(N);
        for (const TimeVariable& q : coordinates) {
            Vector d = w_rel.diff(q.d(1));
            if (d.is_zero() || fb_zero(sys, d)) continue;
            // an axis of a frame when it lies along one (a pin's axis Nz>, not k Nz> / |k|)
            std::vector<const Frame*> frames{&N};
            for (const Frame* F = B.frame(); F; F = F->parent()) frames.push_back(F);
            for (const Frame* F : frames)
                for (const Vector& e : {F->x(), F->y(), F->z()})
                    if (fb_zero(sys, cross(e, d))) {
                        d = e;
                        break;
                    }
            add_direction(sys, axes, d);
        }
        if (axes.empty()) continue;  // a weld
        // the side away from the ground
        for (std::size_t side : {joints[j].body, joints[j].other}) {
            if (side == kGround || comp[side] == comp[kGround]) continue;
            BodySet S = members(comp, comp[side]);
            if (!S.empty()) out.hinged.push_back({std::move(S), joints[j].at, axes});
        }
    }
    return out;
}

// unit directions, parallel ones once
void add_direction(const System& sys, std::vector<Vector>& dirs, const Vector& d) {
    if (d.is_zero() || fb_zero(sys, d)) return;
    for (const Vector& e : dirs)
        if (fb_zero(sys, cross(e, d))) return;
    dirs.push_back(d.unit());
}

// the free-body candidates of S
void add_free_body_candidates(const System& sys, const BodySet& S, const std::vector<ex>& shared,
                              Analysis analysis, std::vector<FbCandidate>& out) {
    const SymbolTable& st = sys.symbols();
    const Frame& N = sys.newtonian();
    // the unknown forces on S from outside it, one line per measure
    std::vector<ForceLine> lines;
    for (const Load& l : sys.loads()) {
        if (l.kind != LoadKind::force || !fb_member(S, l.on) || fb_member(S, l.from)) continue;
        for (const ex& x : shared) {
            if (!(st.owns(x) && st.kind(x) == SymbolKind::unknown)) continue;
            Vector d = l.vector.diff(x);
            if (d.is_zero() || fb_zero(sys, d)) continue;
            lines.push_back({l.point, d, l.label.empty() ? to_string(x) : l.label});
        }
    }
    // directions: the axes of N and of the frames up from S's bodies, the unknown forces'
    std::vector<Vector> dirs;
    for (const Vector& d : {N.x(), N.y(), N.z()}) add_direction(sys, dirs, d);
    for (const Body* b : S)
        for (const Frame* F = b->frame(); F; F = F->parent())
            for (const Vector& d : {F->x(), F->y(), F->z()}) add_direction(sys, dirs, d);
    for (const ForceLine& fl : lines) add_direction(sys, dirs, fl.d);
    // about points: the located points of S, then where two unknown forces' lines meet
    struct About {
        const Point* P;
        std::shared_ptr<const Point> own;
        Vector r;
        int rank;
    };
    std::vector<About> points;
    auto known = [&](const Vector& r) {
        for (const About& a : points)
            if (fb_zero(sys, a.r - r)) return true;
        return false;
    };
    for (const Point* P : sys.points()) {
        Vector r;
        if (!fb_member(S, P->owner()) || !located(sys, *P, r) || known(r)) continue;
        points.push_back({P, nullptr, r, 3});
    }
    for (std::size_t i = 0; i < lines.size(); ++i)
        for (std::size_t j = i + 1; j < lines.size(); ++j)
            for (const Vector& u : dirs) {
                Vector r1, r2;
                if (!located(sys, *lines[i].at, r1) || !located(sys, *lines[j].at, r2)) continue;
                const ex den = dot(cross(lines[i].d, lines[j].d), u);
                if (is_zero_at_random_states(st, den)) continue;
                // r1 + a d1 meets r2 + b d2 in the plane normal to u
                const ex a = dot(cross(r2 - r1, lines[j].d), u) / den;
                Vector r = r1 + a * lines[i].d;
                if (known(r)) continue;
                auto I = std::make_shared<Point>("I_" + lines[i].label + "_" + lines[j].label);
                I->set_pos(sys.origin(), r);
                points.push_back({I.get(), I, r, 4});
            }
    for (const Vector& u : dirs) {
        RoadmapRow r{.variable = ex(), .motion = Motion::translate, .direction = u, .system = S,
                     .analysis = analysis};
        r.equation = form_roadmap_equation(sys, r);
        std::vector<std::size_t> h = held_by(sys, r.equation, shared);
        out.push_back({std::move(r), -1, 2, std::move(h)});
    }
    for (const About& a : points)
        for (const Vector& u : dirs) {
            RoadmapRow r{.variable = ex(), .motion = Motion::rotate, .direction = u, .system = S,
                         .about = a.P, .analysis = analysis};
            r.about_owned = a.own;
            r.equation = form_roadmap_equation(sys, r);
            std::vector<std::size_t> h = held_by(sys, r.equation, shared);
            out.push_back({std::move(r), -1, a.rank, std::move(h)});
        }
}

bool fb_contains(const std::vector<std::size_t>& v, std::size_t x) {
    return std::find(v.begin(), v.end(), x) != v.end();
}

// the coefficient matrix of the rows in the unknowns has full row rank (a non-zero minor)
bool independent(const System& sys, const std::vector<const FbCandidate*>& rows,
                 const std::vector<ex>& xs) {
    const std::size_t r = rows.size(), n = xs.size();
    if (r > n) return false;
    std::vector<std::size_t> pick(r);
    // every r-subset of the columns
    std::vector<bool> mask(n, false);
    std::fill(mask.begin(), mask.begin() + static_cast<std::ptrdiff_t>(r), true);
    do {
        std::size_t k = 0;
        for (std::size_t j = 0; j < n; ++j)
            if (mask[j]) pick[k++] = j;
        GiNaC::matrix A(static_cast<unsigned>(r), static_cast<unsigned>(r));
        for (std::size_t i = 0; i < r; ++i)
            for (std::size_t j = 0; j < r; ++j)
                A(static_cast<unsigned>(i), static_cast<unsigned>(j)) =
                    rows[i]->row.equation.diff(GiNaC::ex_to<GiNaC::symbol>(xs[pick[j]]));
        if (!is_zero_at_random_states(sys.symbols(), A.determinant())) return true;
    } while (std::prev_permutation(mask.begin(), mask.end()));
    return false;
}

}  // namespace

std::vector<RoadmapRow> plan_free_body_rows(const System& sys,
                                            const std::vector<TimeVariable>& coordinates,
                                            const std::vector<FixedRow>& fixed,
                                            const std::vector<ex>& shared,
                                            const std::vector<ex>& unknowns, Analysis analysis,
                                            bool constraint_forces_are_loads) {
    const SymbolTable& st = sys.symbols();
    std::vector<FbCandidate> cands;
    for (const FixedRow& f : fixed) {
        FbCandidate c{f.row, f.coordinate, f.coordinate == FixedRow::kAnyCoordinate ? 1 : 0, {}};
        c.holds = held_by(sys, c.row.equation, shared);
        cands.push_back(std::move(c));
    }
    // the bodies that carry unknown loads from outside them
    std::vector<const Body*> carriers;
    for (const Load& l : sys.loads()) {
        if (!l.on || std::find(carriers.begin(), carriers.end(), l.on) != carriers.end()) continue;
        const GiNaC::exset syms = [&] {
            GiNaC::exset s;
            for (const auto& part : l.vector.components())
                for (int i = 0; i < 3; ++i)
                    for (const ex& x : symbols_of(part.second[i])) s.insert(x);
            return s;
        }();
        for (const ex& x : shared)
            if (syms.count(x) && st.owns(x) && st.kind(x) == SymbolKind::unknown) {
                carriers.push_back(l.on);
                break;
            }
    }
    const Systems systems = calc_systems(sys, coordinates, carriers, constraint_forces_are_loads);
    for (const BodySet& S : systems.free) add_free_body_candidates(sys, S, shared, analysis, cands);
    // a system hinged to the rest at one joint: rotate about the joint's free axes there
    for (const Hinged& h : systems.hinged)
        for (const Vector& u : h.axes) {
            RoadmapRow r{.variable = ex(), .motion = Motion::rotate, .direction = u, .system = h.S,
                         .about = h.at, .analysis = analysis};
            r.equation = form_roadmap_equation(sys, r);
            std::vector<std::size_t> held = held_by(sys, r.equation, shared);
            cands.push_back({std::move(r), -1, 3, std::move(held)});
        }

    // the coordinate whose derivative (or itself) an unknown is, or -1 for a load measure
    std::vector<int> coordinate_of(shared.size(), -1);
    for (std::size_t k = 0; k < shared.size(); ++k)
        for (std::size_t i = 0; i < coordinates.size(); ++i)
            for (int d = 0; d <= coordinates[i].order(); ++d)
                if (shared[k].is_equal(coordinates[i].d(d))) coordinate_of[k] = static_cast<int>(i);
    auto may_take = [&](const FbCandidate& c, std::size_t k) {
        return coordinate_of[k] < 0 || c.coordinate == coordinate_of[k] ||
               c.coordinate == FixedRow::kAnyCoordinate;
    };

    std::vector<bool> solved(shared.size(), false), used(cands.size(), false);
    std::vector<std::pair<std::size_t, ex>> chosen;  // candidate, its variable
    std::size_t n_solved = 0;
    auto fresh = [&](const FbCandidate& c) {
        std::vector<std::size_t> f;
        for (std::size_t k : c.holds)
            if (!solved[k]) f.push_back(k);
        return f;
    };
    while (n_solved < shared.size()) {
        // a row that brings one new unknown, holding as few as possible
        std::size_t best = cands.size();
        std::tuple<std::size_t, std::size_t, int, std::size_t> best_key{};
        for (std::size_t c = 0; c < cands.size(); ++c) {
            if (used[c]) continue;
            std::vector<std::size_t> f = fresh(cands[c]);
            if (f.size() != 1 || !may_take(cands[c], f[0])) continue;
            auto key = std::make_tuple(cands[c].holds.size(), f[0], cands[c].rank, c);
            if (best == cands.size() || key < best_key) best = c, best_key = key;
        }
        if (best < cands.size()) {
            const std::size_t k = fresh(cands[best])[0];
            used[best] = true;
            solved[k] = true;
            ++n_solved;
            chosen.push_back({best, shared[k]});
            continue;
        }
        // else the smallest block: the rows holding no unknowns but those of the row that
        // brings the fewest new ones, as many as they determine
        std::vector<std::size_t> order;
        for (std::size_t c = 0; c < cands.size(); ++c)
            if (!used[c] && !fresh(cands[c]).empty()) order.push_back(c);
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return std::make_tuple(fresh(cands[a]).size(), cands[a].holds.size(), cands[a].rank) <
                   std::make_tuple(fresh(cands[b]).size(), cands[b].holds.size(), cands[b].rank);
        });
        bool progressed = false;
        for (std::size_t seed : order) {
            std::vector<std::size_t> U = fresh(cands[seed]);
            if (U.size() > 4) break;
            std::vector<ex> xs;
            for (std::size_t k : U) xs.push_back(shared[k]);
            std::vector<const FbCandidate*> rows{&cands[seed]};
            std::vector<std::size_t> ids{seed};
            for (std::size_t c : order) {
                if (rows.size() == U.size()) break;
                if (c == seed) continue;
                std::vector<std::size_t> f = fresh(cands[c]);
                if (!std::all_of(f.begin(), f.end(), [&](std::size_t k) { return fb_contains(U, k); }))
                    continue;
                rows.push_back(&cands[c]);
                if (independent(sys, rows, xs)) ids.push_back(c);
                else rows.pop_back();
            }
            if (rows.size() != U.size()) continue;
            // each unknown to a row that may take it: coordinates' derivatives first
            std::vector<bool> taken(ids.size(), false);
            std::vector<std::pair<std::size_t, ex>> block;
            bool ok = true;
            std::vector<std::size_t> byk = U;
            std::stable_sort(byk.begin(), byk.end(),
                             [&](std::size_t a, std::size_t b) { return coordinate_of[a] > coordinate_of[b]; });
            for (std::size_t k : byk) {
                std::size_t j = 0;
                while (j < ids.size() && (taken[j] || !may_take(cands[ids[j]], k) ||
                                          !fb_contains(cands[ids[j]].holds, k)))
                    ++j;
                if (j == ids.size()) {
                    ok = false;
                    break;
                }
                taken[j] = true;
                block.push_back({ids[j], shared[k]});
            }
            if (!ok) continue;
            for (const auto& [c, x] : block) {
                used[c] = true;
                chosen.push_back({c, x});
            }
            for (std::size_t k : U) solved[k] = true;
            n_solved += U.size();
            progressed = true;
            break;
        }
        if (!progressed) {
            std::string names;
            for (std::size_t k = 0; k < shared.size(); ++k)
                if (!solved[k]) names += (names.empty() ? "" : ", ") + to_string(shared[k]);
            throw ModelError("no choice of S, direction and about point determines " + names);
        }
    }
    std::vector<RoadmapRow> rows;
    for (const auto& [c, x] : chosen) {
        RoadmapRow r = cands[c].row;
        r.variable = x;
        if (r.motion == Motion::constraint) {
            r.additional_unknowns.clear();
            form_constraint_row(sys, r, unknowns);
        } else {
            form_roadmap_row(sys, r, unknowns);
        }
        rows.push_back(std::move(r));
    }
    return rows;
}

}  // namespace alembert::detail
