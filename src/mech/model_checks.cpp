// SPDX-License-Identifier: MIT
// Physical checks of what a user states: rotation matrices, masses and inertias.
#include "alembert/mech/model_checks.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

#include "alembert/error.hpp"

namespace alembert {

namespace {

std::string format_check_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// true if every symbol of e has a value: constants with values, nothing time-varying
bool evaluable_at_constants(const SymbolTable& st, const ex& e) {
    for (const ex& s : symbols_of(e)) {
        if (!st.owns(s)) return false;
        SymbolKind k = st.kind(s);
        if (k == SymbolKind::intermediate) {
            if (!evaluable_at_constants(st, st.definition(s))) return false;
        } else if (k != SymbolKind::constant || !st.value(s)) {
            return false;
        }
    }
    return true;
}

// the numeric 3x3 matrix, or nothing when an entry cannot be evaluated at the constants
std::optional<Eigen::Matrix3d> matrix_at_constants(const SymbolTable& st, const Mat3& M) {
    Eigen::Matrix3d out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            if (!evaluable_at_constants(st, M(i, j))) return std::nullopt;
            out(i, j) = st.evaluate(M(i, j));
        }
    return out;
}

// the leaf symbols of e without a value: time-varying ones and constants without a value,
// looking through intermediates to their definitions
void collect_free_symbols(const SymbolTable& st, const ex& e, GiNaC::exset& out) {
    for (const ex& s : st.calc_leaf_symbols(e))
        if (!(st.owns(s) && st.kind(s) == SymbolKind::constant && st.value(s))) out.insert(s);
}

}  // namespace

void check_direction_cosines(const SymbolTable& st, const Mat3& R_PB, const std::string& frame,
                             const std::string& parent) {
    // the free symbols other than valued constants get values from a fixed seed
    GiNaC::exset free;
    for (const ex& e : R_PB.m) collect_free_symbols(st, e, free);
    std::vector<ex> names(free.begin(), free.end());
    std::sort(names.begin(), names.end(), [&](const ex& a, const ex& b) {
        auto name = [&](const ex& s) {
            return st.owns(s) ? st.name(s) : GiNaC::ex_to<GiNaC::symbol>(s).get_name();
        };
        return name(a) < name(b);
    });
    std::mt19937 random(20261124);
    std::uniform_real_distribution<double> value(-1.5, 1.5);
    for (int trial = 0; trial < 3; ++trial) {
        exmap at;
        std::string state;
        for (const ex& s : names) {
            double v = value(random);
            at[s] = v;
            if (state.size() < 120)
                state += (state.empty() ? "" : ", ") +
                         (st.owns(s) ? st.name(s) : GiNaC::ex_to<GiNaC::symbol>(s).get_name()) +
                         " = " + format_check_number(v);
        }
        Eigen::Matrix3d R;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) R(i, j) = st.evaluate(R_PB(i, j), at);
        const double orthogonality = (R * R.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
        const double det = R.determinant();
        const std::string where = state.empty() ? "" : " (at " + state + ")";
        if (orthogonality > kModelCheckTolerance)
            throw ModelError("the direction-cosine matrix of '" + frame + "' in '" + parent +
                             "' is not orthonormal: R R^T differs from the unit matrix by " +
                             format_check_number(orthogonality) + where +
                             "; each row and column must be a unit vector, perpendicular to the "
                             "others");
        if (det < 0)
            throw ModelError("the direction-cosine matrix of '" + frame + "' in '" + parent +
                             "' has determinant " + format_check_number(det) + where +
                             ": it is a reflection, not a rotation; change the sign of one row "
                             "or column so the frame stays right-handed");
    }
}

void check_mass(const SymbolTable& st, const ex& mass, const std::string& body) {
    if (!evaluable_at_constants(st, mass)) return;
    const double m = st.evaluate(mass);
    if (m < 0)
        throw ModelError("the mass of '" + body + "' is " + format_check_number(m) +
                         " kg; a mass cannot be negative: check the sign of its value");
}

void check_inertia_matrix(const SymbolTable& st, const Mat3& I, const std::string& body) {
    std::optional<Eigen::Matrix3d> J = matrix_at_constants(st, I);
    if (!J) return;
    const double scale = std::max(J->cwiseAbs().maxCoeff(), 1e-300);
    const double tol = kModelCheckTolerance * scale;
    if ((*J - J->transpose()).cwiseAbs().maxCoeff() > tol)
        throw ModelError("the inertia matrix of '" + body + "' is not symmetric; give each "
                         "product of inertia once (Ixy, Iyz, Izx)");
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(*J, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d p = eig.eigenvalues();  // ascending
    const std::string moments = format_check_number(p(0)) + ", " + format_check_number(p(1)) +
                                ", " + format_check_number(p(2)) + " kg*m^2";
    if (p(0) < -tol)
        throw ModelError("the inertia of '" + body + "' has a negative principal moment "
                         "(principal moments " + moments +
                         "); moments of inertia are sums of m r^2: check the signs of the "
                         "moments and the size of the products of inertia");
    // a moment written as 0 is the planar convention (inertia A = 0, 0, I_A: only the moment
    // about the plane's normal matters), not a claim about the body: no triangle check then
    const bool planar = I(0, 0).is_zero() || I(1, 1).is_zero() || I(2, 2).is_zero();
    if (!planar && p(0) + p(1) < p(2) - tol)
        throw ModelError("the inertia of '" + body + "' is not physical: its principal "
                         "moments " + moments + " break the triangle inequality I1 + I2 >= I3 "
                         "that every mass distribution satisfies; check the moments (a thin "
                         "rod has 0, I, I; a thin disk I, I, 2 I)");
}

}  // namespace alembert
