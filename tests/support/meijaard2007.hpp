// SPDX-License-Identifier: MIT
// Published reference values of the Whipple bicycle benchmark: J. P. Meijaard, J. M. Papadopoulos,
// A. Ruina and A. L. Schwab (2007), "Linearized dynamics equations for the balance and steer of
// a bicycle: a benchmark and review", Proc. R. Soc. A 463, 1955-1982.
#pragma once

#include <complex>

namespace alembert::test {

/// A row of Table 2: the eigenvalues of the benchmark bicycle at forward speed v (14 decimals as
/// published; the same values are transcribed in D. L. Peterson's gyrostat bicycle tests and in
/// SymPy's bicycle example). At v = 0 the four are real; above, a real capsize eigenvalue, a
/// complex weave pair and a real castering one.
struct MeijaardTable2Row {
    double v;
    std::complex<double> eig[4];
};

inline const MeijaardTable2Row kMeijaardTable2[] = {
    {0, {{-5.53094371765393, 0}, {-3.13164324790656, 0}, {3.13164324790656, 0},
         {5.53094371765393, 0}}},
    {1, {{-3.13423125066578, 0}, {3.52696170990070, -0.80774027519930},
         {3.52696170990070, 0.80774027519930}, {-7.11008014637442, 0}}},
    {2, {{-3.07158645641514, 0}, {2.68234517512745, -1.68066296590675},
         {2.68234517512745, 1.68066296590675}, {-8.67387984831735, 0}}},
    {3, {{-2.63366137253667, 0}, {1.70675605663975, -2.31582447384325},
         {1.70675605663975, 2.31582447384325}, {-10.35101467245920, 0}}},
    {4, {{-1.42944427361326, 0}, {0.41325331521125, -3.07910818603206},
         {0.41325331521125, 3.07910818603206}, {-12.15861426576450, 0}}},
    {5, {{-0.32286642900409, 0}, {-0.77534188219585, -4.46486771378823},
         {-0.77534188219585, 4.46486771378823}, {-14.07838969279820, 0}}},
    {6, {{-0.00406690076970, 0}, {-1.52644486584142, -5.87673060598709},
         {-1.52644486584142, 5.87673060598709}, {-16.08537123098030, 0}}},
    {7, {{0.10268170574766, 0}, {-2.13875644258362, -7.19525913329805},
         {-2.13875644258362, 7.19525913329805}, {-18.15788466125262, 0}}},
    {8, {{0.14327879765713, 0}, {-2.69348683581097, -8.46037971396931},
         {-2.69348683581097, 8.46037971396931}, {-20.27940894394569, 0}}},
    {9, {{0.15790184030917, 0}, {-3.21675402252485, -9.69377351531791},
         {-3.21675402252485, 9.69377351531791}, {-22.43788559040858, 0}}},
    {10, {{0.16105338653172, 0}, {-3.72016840437287, -10.90681139476287},
          {-3.72016840437287, 10.90681139476287}, {-24.62459635017404, 0}}},
};

/// Table 2(a): the weave and capsize speeds (m/s), where the weave pair and the capsize
/// eigenvalue cross the imaginary axis.
constexpr double kMeijaardWeaveSpeed = 4.29238253634111, kMeijaardCapsizeSpeed = 6.02426201538837;

}  // namespace alembert::test
