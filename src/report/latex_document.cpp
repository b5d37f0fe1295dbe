// SPDX-License-Identifier: MIT
// The road-map as a LaTeX document: the table, each row's free-body diagram in TikZ, the
// equations, the mass matrix and the script's results (a sweep's: latex_sweep.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "alembert/error.hpp"
#include "alembert/report/report.hpp"
#include "alembert/sym/print.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

using namespace report_detail;

// text for a verbatim environment: lines longer than a page's width broken at a space (or
// anywhere when there is none), continued indented
std::string verbatim_lines(std::string text) {
    constexpr std::size_t kWidth = 80;
    while (!text.empty() && text.back() == '\n') text.pop_back();
    std::string out;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        bool first = true;
        while (!line.empty() || first) {
            const std::size_t room = first ? kWidth : kWidth - 4;
            std::string piece = line;
            if (line.size() > room) {
                std::size_t cut = line.rfind(' ', room);
                if (cut == std::string::npos || cut < room / 2) cut = room;
                piece = line.substr(0, cut);
                line = line.substr(cut == room ? cut : cut + 1);
            } else {
                line.clear();
            }
            out += (first ? "" : "    ") + piece + "\n";
            first = false;
        }
        if (end == text.size()) break;
        start = end + 1;
    }
    // a line of the text ending the environment early is impossible: \end{verbatim} is never
    // printed by a statement, but guard it all the same
    std::string::size_type at;
    while ((at = out.find("\\end{verbatim}")) != std::string::npos) out.replace(at, 1, "/");
    return out;
}

// a name for LaTeX's text mode that may break after each underscore (IC_knee_angle_r in a
// narrow column)
std::string breakable_name(const std::string& s) {
    std::string o;
    for (const char ch : s) o += ch == '_' ? "\\_\\allowbreak{}" : tex_text(std::string(1, ch));
    return o;
}

std::string set_words(const BodySet& S) {
    std::string s = "\\{";
    for (std::size_t i = 0; i < S.size(); ++i) s += (i ? ",\\allowbreak " : "") + tex_text(S[i]->name());
    return s + "\\}";
}

// ---- the free-body diagram in TikZ ---------------------------------------------------------

std::string cm(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", std::abs(v) < 5e-4 ? 0.0 : v);
    return buf;
}

// the page's projection (the viewer's default view), "up" up the page: planar models in their
// plane; others in axes (h, up, h x up), h the N axis least along up made square to it,
// turned 0.6 rad about up and tilted 0.35 rad; TikZ's y points up
class Projection {
public:
    Projection(const std::vector<double>& up, bool planar) : planar_(planar) {
        u_ = {up.size() > 0 ? up[0] : 0, up.size() > 1 ? up[1] : 1, up.size() > 2 ? up[2] : 0};
        if (planar) u_[2] = 0;
        const double n = std::sqrt(dot(u_, u_));
        if (!(n > 1e-12) || !std::isfinite(n)) u_ = {0, 1, 0};
        else for (double& x : u_) x /= n;
        std::array<std::array<double, 3>, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        std::stable_sort(axes.begin(), axes.end(), [&](const auto& a, const auto& b) {
            return std::abs(dot(a, u_)) < std::abs(dot(b, u_));
        });
        const double k = dot(axes[0], u_);
        for (int i = 0; i < 3; ++i) h_[i] = axes[0][i] - k * u_[i];
        const double hn = std::sqrt(dot(h_, h_));
        for (double& x : h_) x /= hn;
        w_ = {h_[1] * u_[2] - h_[2] * u_[1], h_[2] * u_[0] - h_[0] * u_[2],
              h_[0] * u_[1] - h_[1] * u_[0]};
    }
    std::array<double, 2> operator()(const std::vector<double>& p) const {
        if (p.size() < 3) return {0, 0};
        const std::array<double, 3> q{p[0], p[1], p[2]};
        if (planar_) return {u_[1] * q[0] - u_[0] * q[1], u_[0] * q[0] + u_[1] * q[1]};
        const double ct = std::cos(0.6), st = std::sin(0.6), ce = std::cos(0.35), se = std::sin(0.35);
        const double X = dot(q, h_), Y = dot(q, u_), Z = dot(q, w_);
        const double x = ct * X + st * Z, z = -st * X + ct * Z;
        return {x, ce * Y + se * z};
    }

private:
    static double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
    bool planar_;
    std::array<double, 3> u_{}, h_{}, w_{};
};

