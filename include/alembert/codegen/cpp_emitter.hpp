// SPDX-License-Identifier: MIT
// The C++ emitter: NAME.hpp, NAME.cpp and, for a simulation, NAME_main.cpp.
#pragma once

#include "alembert/codegen/emitter.hpp"

namespace alembert {

/// Emits C++17 in namespace NAME: struct Parameters (the constants, with their defaults as
/// member initializers) and class Model, constructed from parameters (the values computed
/// from them once are members), with the member functions mass_forcing, forward_dynamics
/// (Cholesky or LU, false for a singular M), inverse_dynamics, outputs, load_laws and rhs;
/// and with a simulation NAME_main.cpp, an adaptive Dormand-Prince RK45 integration writing
/// a CSV. Compiles with `c++ -std=c++17 -pedantic -Wall -Wextra`.
class CppEmitter : public Emitter {
public:
    Language language() const override { return Language::cpp; }
    const CodePrinter& printer() const override { return printer_; }
    std::vector<GeneratedFile> emit(const CodePlan& plan) const override;

private:
    CppPrinter printer_;
};

}  // namespace alembert
