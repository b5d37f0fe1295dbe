// SPDX-License-Identifier: MIT
// The path of a test file in tests/biomech/data.
#pragma once

#include <string>

namespace alembert::test {

inline std::string biomech_data(const std::string& name) {
    return std::string(ALEMBERT_BIOMECH_DATA) + "/" + name;
}

}  // namespace alembert::test
