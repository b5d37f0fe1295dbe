// SPDX-License-Identifier: MIT
// Umbrella header: everything Alembert offers.
#pragma once

#include "alembert/error.hpp"
#include "alembert/sym/cse.hpp"
#include "alembert/sym/matrix.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "alembert/sym/symbol_table.hpp"
#include "alembert/vec/dyadic.hpp"
#include "alembert/vec/frame.hpp"
#include "alembert/vec/rotation.hpp"
#include "alembert/vec/vector.hpp"
#include "alembert/mech/body.hpp"
#include "alembert/mech/inertia.hpp"
#include "alembert/mech/load.hpp"
#include "alembert/mech/particle.hpp"
#include "alembert/mech/point.hpp"
#include "alembert/mech/rigid_body.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/mech/system.hpp"
