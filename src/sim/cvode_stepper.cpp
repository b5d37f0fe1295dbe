// SPDX-License-Identifier: MIT
// The BDF integrator: SUNDIALS CVODE stepping one step at a time, with its dense output.
// Built without SUNDIALS (src/sim/CMakeLists.txt), asking for it says how to get it.
#include "dense_stepper.hpp"

#include "alembert/error.hpp"

#if ALEMBERT_HAVE_SUNDIALS
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

namespace alembert::detail {

namespace {

// CVODE's BDF (orders 1 to 5) with Newton iterations on a dense Jacobian that CVODE forms by
// finite differences of f. Errors thrown by f are kept and rethrown after CVODE returns (they
// must not unwind through C frames); CVODE's own messages go into the exception, not stderr.
class CvodeBdf final : public DenseStepper {
public:
    CvodeBdf(double abs_tol, double rel_tol, OdeRhs f)
        : abs_tol_(abs_tol), rel_tol_(rel_tol), f_(std::move(f)) {}
    CvodeBdf(const CvodeBdf&) = delete;
    CvodeBdf& operator=(const CvodeBdf&) = delete;
    ~CvodeBdf() override {
        if (mem_) CVodeFree(&mem_);
        if (solver_) SUNLinSolFree(solver_);
        if (jacobian_) SUNMatDestroy(jacobian_);
        if (y_) N_VDestroy(y_);
        if (dky_) N_VDestroy(dky_);
        if (context_) SUNContext_Free(&context_);
    }

    // the first step is CVODE's own estimate from f and the tolerances: a fast transient at the
    // start (a stiff spring released) needs one far below any output step
    void initialize(const OdeState& x, double t0, double, double t_stop) override {
        const auto n = static_cast<sunindextype>(x.size());
        x_ = x, in_ = x, dx_ = x, t_ = t0, t_prev_ = t0;
        check(SUNContext_Create(nullptr, &context_), "SUNContext_Create");
        y_ = N_VNew_Serial(n, context_);
        dky_ = N_VNew_Serial(n, context_);
        std::copy(x.begin(), x.end(), N_VGetArrayPointer(y_));
        mem_ = CVodeCreate(CV_BDF, context_);
        jacobian_ = SUNDenseMatrix(n, n, context_);
        if (!y_ || !dky_ || !mem_ || !jacobian_) fail("could not allocate CVODE's workspace");
        solver_ = SUNLinSol_Dense(y_, jacobian_, context_);
        check(CVodeSetErrHandlerFn(mem_, &CvodeBdf::on_error, this), "CVodeSetErrHandlerFn");
        check(CVodeInit(mem_, &CvodeBdf::rhs, t0, y_), "CVodeInit");
        check(CVodeSetUserData(mem_, this), "CVodeSetUserData");
        check(CVodeSStolerances(mem_, rel_tol_, abs_tol_), "CVodeSStolerances");
        check(CVodeSetLinearSolver(mem_, solver_, jacobian_), "CVodeSetLinearSolver");
        check(CVodeSetStopTime(mem_, t_stop), "CVodeSetStopTime");
        t_stop_ = t_stop;
    }

    std::pair<double, double> do_step() override {
        double t = t_;
        const int flag = CVode(mem_, t_stop_, y_, &t, CV_ONE_STEP);
        rethrow_error_of_f();
        if (flag < 0)
            fail(std::string("CVODE stopped (") + CVodeGetReturnFlagName(flag) + ")" +
                 (message_.empty() ? "" : ": " + message_));
        t_prev_ = t_, t_ = t;
        const double* y = N_VGetArrayPointer(y_);
        std::copy(y, y + x_.size(), x_.begin());
        return {t_prev_, t_};
    }

    void calc_state(double t, OdeState& x) override {
        x.resize(x_.size());
        if (t == t_) {
            x = x_;
            return;
        }
        check(CVodeGetDky(mem_, t, 0, dky_), "CVodeGetDky");
        const double* y = N_VGetArrayPointer(dky_);
        std::copy(y, y + x_.size(), x.begin());
    }
    double current_time() const override { return t_; }
    const OdeState& current_state() const override { return x_; }
    // a stiff start may begin with steps of 1e-15 s legitimately
    bool guards_step_size() const override { return true; }

private:
    static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
        auto* self = static_cast<CvodeBdf*>(data);
        try {
            const double* in = N_VGetArrayPointer(y);
            std::copy(in, in + self->in_.size(), self->in_.begin());
            self->f_(self->in_, self->dx_, t);
            std::copy(self->dx_.begin(), self->dx_.end(), N_VGetArrayPointer(ydot));
            return 0;
        } catch (...) {
            self->error_ = std::current_exception();
            return -1;  // unrecoverable: CVODE returns at once
        }
    }
    static void on_error(int, const char*, const char*, char* msg, void* data) {
        static_cast<CvodeBdf*>(data)->message_ = msg ? msg : "";
    }
    void rethrow_error_of_f() {
        if (!error_) return;
        std::exception_ptr e = error_;
        error_ = nullptr;
        std::rethrow_exception(e);
    }
    void check(int flag, const char* call) {
        rethrow_error_of_f();
        if (flag < 0)
            fail(std::string(call) + " returned " + CVodeGetReturnFlagName(flag) +
                 (message_.empty() ? "" : ": " + message_));
    }
    [[noreturn]] void fail(const std::string& what) { throw std::runtime_error("bdf: " + what); }

    double abs_tol_, rel_tol_;
    OdeRhs f_;
    SUNContext context_ = nullptr;
    void* mem_ = nullptr;
    N_Vector y_ = nullptr, dky_ = nullptr;
    SUNMatrix jacobian_ = nullptr;
    SUNLinearSolver solver_ = nullptr;
    OdeState x_, in_, dx_;
    double t_ = 0, t_prev_ = 0, t_stop_ = 0;
    std::exception_ptr error_{};
    std::string message_{};
};

}  // namespace

bool have_cvode() { return true; }

std::unique_ptr<DenseStepper> make_cvode_bdf_stepper(double abs_tol, double rel_tol, OdeRhs f) {
    return std::make_unique<CvodeBdf>(abs_tol, rel_tol, std::move(f));
}

}  // namespace alembert::detail

#else

namespace alembert::detail {

bool have_cvode() { return false; }

std::unique_ptr<DenseStepper> make_cvode_bdf_stepper(double, double, OdeRhs) {
    throw ArgumentError(
        "the bdf integrator is SUNDIALS CVODE, and this build of Alembert was made without it: "
        "install it (Debian: apt-get install libsundials-dev, or bash scripts/install_deps.sh "
        "test) and build again, or choose dopri5, rkf78 or bulirsch_stoer");
}

}  // namespace alembert::detail

#endif
