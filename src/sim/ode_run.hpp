// SPDX-License-Identifier: MIT
// One simulation run over a first-order state: steps, output rows, events, progress.
#pragma once

#include <functional>
#include <string>

#include "alembert/sim/simulation.hpp"
#include "dense_stepper.hpp"

namespace alembert::detail {

/// The inputs of the output and event functions at (t, x): [t, q, q', unknowns, inputs] in the
/// layout they were compiled for. The pointer stays valid until the next call.
using OdeGather = std::function<const double*(double t, const OdeState& x)>;

/// Integrates x' = rhs(x, t) from x0 at options.t_initial to options.t_final as `simulate`
/// documents it: the output rows at the requested times, the events located by bisection, the
/// progress line, the step limit. `model` names the run in messages; x_end receives the state
/// at the end (the event time when an event stopped the run). The result's q_end and qd_end
/// are left empty for the caller.
/// @throws as simulate.
SimulationResult integrate_with_outputs(const std::string& model, const OdeState& x0,
                                        const OdeRhs& rhs, const OdeGather& gather,
                                        const SimulationOptions& options,
                                        const OutputFunction& outputs, const EventFunction& events,
                                        const std::function<void(const Table&, std::size_t)>& check_row,
                                        OdeState& x_end);

}  // namespace alembert::detail