// labels placed so that none covers another nor lies on a load arrow, as the page places
// them: each is tried at offsets around its anchor, nearest first, in the eight directions
// starting with the one it prefers; kept is the first place that meets no label placed
// before, no point, arrowhead or load arrow and, near the anchor, no line of S or angle's
// arc; else the first clear of labels, points, heads and load arrows; else of labels, points
// and heads; else of labels. Sizes are estimated for \scriptsize (cm).
class LabelPlacer {
public:
    struct Box {
        double x, y, w, h;  // lower left corner, TikZ axes
    };
    static constexpr double kHeight = 0.32;
    static double width(const std::string& text) {
        return 0.13 * static_cast<double>(text.size()) + 0.1;
    }
    void obstacle(double x, double y, double half) {
        obstacles_.push_back({x - half, y - half, 2 * half, 2 * half});
    }
    void fix(const Box& b) { placed_.push_back(b); }
    // a segment drawn: a load arrow's (arrow) or a line of S or an angle's arc
    void segment(std::array<double, 2> a, std::array<double, 2> b, bool arrow) {
        (arrow ? arrows_ : lines_).push_back({a, b});
    }
    // an arc about c of radius r from angle a0 to a1 (radians), as segments
    void arc(std::array<double, 2> c, double r, double a0, double a1, bool arrow) {
        for (int k = 1; k <= 20; ++k) {
            const double s0 = a0 + (a1 - a0) * (k - 1) / 20, s1 = a0 + (a1 - a0) * k / 20;
            segment({c[0] + r * std::cos(s0), c[1] + r * std::sin(s0)},
                    {c[0] + r * std::cos(s1), c[1] + r * std::sin(s1)}, arrow);
        }
    }
    // the centre of the label's box
    std::array<double, 2> place(const std::string& text, std::array<double, 2> anchor,
                                std::array<double, 2> prefer) {
        static const int dirs[8][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                       {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
        const double w = width(text), h = kHeight;
        int start = 0;
        double best = -1e300;
        for (int i = 0; i < 8; ++i) {
            const double c = (dirs[i][0] * prefer[0] + dirs[i][1] * prefer[1]) /
                             std::hypot(dirs[i][0], dirs[i][1]);
            if (c > best + 1e-9) best = c, start = i;
        }
        const auto at = [&](double gap, int k) {
            const int* d = dirs[(start + k) % 8];
            const double cx = anchor[0] + d[0] * (gap + w / 2);
            const double cy = anchor[1] + d[1] * (gap + h / 2);
            return Box{cx - w / 2, cy - h / 2, w, h};
        };
        const auto meets = [](const Box& a, const Box& b) {
            return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
        };
        const auto crosses = [](const Box& b, const std::vector<Seg>& segments) {
            for (const Seg& s : segments)
                if (segment_meets_box(s[0], s[1], b)) return true;
            return false;
        };
        // level 3: clear of everything; 2: of labels, points, heads and load arrows; 1: of
        // labels, points and heads; 0: of labels
        const auto free = [&](const Box& b, int level) {
            const Box grown{b.x - 0.03, b.y - 0.03, b.w + 0.06, b.h + 0.06};
            for (const Box& o : placed_)
                if (meets(grown, o)) return false;
            if (level >= 1)
                for (const Box& o : obstacles_)
                    if (meets(b, o)) return false;
            if (level >= 2 && crosses(b, arrows_)) return false;
            if (level >= 3 && crosses(b, lines_)) return false;
            return true;
        };
        // clear of everything only near the anchor: farther, a label is better on a line of S
        for (int level = 3; level >= 0; --level)
            for (int r = 0; r < (level == 3 ? 8 : 40); ++r)
                for (int k = 0; k < 8; ++k) {
                    const Box b = at(0.06 + 0.15 * r, k);
                    if (free(b, level)) {
                        placed_.push_back(b);
                        return {b.x + w / 2, b.y + h / 2};
                    }
                }
        const Box b = at(7, 0);
        placed_.push_back(b);
        return {b.x + w / 2, b.y + h / 2};
    }

private:
    using Seg = std::array<std::array<double, 2>, 2>;
    // whether the segment a-b passes through the box (Liang-Barsky clipping)
    static bool segment_meets_box(std::array<double, 2> a, std::array<double, 2> b, const Box& r) {
        double t0 = 0, t1 = 1;
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        const double p[4] = {-dx, dx, -dy, dy};
        const double q[4] = {a[0] - r.x, r.x + r.w - a[0], a[1] - r.y, r.y + r.h - a[1]};
        for (int i = 0; i < 4; ++i) {
            if (std::abs(p[i]) < 1e-12) {
                if (q[i] < 0) return false;
                continue;
            }
            const double t = q[i] / p[i];
            if (p[i] < 0) {
                if (t > t1) return false;
                t0 = std::max(t0, t);
            } else {
                if (t < t0) return false;
                t1 = std::min(t1, t);
            }
        }
        return true;
    }
    std::vector<Box> placed_, obstacles_;
    std::vector<Seg> arrows_, lines_;
};

// the row's variable without its primes: the coordinate whose acceleration it is
std::string coordinate_of(const ex& variable) {
    std::string v = to_string(variable);
    while (!v.empty() && v.back() == '\'') v.pop_back();
    return v;
}

std::string degrees(double a) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", std::abs(a) < 0.05 ? 0.0 : a);
    return buf;
}

// the free-body diagram as the page draws it: S in ink, the loads on S (the row's own unknown
// highlighted, loads the equation does not hold dashed), S's points named, a planar model's
// angles of S marked, u below; *legend says what the styles used mean
std::string tikz_diagram(const System& sys, const Evaluation& ev,
                         const std::vector<const Point*>& placed, bool planar,
                         const RoadmapRow& r, std::string* legend) {
    const Projection project(view_up(sys, ev, planar), planar);
    std::map<const Point*, std::array<double, 2>> at;
    std::vector<const Point*> order;  // the model's order, for the same output run to run
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    // the model's points, and O where the planner located it off them (an instantaneous centre)
    std::vector<const Point*> shown = placed;
    if (const Point* o = row_about_point(r, ev)) shown.push_back(o);
    for (const Point* p : shown) {
        std::array<double, 2> q = project(ev.position(p));
        if (!std::isfinite(q[0]) || !std::isfinite(q[1])) continue;
        at[p] = q;
        order.push_back(p);
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    }
    if (at.empty()) return "";
    const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-9});
    const double scale = 5.0 / size, arrow = 1.3;  // the model 5 cm across; arrows 1.3 cm
    // a point of the model in the picture's centimetres
    const auto cmxy = [&](const std::array<double, 2>& q) {
        return std::array<double, 2>{scale * (q[0] - lo[0]), scale * (q[1] - lo[1])};
    };
    const auto pt = [&](const std::array<double, 2>& c) {
        return "(" + cm(c[0]) + "," + cm(c[1]) + ")";
    };
    const auto xy = [&](const std::array<double, 2>& q) { return pt(cmxy(q)); };
    const auto unit = [&](const std::vector<double>& v, double* ux, double* uy) {
        std::array<double, 2> d = project(v);
        const double n = std::hypot(d[0], d[1]);
        if (!(n > 1e-12) || !std::isfinite(n)) return false;
        *ux = d[0] / n, *uy = d[1] / n;
        return true;
    };
    const auto find = [&](const std::string& name) -> const Point* {
        for (const Point* p : order)
            if (p->name() == name) return p;
        return nullptr;
    };
    const auto in_s = [&](const Body* b) {
        return std::find(r.system.begin(), r.system.end(), b) != r.system.end();
    };
    LabelPlacer labels;
    // the labels, written last (over everything), the row's own first, the points' last
    struct Pending {
        std::string tex, text;  // what is written; its characters, for its size
        std::array<double, 2> anchor, prefer;
        std::string style;
        int rank;
    };
    std::vector<Pending> pending;
    double box_lo[2] = {0, 0};  // the lower left of what is drawn, for u below it
    const auto grow = [&](const std::array<double, 2>& c) {
        for (int k = 0; k < 2; ++k) box_lo[k] = std::min(box_lo[k], c[k]);
    };
    std::string t = "\\begin{tikzpicture}[>=stealth, every node/.style={font=\\scriptsize}]\n";
    for (const Segment& seg : segments_of(sys, placed)) {
        const Point *a = find(seg.from), *b = find(seg.to);
        if (!a || !b) continue;
        const bool ink = std::any_of(r.system.begin(), r.system.end(),
                                     [&](const Body* x) { return x->name() == seg.body; });
        t += "\\draw[" + std::string(ink ? "line width=1.6pt" : "line width=1.2pt, black!25") +
             ", line cap=round] " + xy(at[a]) + " -- " + xy(at[b]) + ";\n";
        if (ink) labels.segment(cmxy(at[a]), cmxy(at[b]), false);
    }
    for (const Point* p : order) {
        t += "\\fill " + xy(at[p]) + " circle (0.8pt);\n";
        const auto c = cmxy(at[p]);
        labels.obstacle(c[0], c[1], 0.06);
        grow(c);
    }
    // the angles of S's rotations (planar models): a dotted line along the parent's axis, an
    // arc from it to the body's axis, the coordinate's name
    const std::string own_name = coordinate_of(r.variable);
    bool own_angle = false;
    if (planar)
        for (const DiagramAngle& a : planar_angles(sys, ev)) {
            if (!in_s(a.body) || !at.count(a.at)) continue;
            double fx = 0, fy = 0, tx = 0, ty = 0, gx = 0, gy = 0;
            if (!unit(a.from, &fx, &fy) || !unit(a.to, &tx, &ty)) continue;
            const auto c = cmxy(at[a.at]);
            // a turn about +z on the picture: the parent's axis turned +90 deg about z, projected
            const bool turned = unit({-a.from[1], a.from[0], 0}, &gx, &gy);
            const double sense = !turned || fx * gy - fy * gx >= 0 ? 1 : -1;
            const double a0 = std::atan2(fy, fx) * 180 / M_PI;
            const double sweep =
                std::atan2(std::sin(a.value), std::cos(a.value)) * 180 / M_PI * sense;
            const bool own = a.name == own_name;
            own_angle = own_angle || own;
            t += "% angle: " + tex_text(a.name) + " of " + tex_text(a.body->name()) + " at " +
                 tex_text(a.at->name()) + "\n";
            t += "\\draw[densely dotted, black!50] " + pt(c) + " -- ++(" + cm(0.9 * fx) + "," +
                 cm(0.9 * fy) + ");\n";
            t += "\\draw[" + std::string(own ? "red!75!black, line width=1.2pt" : "black!70") +
                 "] " + pt({c[0] + 0.45 * fx, c[1] + 0.45 * fy}) + " arc[start angle=" +
                 degrees(a0) + ", end angle=" + degrees(a0 + sweep) + ", radius=0.45];\n";
            labels.arc(c, 0.45, a0 * M_PI / 180, (a0 + sweep) * M_PI / 180, false);
            const double mid = (a0 + sweep / 2) * M_PI / 180;
            pending.push_back({"$" + to_latex(GiNaC::symbol(a.name)) + "$", a.name,
                               {c[0] + 0.45 * std::cos(mid), c[1] + 0.45 * std::sin(mid)},
                               {std::cos(mid), std::sin(mid)},
                               own ? "red!75!black, font=\\scriptsize\\bfseries" : "black!70", 3});
        }
    const std::vector<DiagramLoad> loads = diagram_loads(sys, ev, r);
    bool own_load = false, drops = false, held = false;
    // the loads zero here; those whose value this configuration does not give; those at a
    // point not placed here
    std::string zero, not_given, unplaced;
    for (const DiagramLoad& l : loads) {
        if (!l.placed) {
            unplaced += (unplaced.empty() ? "" : ", ") + tex_text(l.label) + " at " + tex_text(l.at->name());
            continue;
        }
        auto it = at.find(l.at);
        if (it == at.end()) continue;
        const std::array<double, 2> p = cmxy(it->second);
        const std::string colour = l.kind == "gravity" ? "green!50!black"
                                   : l.unknown         ? "red!75!black"
                                                       : "blue!70!black";
        // the row's own unknown highlighted; a load the equation does not hold dashed, faded
        std::string style = colour;
        if (l.role == LoadRole::own)
            style += ", line width=1.2pt, preaction={draw, yellow!80!orange, line width=3.6pt, "
                     "opacity=0.6, -}";
        if (l.role == LoadRole::drops_out) style += ", densely dashed, opacity=0.55";
        own_load = own_load || l.role == LoadRole::own;
        drops = drops || l.role == LoadRole::drops_out;
        held = held || l.role == LoadRole::held;
        // a known load zero here (a damper at rest), or whose value this configuration does
        // not give: along its positive sense, labelled zero (or with no value)
        const std::vector<double>& v = l.sense.empty() ? l.vector : l.sense;
        std::string& listed = l.given ? zero : not_given;
        if (!l.sense.empty() || !l.given) listed += (listed.empty() ? "" : ", ") + tex_text(l.label);
        const std::string label = (l.tex.empty() ? tex_text(l.label) : "$" + l.tex + "$") +
                                  (l.sense.empty() || !l.given ? "" : " $= 0$");
        const std::string text_style =
            colour + (l.role == LoadRole::own ? ", font=\\scriptsize\\bfseries" : "") +
            (l.role == LoadRole::drops_out ? ", text opacity=0.7" : "");
        t += "% load: " + tex_text(l.label) + "\n";
        std::array<double, 2> anchor = p, prefer{1, 1};
        const auto tip = [&](double x, double y) {
            labels.obstacle(x, y, 0.1);
            grow({x, y});
        };
        double ux = 0, uy = 0;
        if (l.kind == "joint") {
            std::vector<std::vector<double>> axes{{1, 0, 0}, {0, 1, 0}};
            if (!planar) axes.push_back({0, 0, 1});
            for (const auto& e : axes)
                if (unit(e, &ux, &uy)) {
                    t += "\\draw[->, " + style + "] " + pt(p) + " -- ++(" +
                         cm(0.7 * arrow * ux) + "," + cm(0.7 * arrow * uy) + ");\n";
                    tip(p[0] + 0.7 * arrow * ux, p[1] + 0.7 * arrow * uy);
                    labels.segment(p, {p[0] + 0.7 * arrow * ux, p[1] + 0.7 * arrow * uy}, true);
                }
            anchor = {p[0] + 0.35 * arrow, p[1] - 0.05};
            prefer = {1, -1};
        } else if (l.kind == "torque" && planar) {
            // an arc about the point, counterclockwise for a +z torque
            const bool ccw = v.size() < 3 || v[2] >= 0;
            const double a0 = ccw ? -1.0 : 2.6, a1 = ccw ? 2.6 : -1.0;
            t += "\\draw[->, " + style + "] " +
                 pt({p[0] + 0.45 * std::cos(a0), p[1] + 0.45 * std::sin(a0)}) +
                 " arc[start angle=" + (ccw ? "-57" : "149") +
                 ", end angle=" + (ccw ? "149" : "-57") + ", radius=0.45];\n";
            tip(p[0] + 0.45 * std::cos(a1), p[1] + 0.45 * std::sin(a1));
            labels.arc(p, 0.45, a0, a1, true);
            anchor = {p[0] + 0.32, p[1] + 0.32};
        } else if (unit(v, &ux, &uy)) {
            const std::array<double, 2> end{p[0] + arrow * ux, p[1] + arrow * uy};
            if (l.kind == "gravity") {
                t += "\\draw[->, " + style + "] " + pt(p) + " -- ++(" + cm(arrow * ux) + "," +
                     cm(arrow * uy) + ");\n";
                tip(end[0], end[1]);
                labels.segment(p, end, true);
                anchor = {p[0] + 0.6 * arrow * ux, p[1] + 0.6 * arrow * uy};
                prefer = {1, 0};
            } else if (l.kind == "torque") {  // in space: a double-headed arrow along the torque
                t += "\\draw[->>, " + style + "] " + pt(p) + " -- " + pt(end) + ";\n";
                tip(end[0], end[1]);
                labels.segment(p, end, true);
                anchor = end;
                prefer = {ux, uy};
            } else {
                const std::array<double, 2> tail{p[0] - arrow * ux, p[1] - arrow * uy};
                t += "\\draw[->, " + style + "] " + pt(tail) + " -- " + pt(p) + ";\n";
                tip(p[0], p[1]);
                labels.segment(tail, p, true);
                grow(tail);
                anchor = tail;
                prefer = {-ux, -uy};
            }
        } else {
            t += "\\draw[" + style + "] " + pt(p) + " circle (0.2);\n";
        }
        pending.push_back(
            {label, l.label, anchor, prefer, text_style, l.role == LoadRole::own ? 0 : 1});
    }
    if (r.about && at.count(r.about)) {
        t += "\\draw " + xy(at[r.about]) + " circle (2.5pt);\n";
        pending.push_back({"$O$ = " + tex_text(r.about->name()), "O = " + r.about->name(),
                           cmxy(at[r.about]), {-1, -1}, "black", 2});
    }
    // S's points named (O's already is)
    for (const Point* p : diagram_points(sys, r, loads))
        if (p != r.about && at.count(p))
            pending.push_back(
                {tex_text(p->name()), p->name(), cmxy(at[p]), {-1, -1}, "black!80", 4});
    // the direction u below the drawing, wholly in its box, its label right of the arrow
    double ux = 0, uy = 0;
    const std::vector<double> u = ev.in_newtonian(r.direction);
    const bool in_plane = unit(u, &ux, &uy) && (!planar || std::hypot(u[0], u[1]) > 0.2);
    const std::array<double, 2> corner{std::min(box_lo[0], -0.8), box_lo[1] - 0.5};  // top left
    double right = 0, middle = 0;
    if (in_plane) {
        const double ax = std::abs(0.8 * ux), ay = std::abs(0.8 * uy);
        const std::array<double, 2> from{corner[0] + (ux < 0 ? ax : 0),
                                         corner[1] - (uy > 0 ? ay : 0)};
        t += "\\draw[->, violet] " + pt(from) + " -- ++(" + cm(0.8 * ux) + "," + cm(0.8 * uy) +
             ");\n";
        right = corner[0] + ax + 0.1;
        middle = corner[1] - ay / 2;
        labels.fix({corner[0] - 0.1, corner[1] - ay - 0.1, ax + 0.2, ay + 0.2});
    } else {
        const std::array<double, 2> c{corner[0] + 0.12, corner[1] - 0.12};
        t += "\\draw[violet] " + pt(c) + " circle (0.12);\n\\fill[violet] " + pt(c) +
             " circle (0.03);\n";
        right = corner[0] + 0.3;
        middle = c[1];
        labels.fix({corner[0], corner[1] - 0.24, 0.24, 0.24});
    }
    const std::string uword = in_plane ? "u" : "u out of the page";
    t += "\\node[violet, anchor=west] at " + pt({right, middle}) + " {$\\hat u$" +
         (in_plane ? "" : " out of the page") + "};\n";
    labels.fix({right, middle - LabelPlacer::kHeight / 2, LabelPlacer::width(uword),
                LabelPlacer::kHeight});
    std::stable_sort(pending.begin(), pending.end(),
                     [](const Pending& a, const Pending& b) { return a.rank < b.rank; });
    for (const Pending& p : pending) {
        const std::array<double, 2> c = labels.place(p.text, p.anchor, p.prefer);
        t += "% label: " + tex_text(p.text) + "\n";
        t += "\\node[" + p.style + ", fill=white, fill opacity=0.7, text opacity=1, " +
             "inner sep=0.5pt] at " + pt(c) + " {" + p.tex + "};\n";
    }
    t += "\\end{tikzpicture}\n";
    if (legend) {
        legend->clear();
        if (own_load || own_angle)
            *legend += " Highlighted: solved for in this row ($" + to_latex(r.variable) + "$).";
        if (held) *legend += " Red: unknowns the equation also holds.";
        if (drops)
            *legend += " Dashed: loads $E_{" + to_latex(r.variable) + "}$ does not hold (" +
                       (r.motion == Motion::rotate
                            ? "through $O$, or their moment about $O$ square to $\\hat u$"
                            : "square to $\\hat u$") +
                       ").";
        if (!zero.empty()) *legend += " Zero at this configuration, drawn in its positive sense: " + zero + ".";
        if (!not_given.empty())
            *legend += " Value not given at this configuration, drawn in its positive sense: " + not_given + ".";
        if (!unplaced.empty())
            *legend += " Not drawn, acting where this configuration does not say: " + unplaced + ".";
    }
    return t;
}

