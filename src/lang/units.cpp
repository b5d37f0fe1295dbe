// SPDX-License-Identifier: MIT
// The unit table and dimension arithmetic.
#include "alembert/lang/units.hpp"

#include <cmath>
#include <numbers>

namespace alembert::lang {

namespace {

struct Entry {
    const char* name;
    double scale;
    Dimension dim;
};

const Entry kUnits[] = {
    {"m", 1, Dimension::length()},      {"cm", 0.01, Dimension::length()},
    {"mm", 0.001, Dimension::length()}, {"km", 1000, Dimension::length()},
    {"kg", 1, Dimension::mass()},       {"g", 0.001, Dimension::mass()},
    {"s", 1, Dimension::time()},        {"ms", 0.001, Dimension::time()},
    {"min", 60, Dimension::time()},     {"h", 3600, Dimension::time()},
    {"rad", 1, Dimension::none()},      {"deg", std::numbers::pi / 180, Dimension::none()},
    {"rev", 2 * std::numbers::pi, Dimension::none()},
    {"N", 1, Dimension::force()},       {"kN", 1000, Dimension::force()},
    {"J", 1, Dimension::torque()},      {"W", 1, {{2, 1, -3}, true}},
    // rates of rotation count revolutions: 1 Hz = 1 rev/s = 2*pi rad/s, as 60 rpm
    {"Hz", 2 * std::numbers::pi, {{0, 0, -1}, true}},
    {"rpm", 2 * std::numbers::pi / 60, {{0, 0, -1}, true}},
    // US customary units, exact by their definitions (NIST SP 811): the international inch
    // and foot, the avoirdupois pound mass, the pound force (lbm times standard gravity
    // 9.80665 m/s^2) and the slug (lbf*s^2/ft)
    {"in", 0.0254, Dimension::length()},  {"ft", 0.3048, Dimension::length()},
    {"lbm", 0.45359237, Dimension::mass()},
    {"lbf", 0.45359237 * 9.80665, Dimension::force()},
    {"slug", 0.45359237 * 9.80665 / 0.3048, Dimension::mass()},
};

}  // namespace

Dimension operator*(const Dimension& a, const Dimension& b) {
    if (!a.known || !b.known) return Dimension::open();
    Dimension r;
    for (std::size_t i = 0; i < 3; ++i) r.exponent[i] = a.exponent[i] + b.exponent[i];
    return r;
}

Dimension operator/(const Dimension& a, const Dimension& b) {
    if (!a.known || !b.known) return Dimension::open();
    Dimension r;
    for (std::size_t i = 0; i < 3; ++i) r.exponent[i] = a.exponent[i] - b.exponent[i];
    return r;
}

Dimension pow(const Dimension& a, int n) {
    if (!a.known) return a;
    Dimension r;
    for (std::size_t i = 0; i < 3; ++i) r.exponent[i] = a.exponent[i] * n;
    return r;
}

std::string si_unit(const Dimension& d) {
    if (!d.known || d.is_none()) return "";
    const auto& e = d.exponent;
    if (d == Dimension::force()) return "N";
    if (d == Dimension::torque()) return "N*m";
    std::string num, den;
    auto add = [](std::string& s, const char* u, int p) {
        if (p == 0) return;
        if (!s.empty()) s += "*";
        s += u;
        if (p != 1) s += "^" + std::to_string(p);
    };
    const char* names[3] = {"m", "kg", "s"};
    // mass first, as in kg*m^2
    for (std::size_t i : {1u, 0u, 2u}) {
        if (e[i] > 0) add(num, names[i], e[i]);
        if (e[i] < 0) add(den, names[i], -e[i]);
    }
    if (num.empty()) num = "1";
    return den.empty() ? num : num + "/" + (den.find('*') != std::string::npos ? "(" + den + ")" : den);
}

std::string describe(const Dimension& d) {
    if (!d.known) return "of open dimension";
    if (d.is_none()) return "an angle or a number";
    struct Named {
        Dimension d;
        const char* name;
    };
    static const Named named[] = {
        {Dimension::length(), "a length"},     {Dimension::mass(), "a mass"},
        {Dimension::time(), "a time"},         {Dimension::force(), "a force"},
        {Dimension::torque(), "a torque or an energy"},
        {{{1, 0, -1}, true}, "a velocity"},    {{{1, 0, -2}, true}, "an acceleration"},
        {{{0, 0, -1}, true}, "an angular velocity"},
        {{{0, 0, -2}, true}, "an angular acceleration"},
        {{{2, 1, 0}, true}, "a moment of inertia"},
    };
    for (const auto& n : named)
        if (n.d == d) return std::string(n.name) + " (" + si_unit(d) + ")";
    return "in " + si_unit(d);
}

std::optional<Unit> find_unit(std::string_view name) {
    for (const Entry& e : kUnits)
        if (name == e.name) return Unit{e.scale, e.dim, e.name};
    return std::nullopt;
}

std::string known_units() {
    std::string s;
    for (const Entry& e : kUnits) s += (s.empty() ? "" : " ") + std::string(e.name);
    return s;
}

Unit parse_unit(const UnitText& text) {
    Unit u;
    for (std::size_t i = 0; i < text.factors.size(); ++i) {
        const auto& f = text.factors[i];
        std::optional<Unit> one = find_unit(f.name.text);
        if (!one)
            throw ScriptError(f.name.location, "unknown unit '" + f.name.text + "'",
                              "known units: " + known_units() + " (combine them with * / ^)");
        u.scale *= std::pow(one->scale, f.power);
        u.dimension = u.dimension * pow(one->dimension, f.power);
        // the text as written: a/b^2 prints as written, with '/' before the first negative power
        int p = f.power;
        std::string piece = f.name.text;
        if (std::abs(p) != 1) piece += "^" + std::to_string(std::abs(p));
        if (i == 0) u.text = p < 0 ? "1/" + piece : piece;
        else u.text += (p < 0 ? "/" : "*") + piece;
    }
    return u;
}

}  // namespace alembert::lang
