// SPDX-License-Identifier: MIT
// Inertia dyadics from moments and products, and the parallel-axis transfer.
#pragma once

#include "alembert/vec/dyadic.hpp"

namespace alembert {

/// The inertia dyadic sum_ij I_ij B_i> B_j> from its matrix in frame B. The products are the
/// matrix elements (Ixy = Bx>.I.By>, which is -sum m x y for a set of particles), as in
/// Kane & Levinson 1985, sec. 3.3.
Dyadic inertia_dyadic(const Frame& B, const ex& Ixx, const ex& Iyy, const ex& Izz,
                      const ex& Ixy = 0, const ex& Iyz = 0, const ex& Izx = 0);

/// The inertia about O of a mass m at position r from O: m ((r.r) U - r r)
/// (the parallel-axis term, Kane 1985, eq. 3.8.8). U is written in `U_frame`.
Dyadic point_mass_inertia(const ex& m, const Vector& r, const Frame& U_frame);

}  // namespace alembert
