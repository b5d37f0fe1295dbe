// SPDX-License-Identifier: MIT
// Gait events from force plates, cycles from heel strike to heel strike, and time normalised
// to 0-100 % of a cycle.
#pragma once

#include <string>
#include <vector>

#include "alembert/biomech/force_plate.hpp"
#include "alembert/sim/table.hpp"

namespace alembert {

/// The contacts of one foot with its force plates: foot strikes (heel strike, contact on) and
/// foot offs (toe off, contact off), in s, in increasing order.
struct GaitEvents {
    std::vector<double> strikes{};
    std::vector<double> offs{};
};

/// The gait events of one foot from the plates it steps on: contact on where a plate's
/// vertical force rises through its contact threshold (ForcePlate::contact_threshold; 20 N by
/// default, above the noise of an unloaded plate and below any foot's load), contact off where
/// it falls below it, each at the time the force crosses the threshold by linear interpolation
/// between the two samples around it.
/// A plate already loaded at its first sample gives no strike there (the contact began before
/// the record), one still loaded at its last gives no off. `vertical` is the axis of the
/// plate's force that is vertical (1: the lab's Y up, as OpenSim's files).
/// @throws alembert::ArgumentError if a threshold is not positive (naming the plate),
///         `vertical` is not 0, 1 or 2, or as ForcePlate::in_contact (a missing force sample).
GaitEvents calc_gait_events(const std::vector<ForcePlate>& plates, int vertical = 1);

/// One gait cycle: from a foot strike to the next strike of the same foot, with the foot off
/// between them (NaN when the record holds none).
struct GaitCycle {
    double start = 0, end = 0;
    double foot_off = 0;
    /// The foot off as a percentage of the cycle, 100 (foot_off - start) / (end - start).
    double foot_off_percent() const { return 100 * (foot_off - start) / (end - start); }
};

/// The cycles between consecutive strikes of the events.
std::vector<GaitCycle> calc_gait_cycles(const GaitEvents& events);

/// A result table over one cycle, resampled onto 0, 1, ..., 100 % of the cycle (`points`
/// evenly spaced values from 0 to 100 %): the first column "cycle [%]", then every column of
/// `table` after its time, same names and units, linearly interpolated at the times
/// start + p/100 (end - start). Linear interpolation: at 100 Hz or more and 101 points per
/// cycle of about a second, it changes a gait curve by less than its filter does.
/// @throws alembert::ArgumentError if the cycle is not inside the table's times (naming
///         both), the table's first column is not increasing, or points < 2.
Table calc_cycle_table(const Table& table, const GaitCycle& cycle, std::size_t points = 101);

/// Mean and sample standard deviation (n - 1 in the denominator; 0 for one curve) over curves
/// normalised to the cycle (calc_cycle_table's tables, from several cycles or trials): the
/// first column "cycle [%]", then per column X of the curves "X_mean" and "X_sd" in X's unit.
/// `names` names each curve in messages (its trial and cycle).
/// @throws alembert::ArgumentError if there are no curves, or a curve's columns, units or
///         percentages differ from the first's (naming both curves).
Table calc_cycle_statistics(const std::vector<Table>& curves,
                            const std::vector<std::string>& names);

/// One row per quantity of a calc_cycle_statistics table: its name, unit, the mean curve's
/// peak (the value of largest magnitude, with its sign), the percentage of the cycle where it
/// is, the standard deviation there, the mean curve's smallest and largest values, and the
/// number of curves.
struct CycleSummaryRow {
    std::string quantity{}, unit{};
    double peak = 0, peak_percent = 0, sd_at_peak = 0, min = 0, max = 0;
    std::size_t curves = 0;
};

/// The summary of a calc_cycle_statistics table over `curves` curves.
std::vector<CycleSummaryRow> calc_cycle_summary(const Table& statistics, std::size_t curves);

/// Writes the summary as CSV: quantity,unit,peak,peak_percent,sd_at_peak,min,max,curves
/// (numbers as write_csv writes them), atomically.
/// @throws alembert::ArgumentError if the path cannot be written.
void write_cycle_summary(const std::vector<CycleSummaryRow>& rows, const std::string& path);

}  // namespace alembert
