// SPDX-License-Identifier: MIT
// Compact form of derived kinematic vectors of long chains.
#include "alembert/vec/compact_form.hpp"

#include "alembert/vec/frame.hpp"

namespace alembert {

FormedVector form_compact_if_long(const Vector& v, const Frame& E, bool from_compact) {
    if (!from_compact && v.components().size() <= kReadableFrames) return {v, false};
    if (v.is_zero()) return {v, true};
    Col3 c = v.components_in(E);
    for (ex& e : c.v) e = E.symbols().name_if_large(e, kCompactNameOps);
    return {Vector(E, c), true};
}

}  // namespace alembert
