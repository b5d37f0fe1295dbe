// SPDX-License-Identifier: MIT
// Deterministic printing of expressions: primes for derivatives, stable term order.
#pragma once

#include <ginac/ginac.h>

#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace alembert {

using GiNaC::ex;

/// Prints `e` in a deterministic order that does not depend on GiNaC's internal (hash and
/// creation-order dependent) ordering: factors of a product are sorted symbols first, then
/// functions, then parenthesised sums, by name; terms of a sum by their printed symbols, then
/// by degree. Derivatives print with primes (qA', qA'') because that is their symbol name.
std::string to_string(const ex& e);

/// The texts of `exprs` printed with one memo, so subexpressions they share are printed once.
std::vector<std::string> to_strings(const std::vector<ex>& exprs);

struct AbbreviatedForm;

/// to_string with one memo across calls, for a caller that prints many overlapping
/// expressions (the operands of a sum at every level of a TeX walk, the lines of an
/// abbreviation): a subexpression met again is looked up, not printed again. The texts are
/// those to_string gives; memory grows with the distinct subexpressions printed.
class TextPrinter {
public:
    TextPrinter();
    ~TextPrinter();
    TextPrinter(TextPrinter&&) noexcept;
    TextPrinter& operator=(TextPrinter&&) noexcept;

    /// to_string(e); the reference stays valid while this printer lives
    const std::string& operator()(const ex& e);

    /// The factor `f` of a product in the sign to_string writes it: GiNaC holds -L*s or
    /// L*(-s) depending on its term order, so a sum (a sum to an integer power, sin or cos of
    /// a sum) is turned to one canonical sign chosen from its text, and `flip` toggles for each
    /// sign taken out. For printers of other notations (TeX) to agree with the text.
    ex canonical_factor(const ex& f, bool& flip);

private:
    friend AbbreviatedForm abbreviate_form(const std::vector<ex>&, TextPrinter&, std::size_t,
                                           const std::string&, std::size_t);
    struct Memo;
    std::unique_ptr<Memo> memo_;
};

/// Streams `to_string(e)`.
void print(std::ostream& os, const ex& e);

class SymbolTable;

/// The definitions a reader needs before `printed`: one line "z3 = ..." for each intermediate
/// of `table` that `printed` names, directly or through another definition, in dependency order
/// (calc_used_intermediates, definitions made readable with calc_readable); empty if none.
std::string format_intermediates(const SymbolTable& table, const std::vector<ex>& printed);

/// Results too long to read as one line each, printed as MotionGenesis prints them: numbered
/// intermediates ("z1 = ..."), each defined before its first use, and every line at most about
/// `width` characters (a line is longer only where one function call or power alone is).
struct AbbreviatedText {
    std::vector<std::string> definitions;  ///< "z1 = ...", in dependency order
    std::vector<std::string> results;      ///< each expression's text, using the definitions
    /// how many definitions precede results[i]: a reader of results[i] needs only those, so the
    /// expressions may themselves be definitions printed in order (each after what it uses)
    std::vector<std::size_t> defined_before;
};

/// `exprs` abbreviated as above: a subexpression of two or more operations used more than
/// once is named, and so are the longest operands of a line that would pass `width`, and runs
/// of operands of a sum or product too long for one line. The names are `stem` followed by
/// `first`, `first` + 1, ...; they stand only for the printed text. Each distinct subexpression
/// is printed once; the operands of each node are visited in the order of their texts, so the
/// cost follows the length of the texts of the expressions' distinct nodes.
AbbreviatedText abbreviate(const std::vector<ex>& exprs, std::size_t width = 100,
                           const std::string& stem = "z", std::size_t first = 1);

/// The same as expressions, for printers of other notations (TeX): `definitions` pairs each
/// name's symbol with what it stands for; results and definitions use those symbols.
struct AbbreviatedForm {
    std::vector<std::pair<ex, ex>> definitions;
    std::vector<ex> results;
    std::vector<std::size_t> defined_before;
};
AbbreviatedForm abbreviate_form(const std::vector<ex>& exprs, std::size_t width = 100,
                                const std::string& stem = "z", std::size_t first = 1);

/// The same, its lines measured by `printer`: abbreviations of expressions that share nodes
/// (a page's vectors and equations, all holding the model's kinematics) print each shared node
/// once with one printer kept across the calls. The result does not depend on the printer.
AbbreviatedForm abbreviate_form(const std::vector<ex>& exprs, TextPrinter& printer,
                                std::size_t width = 100, const std::string& stem = "z",
                                std::size_t first = 1);

}  // namespace alembert
