// SPDX-License-Identifier: MIT
// Statements left out: an Autolev statement with no counterpart in the script is left out with a
// warning at its column and a comment at its place in the script, and so is every later
// statement that uses a name it defined or would have changed; a model whose equations change,
// or that is left without equations, says so.
#include <unordered_set>

#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

namespace {

// the Autolev vector names that give a model its positions, motions and loads
bool model_vector(const std::string& key) {
    for (const char* prefix : {"P_", "V_", "A_", "W_", "ALF_", "FORCE_", "TORQUE_"})
        if (key.rfind(prefix, 0) == 0) return true;
    return false;
}

// `X = ...` as the file says it in a message: X, R>, D>>, ZERO[...], Q''
std::string said(const Expr& e) {
    std::string s = e.text;
    if (e.kind == Expr::Kind::index) s += "[...]";
    s += std::string(static_cast<std::size_t>(e.primes), '\'');
    if (e.dyadic)
        s += ">>";
    else if (e.vector)
        s += ">";
    return s;
}

// the statement, in a few words, for the list of what changes the equations
std::string describe(const Statement& st) {
    switch (st.kind) {
        case Statement::Kind::declaration:
        case Statement::Kind::list:
        case Statement::Kind::command:
            return st.keyword;
        case Statement::Kind::assignment:
            return said(st.lhs) + " " + (st.compound ? std::string(1, st.compound) : "") + "= ...";
        case Statement::Kind::expression:
            return st.expr.kind == Expr::Kind::call ? upper(st.expr.text) + "(...)"
                                                    : "an expression";
    }
    return "a statement";
}

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

}  // namespace

std::vector<StatementNames> Translator::index_names(const ParsedFile& parsed) {
    std::vector<StatementNames> index;
    index.reserve(parsed.statements.size());
    for (const Statement& st : parsed.statements) {
        StatementNames n;
        std::unordered_set<std::string> seen;
        // every name the expression holds, once each, by a worklist (chains of any length)
        auto uses = [&](const Expr& root) {
            std::vector<const Expr*> todo{&root};
            while (!todo.empty()) {
                const Expr* e = todo.back();
                todo.pop_back();
                if (e->kind == Expr::Kind::name || e->kind == Expr::Kind::index) {
                    std::string key = upper(e->text);
                    if (seen.insert(key).second) n.uses.push_back({key, said(*e), e->where});
                }
                for (const Expr& a : e->args) todo.push_back(&a);
            }
        };
        auto defines_names = [&](const Expr& e) {
            if (e.kind == Expr::Kind::name) n.defines.push_back(upper(e.text));
        };
        switch (st.kind) {
            case Statement::Kind::declaration: {
                const std::string& w = st.keyword;
                const bool definitions = w.rfind("VARIABLE", 0) == 0 ||
                                         w.rfind("MOTIONVARIABLE", 0) == 0 ||
                                         w.rfind("SPECIFIED", 0) == 0;
                for (const Declarator& d : st.declarators) {
                    if (!d.has_value) continue;
                    uses(d.value);
                    if (definitions)
                        for (const std::string& name : expand(d)) n.defines.push_back(upper(name));
                }
                break;
            }
            case Statement::Kind::list:
                for (const Item& it : st.items) {
                    uses(it.lhs);
                    if (it.has_value) uses(it.value);
                }
                break;
            case Statement::Kind::command:
                break;
            case Statement::Kind::assignment: {
                uses(st.rhs);
                const std::string key = upper(st.lhs.text);
                if (st.lhs.kind == Expr::Kind::index) {
                    if (key == "AUXILIARY") {
                        defines_names(st.rhs);  // the speed made auxiliary
                    } else if (key != "DEPENDENT") {
                        uses(st.lhs);  // ZERO[2] = ... continues the array ZERO
                        n.defines.push_back(key);
                    }
                } else if (st.lhs.primes == 0) {
                    n.defines.push_back(key);
                }
                break;
            }
            case Statement::Kind::expression: {
                const Expr& e = st.expr;
                uses(e);
                if (e.kind != Expr::Kind::call) break;
                const std::string f = upper(e.text);
                // SOLVE and EIG assign their unknowns and results; KANE(F1, F2) its forces;
                // CONSTRAIN(AUXILIARY[U4]) changes what U4 is
                if (f == "SOLVE" || (f == "EIG" && e.args.size() > 1))
                    for (std::size_t i = 1; i < e.args.size(); ++i) defines_names(e.args[i]);
                if (f == "KANE")
                    for (const Expr& a : e.args) defines_names(a);
                // SIMPROT(A, B, ...) orients B: B and its unit vectors B1>, B2>, B3>
                if (f == "SIMPROT" && e.args.size() == 4 && e.args[1].kind == Expr::Kind::name) {
                    const std::string b = upper(e.args[1].text);
                    for (const char* k : {"", "1", "2", "3"}) n.defines.push_back(b + k);
                }
                if (f == "CONSTRAIN")
                    for (const Expr& a : e.args)
                        if (a.kind == Expr::Kind::index && upper(a.text) == "AUXILIARY")
                            for (const Expr& u : a.args) defines_names(u);
                break;
            }
        }
        index.push_back(std::move(n));
    }
    return index;
}

