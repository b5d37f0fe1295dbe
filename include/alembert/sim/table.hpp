// SPDX-License-Identifier: MIT
// Tables of numbers with named columns and units: CSV written atomically and read with checks.
#pragma once

#include <string>
#include <vector>

namespace alembert {

/// A unit for printing or reading a column: its name as written ("deg", "N m") and the factor
/// that turns a value in it into SI (value_SI = factor * value; deg: pi/180), and the
/// quantity it measures ("angle", "length", "time", "force", "torque", ...; "" for no unit).
struct Unit {
    std::string name{};
    double factor = 1.0;
    std::string quantity{};
};

/// The unit of this name. Known: "" and "1" (no unit), s, ms, min, rad, deg, rev, m, cm, mm,
/// km, kg, g, N, kN, N m (also N*m, N.m, Nm, N·m), J, kJ, W, Hz, rad/s, deg/s, rpm, rad/s^2,
/// deg/s^2, m/s, km/h, m/s^2, N m/kg, N/kg, W/kg, kg m^2.
/// @throws alembert::ArgumentError naming the unit and listing the known ones.
Unit parse_unit(const std::string& name);

/// A table of numbers stored by column: column c has the name names[c], the unit units[c]
/// (as printed) and the values columns[c][row], in that unit.
struct Table {
    std::vector<std::string> names{};
    std::vector<std::string> units{};
    std::vector<std::vector<double>> columns{};
    /// For a table read from a file: the line each row came from (for messages); else empty.
    std::vector<int> lines{};

    /// Appends an empty column; returns its index.
    std::size_t add_column(const std::string& name, const std::string& unit);
    /// Number of rows (0 without columns).
    std::size_t row_count() const { return columns.empty() ? 0 : columns.front().size(); }
    /// The index of the column named `name`.
    /// @throws alembert::ArgumentError naming the column and listing the table's columns.
    std::size_t column_index(const std::string& name) const;
};

/// The rows of `table` to draw when a plot needs at most about `max_rows` of them: every row
/// if there are no more than that; else the first and last rows and, in each of
/// max_rows / (2 (columns - 1)) runs of consecutive rows, the rows where each column but the
/// first (the time) takes its least and its greatest value. So a thinned curve keeps its
/// extremes (a spike one row wide survives), in increasing row order, with at most
/// max_rows + 2 rows. O(rows x columns).
std::vector<std::size_t> calc_plot_rows(const Table& table, std::size_t max_rows);

/// `table` restricted to `rows` (as calc_plot_rows gives them), same names and units.
Table calc_table_rows(const Table& table, const std::vector<std::size_t>& rows);

/// Writes `table` as CSV: a header row "name [unit]" per column (a name alone when the unit
/// is empty), then one row per sample. With `digits` 0 (the default) each number is written
/// in the shortest form that reads back as the same double (at most 17 significant digits:
/// 0.84 stays 0.84), so a table written and read again is exact; with `digits` from 1 to 17
/// numbers are rounded to that many significant digits (printf's %.*g). The file is written
/// to a temporary beside `path` and renamed, so readers never see half a file.
/// @throws alembert::ArgumentError naming the path if it cannot be written (directory
///         missing, no permission), or if `digits` is outside 0..17.
void write_csv(const Table& table, const std::string& path, int digits = 0);

/// `v` as write_csv writes it: the shortest text that reads back as `v` when `digits` is 0,
/// otherwise rounded to `digits` significant digits.
std::string format_csv_number(double v, int digits = 0);

/// Reads a CSV table as write_csv writes it: a header row of "name [unit]" cells (the unit
/// optional), then rows of numbers, separated by commas; blank lines and lines starting with
/// '#' are skipped.
/// @throws alembert::ArgumentError with "path:line: " and what is wrong (a cell that is not a
///         number, a row with the wrong number of cells, a duplicate column, no rows, a file
///         that is not text: its first binary byte is named in hex, never printed).
Table read_csv(const std::string& path);

}  // namespace alembert