// an equation's first lines kept in one box with its row's diagram: at most kKeptLines lines
// and kKeptChars characters of TeX (a diagram and about a fifth of a page), so the box never
// passes the page's foot; the further lines follow the box, free to break across pages, and an
// equation whose first line alone is longer follows the box with that line's start held to it
constexpr std::size_t kKeptChars = 1500;
constexpr std::size_t kKeptLines = 8;

// the road-map table in the seed's columns; the direction, the set and the unknowns wrap in
// their columns
std::string table_tex(const System& sys, const std::vector<RoadmapRow>& rows) {
    std::string t =
        "{\\small\\setlength{\\tabcolsep}{4pt}\\noindent\\begin{tabular}{@{}l l p{0.22\\linewidth} p{0.16\\linewidth} "
        "p{0.13\\linewidth} p{0.2\\linewidth}@{}}\n\\hline\nvariable & translate/rotate & direction & system $S$ "
        "& about point & additional unknowns \\\\\n\\hline\n";
    for (const RoadmapRow& r : rows) {
        std::string extra;
        for (std::size_t i = 0; i < r.additional_unknowns.size(); ++i)
            extra += (i ? ", " : "") + std::string("$") + to_latex(r.additional_unknowns[i]) + "$";
        const bool constraint = r.motion == Motion::constraint;
        t += "$" + to_latex(r.variable) + "$ & " + motion_word(r.motion) + " & " +
             (constraint ? "--" : "\\raggedright " + tex_text(direction_words(sys, r.direction))) +
             " & " + (constraint ? "--" : "\\raggedright $" + set_words(r.system) + "$") + " & " +
             (r.about ? "\\raggedright " + breakable_name(r.about->name()) : "--") + " & " +
             (extra.empty() ? "none" : "\\raggedright " + extra) + " \\tabularnewline\n";
    }
    return t + "\\hline\n\\end{tabular}}\n\n";
}

}  // namespace