bool Translator::shapes_model(const Statement& st) const {
    switch (st.kind) {
        case Statement::Kind::declaration:
        case Statement::Kind::command:
            return false;
        case Statement::Kind::list:
            return st.keyword == "MASS" || st.keyword == "INERTIA";
        case Statement::Kind::expression: {
            if (st.expr.kind != Expr::Kind::call) return false;
            const std::string f = upper(st.expr.text);
            for (const char* g : {"GRAVITY", "FORCE", "TORQUE", "SIMPROT", "V2PTS", "V1PT", "A2PTS",
                                  "A1PT", "CONSTRAIN", "KANE"})
                if (f == g) return true;
            return false;
        }
        case Statement::Kind::assignment: {
            const Expr& lhs = st.lhs;
            const std::string key = upper(lhs.text);
            if (lhs.kind == Expr::Kind::index) return key == "DEPENDENT" || key == "AUXILIARY";
            if (lhs.primes > 0 || key == "ZERO")
                return true;  // kinematical or differential equations
            if (lhs.dyadic) return key.rfind("I_", 0) == 0;  // an inertia dyadic
            if (lhs.vector) return model_vector(key);
            // a direction cosine matrix A_B = [...]
            auto fr = [this](std::string_view x) { return frame_of(x); };
            return st.rhs.kind == Expr::Kind::matrix &&
                   split(std::string_view(lhs.text), fr, fr).has_value();
        }
    }
    return false;
}

Translator::Journal Translator::open_journal() {
    added_.clear();
    wholes_written_.clear();
    return {model_.size(), out_.diagnostics.size(), extra_constants_.size(), renames_.size(),
            time_unit_};
}

void Translator::roll_back(const Journal& j) {
    model_.resize(j.model);
    out_.diagnostics.resize(j.diagnostics);
    extra_constants_.resize(j.extra_constants);
    renames_.resize(j.renames);
    time_unit_ = j.time_unit;
    for (const auto& [key, object] : added_) (object ? objects_ : names_).erase(key);
    for (const std::string& key : wholes_written_)
        if (auto it = names_.find(key); it != names_.end()) it->second.whole_written = false;
    added_.clear();
    wholes_written_.clear();
}

std::optional<NameUse> Translator::left_out_use(const Expr& root) const {
    std::vector<const Expr*> todo{&root};
    while (!todo.empty()) {
        const Expr* e = todo.back();
        todo.pop_back();
        if (e->kind == Expr::Kind::name || e->kind == Expr::Kind::index)
            if (left_out_names_.count(upper(e->text)))
                return NameUse{upper(e->text), said(*e), e->where};
        for (const Expr& a : e->args) todo.push_back(&a);
    }
    return std::nullopt;
}

