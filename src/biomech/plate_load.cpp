// SPDX-License-Identifier: MIT
// Force-plate records interpolated in time for the plate symbols of a model's equations.
#include "alembert/biomech/plate_load.hpp"

#include <algorithm>

#include "alembert/error.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

void PlateInputs::add(const ForcePlate& plate, const PlateSymbols& s, SagittalPlane plane) {
    const std::size_t n = plate.t.size();
    if (n < 2)
        throw ArgumentError("PlateInputs::add(): plate '" + plate.name + "' has " +
                            std::to_string(n) + " sample(s); a record needs at least 2");
    for (std::size_t k = 1; k < n; ++k)
        if (!(plate.t[k] > plate.t[k - 1]))
            throw ArgumentError("PlateInputs::add(): plate '" + plate.name + "': the time " +
                                format_csv_number(plate.t[k]) + " s does not follow " +
                                format_csv_number(plate.t[k - 1]) + " s; times must increase");
    const int h = plane.horizontal, v = plane.vertical, z = 3 - h - v;
    // the moment about h x v: + for (h, v) in cyclic order (x, y), (y, z), (z, x), else -
    const double sense = ((v - h + 3) % 3 == 1) ? 1.0 : -1.0;
    Channel c{plate.name, plate.t, {}};
    for (std::size_t k = 0; k < n; ++k) {
        const bool on = plate.in_contact(k);
        c.v[0].push_back(on ? plate.F[h][k] : 0.0);
        c.v[1].push_back(on ? plate.F[v][k] : 0.0);
        c.v[2].push_back(on ? plate.p_CoP[h][k] : 0.0);
        c.v[3].push_back(on ? plate.p_CoP[v][k] : 0.0);
        c.v[4].push_back(on ? sense * plate.T_free[z][k] : 0.0);
    }
    // a centre of pressure out of contact takes its neighbour's in contact, so interpolation
    // towards a contact does not drag it from the lab's origin (the force is zero there anyway)
    for (int axis : {2, 3}) {
        std::vector<double>& p = c.v[axis];
        for (std::size_t k = 1; k < n; ++k)
            if (!plate.in_contact(k) && plate.in_contact(k - 1)) p[k] = p[k - 1];
        for (std::size_t k = n - 1; k-- > 0;)
            if (!plate.in_contact(k) && plate.in_contact(k + 1)) p[k] = p[k + 1];
    }
    plates_.push_back(std::move(c));
    for (const ex& x : {s.Fx, s.Fy, s.px, s.py, s.Tz}) symbols_.push_back(x);
}

void PlateInputs::calc_values(double t, double* values) const {
    for (std::size_t i = 0; i < plates_.size(); ++i) {
        const Channel& c = plates_[i];
        // the samples around t, linear weights
        if (t < c.t.front() - 1e-9 || t > c.t.back() + 1e-9)
            throw ArgumentError(
                "plate '" + c.name + "': its record covers t = " + format_csv_number(c.t.front()) +
                " to " + format_csv_number(c.t.back()) + " s, not t = " + format_csv_number(t) +
                " s; record the plates over the whole trial, or trim the motion to the record");
        const auto hi = std::upper_bound(c.t.begin(), c.t.end(), t);
        std::size_t k1 = static_cast<std::size_t>(hi - c.t.begin());
        k1 = std::clamp<std::size_t>(k1, 1, c.t.size() - 1);
        const std::size_t k0 = k1 - 1;
        const double w = std::clamp((t - c.t[k0]) / (c.t[k1] - c.t[k0]), 0.0, 1.0);
        double* out = values + 5 * i;
        for (int j = 0; j < 5; ++j) out[j] = (1 - w) * c.v[j][k0] + w * c.v[j][k1];
        out[2] -= origin_h_;
        out[3] -= origin_v_;
    }
}

FunctionMaker with_plate_inputs(FunctionMaker make, std::shared_ptr<const PlateInputs> plates) {
    return [make = std::move(make), plates](const SymbolTable& table, const std::vector<ex>& inputs,
                                            const std::vector<ex>& outputs) {
        std::vector<ex> all = inputs;
        all.insert(all.end(), plates->symbols().begin(), plates->symbols().end());
        NumericFunction inner = make_numeric_function(table, all, outputs, make);
        NumericFunction f = inner;
        f.input_count = inputs.size();
        const std::size_t n = inputs.size();
        auto buffer = std::make_shared<std::vector<double>>(all.size());
        f.evaluate = [inner, plates, n, buffer](const double* x, double* y) {
            std::copy(x, x + n, buffer->begin());
            plates->calc_values(x[0], buffer->data() + n);
            inner.evaluate(buffer->data(), y);
        };
        return f;
    };
}

}  // namespace alembert
