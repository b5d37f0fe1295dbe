// SPDX-License-Identifier: MIT
// One interface over the integration methods: adaptive steps with dense output inside the last.
#pragma once

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "alembert/sim/integrator.hpp"

namespace alembert::detail {

using OdeState = std::vector<double>;
/// x' = f(x, t), written into dxdt (sized like x).
using OdeRhs = std::function<void(const OdeState& x, OdeState& dxdt, double t)>;

/// An adaptive integrator with dense output, the way simulate drives it: initialize, then
/// do_step until current_time() reaches the end, reading states inside the last step with
/// calc_state. What f throws passes through do_step unchanged.
class DenseStepper {
public:
    virtual ~DenseStepper() = default;
    /// Starts at x(t0) = x; `dt` is the first step tried (a method may pick its own), and no
    /// step goes past `t_stop` for methods that can stop there (bdf); the others may overshoot.
    virtual void initialize(const OdeState& x, double t0, double dt, double t_stop) = 0;
    /// One accepted step; returns (t_before, t_after).
    virtual std::pair<double, double> do_step() = 0;
    /// The state at t within the last step [t_before, t_after].
    virtual void calc_state(double t, OdeState& x) = 0;
    virtual double current_time() const = 0;
    virtual const OdeState& current_state() const = 0;
    /// True if the method stops by itself when its steps shrink to nothing (CVODE: repeated
    /// error-test failures at its smallest step); else the caller checks the step size.
    virtual bool guards_step_size() const { return false; }
};

/// A stepper of `method` on f under tolerances abs_tol, rel_tol.
/// @throws alembert::ArgumentError if bdf is asked for and the build has no SUNDIALS.
std::unique_ptr<DenseStepper> make_dense_stepper(Integrator method, double abs_tol,
                                                 double rel_tol, OdeRhs f);

/// The CVODE BDF stepper (cvode_stepper.cpp).
/// @throws alembert::ArgumentError, saying how to get SUNDIALS, in a build without it.
std::unique_ptr<DenseStepper> make_cvode_bdf_stepper(double abs_tol, double rel_tol, OdeRhs f);

/// Whether this build has SUNDIALS CVODE (the bdf integrator).
bool have_cvode();

}  // namespace alembert::detail
