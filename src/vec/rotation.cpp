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

Mat3 simple_rotation(Axis axis, const ex& angle) {
    ex c = GiNaC::cos(angle), s = GiNaC::sin(angle);
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
