// Smoke test: an outside project that finds the installed Alembert package.
#include <alembert/alembert.hpp>

#include <iostream>

int main() {
    alembert::SymbolTable st;
    auto q = st.add_variable("q", 2);
    std::cout << "d/dt q = " << st.dt(q) << '\n';
    return 0;
}