std::string report_detail::tex_text(const std::string& s) {
    std::string o;
    for (char ch : s) {
        switch (ch) {
            case '_':
                o += "\\_";
                break;
            case '&':
                o += "\\&";
                break;
            case '%':
                o += "\\%";
                break;
            case '#':
                o += "\\#";
                break;
            case '$':
                o += "\\$";
                break;
            case '{':
                o += "\\{";
                break;
            case '}':
                o += "\\}";
                break;
            case '>':
                o += "\\textgreater{}";
                break;
            case '<':
                o += "\\textless{}";
                break;
            case '^':
                o += "\\textasciicircum{}";
                break;
            case '~':
                o += "\\textasciitilde{}";
                break;
            case '\\':
                o += "\\textbackslash{}";
                break;
            default:
                o += ch;
        }
    }
    return o;
}

std::string render_report_latex(const ReportContent& c) {
    return report_detail::render_latex(c, report_detail::typeset_equations(c));
}

namespace {

// text for LaTeX: û as $\hat u$, the en dash as --, the rest as tex_text writes it
std::string step_text(const std::string& s) {
    std::string t = tex_text(s);
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"\u00fb", "$\\hat u$"},
                                   {"\u2013", "--"}, {"\u2713", "$\\surd$"}, {"\u00b7", "$\\cdot$"}}) {
        for (std::size_t at = t.find(from); at != std::string::npos; at = t.find(from, at + to.size()))
            t.replace(at, from.size(), to);
    }
    return t;
}

