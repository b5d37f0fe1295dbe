// SPDX-License-Identifier: MIT
// The registry of statements, and what is driven from it: help, the reference tables of
// docs/language.md and the fuzzer's dictionary.
#include "alembert/lang/statements.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "alembert/lang/parser.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

// the registry's index by keyword
const std::map<std::string_view, std::size_t>& statement_index() {
    static const std::map<std::string_view, std::size_t> index = [] {
        std::map<std::string_view, std::size_t> out;
        const auto& all = statements();
        for (std::size_t i = 0; i < all.size(); ++i) out.emplace(all[i].keyword, i);
        return out;
    }();
    return index;
}

// Markdown of a grammar or call cell as plain text: no backticks or italics, `\|` as `|`
std::string plain_text(std::string_view md) {
    std::string out;
    for (std::size_t i = 0; i < md.size(); ++i) {
        if (md[i] == '`' || md[i] == '*') continue;
        if (md[i] == '\\' && i + 1 < md.size() && md[i + 1] == '|') continue;
        out += md[i];
    }
    return out;
}

// an example as a Markdown table cell: code, with `|` escaped
std::string example_cell(std::string_view example) {
    std::string out = "`";
    for (char c : example) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out + "`";
}

}  // namespace

const std::vector<StatementSpec>& statements() {
    static const std::vector<StatementSpec> all = [] {
        std::vector<StatementSpec> out;
        using Family = std::vector<StatementSpec> (*)();
        for (Family family : {include_statements, declaration_statements, kinematics_statements, load_statements,
                              biomech_statements, lab_statements, scale_statements,
                              constraint_statements, equation_statements, linearize_statements,
                              number_statements})
            for (StatementSpec& s : family()) out.push_back(std::move(s));
        return out;
    }();
    return all;
}

const StatementSpec* find_statement(std::string_view keyword) {
    const auto& index = statement_index();
    auto it = index.find(keyword);
    return it == index.end() ? nullptr : &statements()[it->second];
}

std::vector<std::string_view> statement_families() {
    std::vector<std::string_view> out;
    for (const StatementSpec& s : statements())
        if (std::find(out.begin(), out.end(), s.family) == out.end()) out.push_back(s.family);
    return out;
}

const std::vector<std::string>& statement_clause_words() {
    static const std::vector<std::string> words = [] {
        std::set<std::string, std::less<>> set;
        for (const StatementSpec& s : statements())
            for (std::string_view w : s.clauses) set.emplace(w);
        return std::vector<std::string>(set.begin(), set.end());
    }();
    return words;
}

std::string statement_help(std::string_view keyword) {
    std::string out;
    if (keyword.empty()) {
        // every statement with its one line, by family
        std::size_t width = 0;
        for (const StatementSpec& s : statements()) width = std::max(width, s.keyword.size());
        out += "Statements (help WORD shows a statement's forms and examples):\n";
        for (std::string_view family : statement_families()) {
            out += std::string(family) + "\n";
            for (const StatementSpec& s : statements()) {
                if (s.family != family) continue;
                out += "  " + std::string(s.keyword) + std::string(width + 2 - s.keyword.size(), ' ') +
                       std::string(s.help) + "\n";
            }
        }
        out += "Also: name = expression assigns a value; an expression alone prints it (functions:\n"
               "docs/language.md). quit or exit ends the session.\n";
        return out;
    }
    const StatementSpec* s = find_statement(keyword);
    if (!s)
        return "'" + std::string(keyword) + "' is not a statement; type help for the list of statements\n";
    out += std::string(s->keyword) + ": " + std::string(s->help) + "\n";
    for (const StatementForm& f : s->forms) {
        out += "  " + plain_text(f.grammar) + "\n";
        out += "      e.g. " + std::string(f.example) + "\n";
        out += "      calls " + plain_text(f.call) + "\n";
    }
    return out;
}

std::string statement_forms(std::string_view keyword, std::string_view indent) {
    std::string out;
    if (const StatementSpec* s = find_statement(keyword))
        for (const StatementForm& f : s->forms) out += std::string(indent) + plain_text(f.grammar) + "\n";
    return out;
}

std::string statement_table_markdown(std::string_view family) {
    std::string out = "| statement | example | library call |\n|---|---|---|\n";
    for (const StatementSpec& s : statements()) {
        if (s.family != family) continue;
        for (const StatementForm& f : s.forms)
            out += "| " + std::string(f.grammar) + " | " + example_cell(f.example) + " | " +
                   std::string(f.call) + " |\n";
    }
    return out;
}

std::string fuzz_dictionary() {
    std::string out = "# The words of the Alembert language, for libFuzzer (-dict=); generated from the\n"
                      "# statement registry by fuzz_dictionary(), checked by test_lang.\n";
    std::set<std::string> seen;
    auto add = [&](const std::string& w) {
        if (!seen.insert(w).second) return;
        std::string escaped;
        for (char c : w) {
            if (c == '"' || c == '\\') escaped += '\\';
            escaped += c;
        }
        out += "\"" + escaped + "\"\n";
    };
    for (const StatementSpec& s : statements()) add(std::string(s.keyword) + " ");
    for (const std::string& w : statement_clause_words()) add(" " + w + " ");
    for (const std::string& f : function_names()) add(f + "(");
    for (const char* p : {">", ">>", "0>", "''", " = ", ", ", "[", "]", "; ", "#", " deg", " m/s^2", " N*m"})
        add(p);
    return out;
}

}  // namespace alembert::lang