void Translator::translate_or_leave_out(const Statement& st, const StatementNames& names) {
    // the comments of declarations left out in part stand where the declaration stands
    if (auto c = part_comments_.find({st.where.line, st.where.column}); c != part_comments_.end())
        for (const std::string& l : c->second) emit(l);
    auto uses_why = [this](const NameUse& u) {
        const int line = left_out_names_.at(u.key);
        return std::make_pair(
            "uses " + u.said + ", which line " + std::to_string(line) + " left out",
            "write the counterpart of line " + std::to_string(line) +
                " by hand in the script, then this statement");
    };
    const Journal j = open_journal();
    try {
        const NameUse* tainted = nullptr;
        if (!left_out_names_.empty())
            for (const NameUse& u : names.uses)
                if (left_out_names_.count(u.key)) {
                    tainted = &u;
                    break;
                }
        const bool values_list =
            st.kind == Statement::Kind::list &&
            (st.keyword.rfind("INPUT", 0) == 0 || st.keyword.rfind("OUTPUT", 0) == 0);
        if (tainted && values_list) {
            // INPUT and OUTPUT lose only the items that use a left-out name
            Statement kept = st;
            kept.items.clear();
            for (const Item& it : st.items) {
                std::optional<NameUse> u = left_out_use(it.lhs);
                if (!u && it.has_value) u = left_out_use(it.value);
                if (!u) {
                    kept.items.push_back(it);
                    continue;
                }
                const auto [why, hint] = uses_why(*u);
                record_left_out(st, u->where, why, hint, {}, true);
            }
            translate(kept);
            return;
        }
        if (tainted) {
            const auto [why, hint] = uses_why(*tainted);
            leave_out(tainted->where, why, hint);
        }
        translate(st);
        // a name assigned again means what this statement says from here on
        // (but not those this statement left out in part: KANE(F1, F2)'s forces)
        for (const std::string& k : names.defines)
            if (auto t = left_out_names_.find(k);
                t != left_out_names_.end() && t->second != st.where.line)
                left_out_names_.erase(t);
    } catch (const LeftOut& e) {
        roll_back(j);
        record_left_out(st, e.where(), e.what(), e.hint(), names.defines, false);
    }
}

void Translator::record_left_out(const Statement& st, Location where, const std::string& reason,
                                 const std::string& hint, const std::vector<std::string>& defines,
                                 bool part) {
    report(Severity::warning, where, (part ? "left out in part: " : "left out: ") + reason,
           hint.empty() ? "the statement is left out of the Alembert script; write its counterpart "
                          "by hand if needed"
                        : hint);
    const std::string comment =
        "# left out (" + file_ + ":" + std::to_string(where.line) + "): " + one_line(reason);
    // a declaration's part is left out while the declarations are read, before the statements
    if (st.kind == Statement::Kind::declaration && part)
        part_comments_[{st.where.line, st.where.column}].push_back(comment);
    else
        emit(comment);
    for (const std::string& k : defines) left_out_names_[k] = st.where.line;
    if (shapes_model(st)) model_changes_.emplace_back(st.where.line, describe(st));
    const bool dynamics =
        st.kind == Statement::Kind::assignment && st.lhs.kind == Expr::Kind::name &&
        !st.lhs.vector &&
        (st.lhs.primes == 2 || (upper(st.lhs.text) == "ZERO" && st.lhs.primes == 0) ||
         (st.lhs.primes == 1 && [&] {
             const Entry* en = find(st.lhs.text);
             return en && rate_of_.count(en->name) > 0;
         }()));
    if (dynamics && !part) {
        dynamics_left_out_.push_back(st.where.line);
        if (const Entry* en = find(st.lhs.text); en && st.lhs.primes > 0)
            odes_left_out_.insert(en->name);
    }
}

void Translator::say_model_changes() {
    auto lines = [](const std::vector<std::pair<int, std::string>>& v) {
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i)
            s += (i ? ", " : "") + std::to_string(v[i].first) + " (" + v[i].second + ")";
        return s;
    };
    if (kane_at_ && !model_changes_.empty()) {
        const std::string which =
            (model_changes_.size() == 1 ? "line " : "lines ") + lines(model_changes_);
        const Location where = odes_.empty() ? kane_where_ : odes_.front().second;
        const std::string says = "the equations of motion are formed without what " + which +
                                 " left out, so they are not the Autolev file's equations";
        report(Severity::warning, where, says,
               "write the counterparts of those lines by hand in the script, before its kane "
               "statement");
        model_warnings_.insert(says);
        model_[*kane_at_] = "# the equations below lack what " + which +
                            " left out: they are not the Autolev "
                            "file's equations\n" +
                            model_[*kane_at_];
    }
    if (!kane_at_ && !dynamics_left_out_.empty()) {
        std::string which;
        for (std::size_t i = 0; i < dynamics_left_out_.size(); ++i)
            which += (i ? ", " : "") + std::to_string(dynamics_left_out_[i]);
        const std::string says =
            "the file's equations of motion (line" +
            std::string(dynamics_left_out_.size() == 1 ? " " : "s ") + which +
            ") are left out, so the script forms no model: it holds the rest of the file only";
        report(Severity::warning, {dynamics_left_out_.front(), 1}, says,
               "write the equations of motion by hand in the script (docs/autolev.md)");
        model_warnings_.insert(says);
    }
}

}  // namespace alembert::lang::autolev
