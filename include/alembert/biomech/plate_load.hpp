// SPDX-License-Identifier: MIT
// Force-plate records as the values of a model's data symbols, fed to its compiled equations.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "alembert/biomech/force_plate.hpp"
#include "alembert/biomech/segment_angles.hpp"
#include "alembert/sim/numeric_function.hpp"

namespace alembert {

/// The symbols of a model that a plate's record gives values to, in the model's Newtonian
/// frame: the force F = Fx Nx> + Fy Ny> on the body (N), applied at its centre of pressure
/// p_NoCoP = px Nx> + py Ny> (m), and the free moment Tz Nz> (N m).
struct PlateSymbols {
    ex Fx{}, Fy{}, px{}, py{}, Tz{};
};

/// Plate records as functions of time for a model's plate symbols. In the plane `plane` of
/// the lab (SagittalPlane: horizontal to Nx>, vertical to Ny>, h x v to Nz>), the force and the
/// centre of pressure are the record's components along h and v, the free moment its component
/// about h x v; the centre of pressure is taken from the lab's origin to the model's N_o by
/// set_origin. Between samples the values are interpolated linearly; at a sample out of contact
/// (ForcePlate::in_contact: force below the threshold) the force and moment are zero and the
/// centre of pressure (noise over a small force) is not used.
class PlateInputs {
public:
    /// Adds a plate and the model's symbols it gives values to.
    /// @throws alembert::ArgumentError if the record has fewer than 2 samples or its times do
    ///         not increase.
    void add(const ForcePlate& plate, const PlateSymbols& symbols, SagittalPlane plane = {});
    /// Where the model's origin N_o is in the lab (horizontal, vertical), m.
    void set_origin(double h, double v) { origin_h_ = h, origin_v_ = v; }
    /// The symbols, five per plate in the order added: Fx, Fy, px, py, Tz.
    const std::vector<ex>& symbols() const { return symbols_; }
    /// The symbols' values at time t (symbols().size() values).
    /// @throws alembert::ArgumentError naming the plate if t is outside its record.
    void calc_values(double t, double* values) const;
    /// Number of plates.
    std::size_t size() const { return plates_.size(); }

private:
    struct Channel {
        std::string name;
        std::vector<double> t;
        std::vector<double> v[5];  // Fx, Fy, px, py, Tz per sample, zero out of contact
    };
    std::vector<Channel> plates_;
    std::vector<ex> symbols_;
    double origin_h_ = 0, origin_v_ = 0;
};

/// A FunctionMaker whose functions take the plates' symbols from `plates` at the time that is
/// their first input (inverse dynamics: [t, q, q', q'']), so equations holding plate loads
/// compile and evaluate as if the plates were part of the model: `make` (empty: the tape)
/// compiles outputs of inputs + plates->symbols(), and each call appends the plates' values at
/// inputs[0].
FunctionMaker with_plate_inputs(FunctionMaker make, std::shared_ptr<const PlateInputs> plates);

}  // namespace alembert
