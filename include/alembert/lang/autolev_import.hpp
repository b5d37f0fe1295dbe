// SPDX-License-Identifier: MIT
// Translation of Autolev-dialect models (.al) into Alembert scripts (.alb): `alembert import`.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "alembert/lang/diagnostic.hpp"

namespace alembert::lang {

/// The result of translating an Autolev file: the Alembert script, and what could not be
/// translated, statement by statement.
///
/// Errors are input the translator cannot read or that cannot mean anything (a malformed
/// statement, an undeclared name, a wrong number of arguments, a vector plus a scalar);
/// warnings are Autolev statements it read but that have no counterpart in Alembert (`PAUSE`,
/// `SQR(X)`, `COMPLEX ON`, `GRAVITY` on some bodies, ...) and were left out, with a comment at
/// their place in the script, together with every later statement that uses what they defined. Each names the
/// file, line and column of the Autolev statement, says what is wrong and how to go on.
struct AutolevTranslation {
    std::string script{};                   ///< the Alembert script (complete only if ok())
    std::vector<Diagnostic> diagnostics{};  ///< in the order of the Autolev file
    /// The lines of the Autolev file left out of the script in whole or in part (one warning
    /// each at least), ascending: statements with no counterpart, and the statements after
    /// them that use what they defined.
    std::vector<int> left_out_lines{};
    /// True if no diagnostic is an error: the script holds every statement that was read, but
    /// those the warnings (and left_out_lines) name.
    bool ok() const;
};

/// Translates the Autolev-dialect model `source` (named `file` in diagnostics) into an
/// Alembert script. Names are matched without regard to case and spelt as first declared;
/// indexed declarations (`Q{3}`, `U{2:4}`) are expanded; Autolev's implicit names (`NO`, the
/// Newtonian origin, and `BO`, the mass centre of body B) become Alembert's (`N_o`, `Bcm`);
/// declarations are moved first and the values of `INPUT` go into the constants and the
/// initial values, so statements may come in Autolev's order. Values carry no units unless
/// the Autolev file gives them. docs/autolev.md lists the statements and their translation.
/// Never throws on bad input: every problem becomes a diagnostic.
AutolevTranslation translate_autolev(std::string_view source, const std::string& file);

}  // namespace alembert::lang