// each row's derivation as an enumerated list, an appendix to the rows
std::string derivations_tex(const ReportContent& c, const std::vector<report_detail::RowSteps>& steps) {
    std::string t = "\\subsection*{Derivations, row by row}\\label{derivations}\nEach row's equation "
                    "formed step by step: the quantities it is formed from, then their projection on "
                    "$\\hat u$.\n\n";
    for (std::size_t i = 0; i < c.rows.size() && i < steps.size(); ++i) {
        t += "\\paragraph{Row " + std::to_string(i + 1) + ": $E_{" + to_latex(c.rows[i].variable) +
             "}$.}\n\\begin{enumerate}\n";
        for (const report_detail::DerivationStep& d : steps[i].steps) {
            t += "\\item \\textbf{" + step_text(d.label) + "}" + (d.text.empty() ? "" : ": " + step_text(d.text)) + ".\n";
            if (d.tex.empty()) continue;
            t += "\\begin{eqlines}\n";
            for (const std::string& line : report_detail::tex_lines(d.tex)) t += "\\eqline{" + line + "}\n";
            t += "\\end{eqlines}\n";
        }
        t += "\\end{enumerate}\n";
    }
    return t;
}

}  // namespace

std::string report_detail::render_latex(const ReportContent& c,
                                        const std::vector<std::string>& equations,
                                        const std::vector<RowSteps>* given_steps,
                                        const BruteForceCount* given_count) {
    if (!c.system)
        throw ArgumentError(
            "render_report_latex(): the report has no model; build one (newtonian N, ...) before "
            "report");
    const System& sys = *c.system;
    std::string t;
    t += "% Generated by Alembert from the model '" + c.title + "'; regenerate rather than edit.\n";
    t += "\\documentclass[a4paper]{article}\n\\usepackage{amsmath}\n\\usepackage[margin=2cm]{"
         "geometry}\n\\usepackage{tikz}\n";
    // pgfplots only where a result's sweep is plotted
    const bool sweep_plots =
        c.plot_histories &&
        std::any_of(c.results.begin(), c.results.end(),
                    [](const ReportResult& r) { return r.sweep && sweep_shown(*r.sweep); });
    if (sweep_plots) t += sweep_preamble();
    // an equation's lines: paragraphs of text-style math, ragged right, continued indented, so
    // that TeX breaks a long one after a + or - where the line is full
    t += "\\newenvironment{eqlines}{\\par\\smallskip\\raggedright}{\\par\\smallskip}\n"
         "\\newcommand{\\eqline}[1]{\\par\\noindent\\hangindent=3em\\hangafter=1 $#1$\\par}\n";
    t += "\\begin{document}\n\\section*{MG road-map of " + tex_text(c.title) + "}\n\n";
    for (const std::string& note : c.notes) t += tex_text(note) + "\n\n";
    if (c.rows.empty()) {
        t += "This model has no MG road-map rows, so there is no table, free-body diagram or row "
             "equation to show" +
             std::string(c.notes.empty() ? ": the script formed none (no \\texttt{roadmap} or "
                                           "\\texttt{plan} was run on it)"
                                         : "") +
             ".\n\n";
    } else {
        t += "Each row's equation is $E = \\text{applied} - \\text{inertial} = 0$, shown solved for "
             "the row's unknown where it holds it linearly with a constant coefficient, else as "
             "$0 = E$; accelerations are collected. The free-body diagram of $S$ lists the loads "
             "external to $S$.\n\n";
        t += table_tex(sys, c.rows);
        const std::string bf = brute_force_words(given_count ? *given_count : calc_brute_force_count(c), c.rows.size());
        if (!bf.empty()) t += step_text(bf) + "\n\n";
        t += "\\subsection*{Rows: free-body diagrams and equations}\n";
        t += "Unknown loads in red, known in blue, gravity in green; $O$ is the about point and "
             "$\\hat u$ the direction. Drawn at " +
             tex_text(configuration_words(c)) + ".\n\n";
    }
    Evaluation ev(sys, c.configuration);
    const std::vector<const Point*> placed = placed_points(sys, &ev);
    bool planar = true;
    (void)geometry_json(sys, ev, placed, &planar);
    int figure = 0;
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        const RoadmapRow& r = c.rows[i];
        const std::vector<std::string> lines = tex_lines(equations.at(i));
        const std::string name = "E_{" + to_latex(r.variable) + "}\\colon\\ ";
        // the diagram, its caption and the equation's first lines in one unbreakable box (no
        // float to drift from them); lines past kKeptLines or kKeptChars follow it, free to
        // break across pages
        std::size_t kept = 0, chars = 0;
        while (kept < lines.size() && kept < kKeptLines && chars + lines[kept].size() <= kKeptChars)
            chars += lines[kept++].size();
        t += "\\par\\bigskip\\noindent\\begin{minipage}{\\linewidth}\n";
        if (r.motion == Motion::constraint) {
            t += "\\paragraph{Row " + std::to_string(i + 1) + ": $" + to_latex(r.variable) +
                 "$ from constraint " + tex_text(r.constraint) + ".}\n";
        } else {
            t += "\\paragraph{Row " + std::to_string(i + 1) + ": $S = " + set_words(r.system) +
                 "$ for $" + to_latex(r.variable) + "$.}";
            for (std::size_t k = 0; k < r.fbd.size(); ++k)
                t += (k ? "; " : " ") + tex_text(r.fbd[k]);
            std::string legend;
            const std::string picture = tikz_diagram(sys, ev, placed, planar, r, &legend);
            t += ".\n\n\\begin{center}\n" + picture + "\\par\\smallskip\\small Figure " +
                 std::to_string(++figure) + ": free-body diagram of $S = " + set_words(r.system) +
                 "$ for $" + to_latex(r.variable) + "$." + legend + "\n\\end{center}\n";
        }
        if (kept > 0) {
            t += "\\begin{eqlines}\n";
            for (std::size_t k = 0; k < kept; ++k)
                t += "\\eqline{" + (k ? std::string() : name) + lines[k] + "}\n";
            t += "\\end{eqlines}\n";
        }
        t += "\\end{minipage}\n";
        if (kept < lines.size()) {
            // with nothing of it in the box: no page break between the box and the equation's
            // start, nor after each line's first printed line
            t += kept > 0 ? "\\begin{eqlines}\n" : "\\par\\nobreak\n\\begin{eqlines}\\clubpenalty=10000\n";
            for (std::size_t k = kept; k < lines.size(); ++k)
                t += "\\eqline{" + (k ? std::string() : name) + lines[k] + "}\n";
            t += "\\end{eqlines}\n";
        }
        if (i < c.unit_checks.size()) {
            const ReportUnitCheck& u = c.unit_checks[i];
            // a paragraph of its own, ragged right: the terms that are off, each unbroken
            // (-m_T*sin(hip_flexion_r + knee_angle_r)*(...), break between them
            t += "\\par{\\raggedright\\noindent\\small " + step_text(u.summary) +
                 (u.verdict == ReportUnitCheck::Verdict::consistent ? " $\\surd$"
                  : u.verdict == ReportUnitCheck::Verdict::inconsistent ? " $\\times$" : "") +
                 "\\par}\n\n";
        }
    }
    const std::vector<RowSteps> formed_steps =
        given_steps ? std::vector<RowSteps>{} : calc_rows_steps(c, equations);
    const std::vector<RowSteps>& steps = given_steps ? *given_steps : formed_steps;
    if (!c.rows.empty()) t += derivations_tex(c, steps);
    // the intermediates the equations and derivations name, once for all of them
    const PageIntermediates zs = page_intermediates(sys, c.rows, &steps);
    if (!zs.tex.empty()) {
        t += "\\subsection*{Intermediates}\nThe equations use\n\\begin{eqlines}\n";
        for (const std::string& d : zs.tex) t += "\\eqline{" + d + "}\n";
        t += "\\end{eqlines}\n";
    }
    if (c.matrices) {
        t += "\\subsection*{Mass matrix and forcing}\n$M(q)\\,\\ddot q = f(q, \\dot q, t)$:\n"
             "\\begin{eqlines}\n";
        for (const std::string& line : tex_lines(matrices_tex(sys.symbols(), *c.matrices)))
            t += "\\eqline{" + line + "}\n";
        t += "\\end{eqlines}\n";
    }
    // the equations kane and lagrange formed, typeset after the rows'
    std::size_t next = c.rows.size();
    for (const ReportEquationSet& set : c.equation_sets) {
        t += "\\subsection*{" + tex_text(set.method) + ": " + tex_text(set.name) + " (line " +
             std::to_string(set.line) + ")}\n\\begin{eqlines}\n";
        for (std::size_t k = 0; k < set.equations.size(); ++k) {
            const std::vector<std::string> lines = tex_lines(equations.at(next++));
            for (std::size_t j = 0; j < lines.size(); ++j)
                t += "\\eqline{" +
                     (j ? std::string()
                        : "\\mathrm{" + tex_text(set.name) + "}[" + std::to_string(k + 1) + "]\\colon\\ ") +
                     lines[j] + "}\n";
        }
        t += "\\end{eqlines}\n";
    }
    if (!c.results.empty()) {
        t += "\\subsection*{Results}\n";
        for (const ReportResult& r : c.results) {
            t += "Line " + std::to_string(r.line) + ":\n\\begin{verbatim}\n" +
                 verbatim_lines("> " + r.statement + "\n" + r.text) + "\\end{verbatim}\n";
            // a sweep's values under its text: plotted against the swept value, and tabulated
            if (r.sweep) t += sweep_latex(*r.sweep, c.plot_histories, &figure);
        }
    }
    t += "\\end{document}\n";
    return t;
}

}  // namespace alembert
