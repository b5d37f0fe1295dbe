// SPDX-License-Identifier: MIT
// Integration methods by name; the Boost.Odeint steppers behind one dense-output interface.
#include "alembert/sim/integrator.hpp"

#include <boost/numeric/odeint.hpp>
#include <cmath>

#include "alembert/error.hpp"
#include "dense_stepper.hpp"

namespace alembert {

const std::vector<std::string>& integrator_names() {
    static const std::vector<std::string> names{"dopri5", "rkf78", "bulirsch_stoer", "bdf"};
    return names;
}

std::string_view to_string(Integrator method) {
    return integrator_names()[static_cast<std::size_t>(method)];
}

Integrator parse_integrator(std::string_view name) {
    const std::vector<std::string>& names = integrator_names();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (name == names[i]) return static_cast<Integrator>(i);
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) list += (i ? ", " : "") + names[i];
    throw ArgumentError("parse_integrator(): there is no integrator named '" + std::string(name) +
                        "'; choose one of " + list);
}

bool integrator_available(Integrator method) {
    return method != Integrator::bdf || detail::have_cvode();
}

namespace detail {

namespace {

namespace odeint = boost::numeric::odeint;

// Dormand-Prince and Bulirsch-Stoer: odeint's own dense-output steppers
template <class Stepper>
class OdeintDense final : public DenseStepper {
public:
    OdeintDense(Stepper s, OdeRhs f) : stepper_(std::move(s)), f_(std::move(f)) {}
    void initialize(const OdeState& x, double t0, double dt, double) override {
        stepper_.initialize(x, t0, dt);
    }
    std::pair<double, double> do_step() override { return stepper_.do_step(std::ref(f_)); }
    void calc_state(double t, OdeState& x) override { stepper_.calc_state(t, x); }
    double current_time() const override { return stepper_.current_time(); }
    const OdeState& current_state() const override { return stepper_.current_state(); }

private:
    Stepper stepper_;
    OdeRhs f_;
};

// Fehlberg 7(8) under error control. Odeint has no dense output for it: a state inside the
// last step is one more (uncontrolled) 7(8) step from the step's start, shorter than the
// accepted one, so its error is within the step's own.
class Fehlberg78 final : public DenseStepper {
public:
    Fehlberg78(double abs_tol, double rel_tol, OdeRhs f)
        : stepper_(odeint::make_controlled(abs_tol, rel_tol,
                                           odeint::runge_kutta_fehlberg78<OdeState>())),
          f_(std::move(f)) {}
    void initialize(const OdeState& x, double t0, double dt, double) override {
        x_ = x, x_prev_ = x, t_ = t0, t_prev_ = t0, dt_ = dt;
    }
    std::pair<double, double> do_step() override {
        x_prev_ = x_, t_prev_ = t_;
        // the controller shrinks dt after each rejection; it cannot shrink forever
        for (int tries = 0; tries < 500; ++tries) {
            if (stepper_.try_step(std::ref(f_), x_, t_, dt_) == odeint::success)
                return {t_prev_, t_};
            if (!(std::abs(dt_) > 1e-15 * std::max(1.0, std::abs(t_)))) break;
        }
        return {t_prev_, t_prev_};  // no progress: the caller reports the step size
    }
    void calc_state(double t, OdeState& x) override {
        if (t == t_) {
            x = x_;
        } else if (t == t_prev_) {
            x = x_prev_;
        } else {
            x.resize(x_.size());
            stepper_.stepper().do_step(std::ref(f_), x_prev_, t_prev_, x, t - t_prev_);
        }
    }
    double current_time() const override { return t_; }
    const OdeState& current_state() const override { return x_; }

private:
    odeint::controlled_runge_kutta<odeint::runge_kutta_fehlberg78<OdeState>> stepper_;
    OdeRhs f_;
    OdeState x_, x_prev_;
    double t_ = 0, t_prev_ = 0, dt_ = 0;
};

}  // namespace

std::unique_ptr<DenseStepper> make_dense_stepper(Integrator method, double abs_tol,
                                                 double rel_tol, OdeRhs f) {
    switch (method) {
        case Integrator::dopri5: {
            auto s = odeint::make_dense_output(abs_tol, rel_tol,
                                               odeint::runge_kutta_dopri5<OdeState>());
            return std::make_unique<OdeintDense<decltype(s)>>(std::move(s), std::move(f));
        }
        case Integrator::rkf78:
            return std::make_unique<Fehlberg78>(abs_tol, rel_tol, std::move(f));
        case Integrator::bulirsch_stoer: {
            odeint::bulirsch_stoer_dense_out<OdeState> s(abs_tol, rel_tol);
            return std::make_unique<OdeintDense<decltype(s)>>(std::move(s), std::move(f));
        }
        case Integrator::bdf:
            return make_cvode_bdf_stepper(abs_tol, rel_tol, std::move(f));
    }
    throw ArgumentError("make_dense_stepper(): unknown integrator");
}

}  // namespace detail

}  // namespace alembert
