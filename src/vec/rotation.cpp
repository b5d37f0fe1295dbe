// SPDX-License-Identifier: MIT
// Simple rotation matrices and rotation-sequence names.
#include "alembert/vec/rotation.hpp"

#include <cctype>

#include "alembert/error.hpp"

namespace alembert {

namespace {
constexpr const char* kNames[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX",
                                  "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};
}

RotationSequence parse_rotation_sequence(const std::string& text) {
    std::string up;
    for (char c : text) up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (int i = 0; i < 12; ++i)
        if (up == kNames[i]) return static_cast<RotationSequence>(i);
    std::string all;
    for (const char* n : kNames) all += std::string(all.empty() ? "" : ", ") + n;
    throw ArgumentError("parse_rotation_sequence(): '" + text +
                        "' is not a rotation sequence; use one of " + all);
}

std::string to_string(RotationSequence seq) { return kNames[static_cast<int>(seq)]; }

std::array<Axis, 3> axes_of(RotationSequence seq) {
    std::string n = kNames[static_cast<int>(seq)];
    std::array<Axis, 3> out{};
    for (int i = 0; i < 3; ++i) out[static_cast<std::size_t>(i)] = static_cast<Axis>(n[static_cast<std::size_t>(i)] - 'X');
    return out;
}

namespace {
// true if a numeric coefficient leads `e` with a minus sign (-q, -2 q, -q r)
bool negative_term(const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e).is_negative();
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        const ex& c = e.op(e.nops() - 1);  // GiNaC keeps a mul's numeric coefficient last
        return GiNaC::is_a<GiNaC::numeric>(c) && GiNaC::ex_to<GiNaC::numeric>(c).is_negative();
    }
    return false;
}

// true if -a reads better than a: more of a's terms are negative (ties: a deterministic
// choice between the two), so cos(-qB) and cos(qB) meet as one function
bool prefer_negated(const ex& a) {
    if (!GiNaC::is_a<GiNaC::add>(a)) return negative_term(a);
    std::size_t neg = 0, n = a.nops();
    for (std::size_t i = 0; i < n; ++i) neg += negative_term(a.op(i)) ? 1 : 0;
    if (2 * neg != n) return 2 * neg > n;
    return GiNaC::ex_is_less()(-a, a);
}
}  // namespace

Mat3 simple_rotation(Axis axis, const ex& angle) {
    // cos is even and sin odd: write both with the better-reading sign of the angle
    bool flip = prefer_negated(angle);
    ex a = flip ? ex(-angle) : angle;
    ex c = GiNaC::cos(a), s = flip ? ex(-GiNaC::sin(a)) : ex(GiNaC::sin(a));
    Mat3 r;
    switch (axis) {
        case Axis::x:
            r(0, 0) = 1;
            r(1, 1) = c, r(1, 2) = -s;
            r(2, 1) = s, r(2, 2) = c;
            break;
        case Axis::y:
            r(1, 1) = 1;
            r(0, 0) = c, r(0, 2) = s;
            r(2, 0) = -s, r(2, 2) = c;
            break;
        case Axis::z:
            r(2, 2) = 1;
            r(0, 0) = c, r(0, 1) = -s;
            r(1, 0) = s, r(1, 1) = c;
            break;
    }
    return r;
}

}  // namespace alembert
