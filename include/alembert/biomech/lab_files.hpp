// SPDX-License-Identifier: MIT
// Readers and writers of the files motion-capture labs exchange: OpenSim .trc, .mot/.sto, CSV.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "alembert/sim/table.hpp"

namespace alembert {

/// Marker trajectories read from an OpenSim .trc file. `table` holds the column "time [s]"
/// and, per marker M, the columns "M.X [m]", "M.Y [m]", "M.Z [m]" in SI units whatever the
/// file's unit (mm, cm, m); a coordinate the file leaves empty (a marker not seen by the
/// cameras) is NaN. Gaps are filled and irregular time bases resampled by
/// regularize_time_base (time_base.hpp).
struct MarkerTable {
    Table table{};
    std::vector<std::string> markers{};  ///< in file order
    double data_rate_hz = 0;             ///< the header's DataRate
    std::string file_unit{};             ///< the header's Units ("mm")
    /// Things a reader should know that are not errors (the header's NumFrames disagreeing
    /// with the rows found), one sentence each.
    std::vector<std::string> notes{};

    /// The column index of marker `marker`'s coordinate `axis` (0 X, 1 Y, 2 Z).
    /// @throws alembert::ArgumentError naming the marker and listing the table's markers.
    std::size_t column(const std::string& marker, int axis) const;
};

/// The markers `names` of a trial (in the file's order, each once), with the time column and
/// the header's rate, unit and notes: the markers a model uses, so a marker it does not use
/// (one the cameras never saw) cannot block its trial.
/// @throws alembert::ArgumentError naming a marker the trial does not have and listing its
///         markers.
MarkerTable select_markers(const MarkerTable& trial, const std::vector<std::string>& names);

/// Reads an OpenSim marker file (.trc, "PathFileType 4 (X/Y/Z)"): the header keys DataRate,
/// NumFrames, NumMarkers and Units on lines 2-3, the marker names on line 4 (each above its X
/// column), the X1 Y1 Z1 ... line, then rows "frame time x1 y1 z1 ...", separated by tabs.
/// Empty cells (or fewer cells than markers at the end of a row, or "NaN") are a marker
/// missing at that frame and read as NaN.
/// @throws alembert::ArgumentError "path:line: what is wrong; how to fix it" for a file that
///         is not a .trc (or not text: a binary byte is named, never printed), a header key missing or not a number, a unit that is not a length,
///         NumMarkers disagreeing with the names on line 4, a cell that is not a number, a row
///         with more cells than markers, times not increasing, or no rows.
MarkerTable read_trc(const std::string& path);

/// An OpenSim storage file (.sto or .mot): its header's key=value lines, the inDegrees flag,
/// and the table of columns (the first is "time"; units are "s" for time and empty for the
/// others, since the format does not give them: see motion_table_from_storage).
struct StorageFile {
    Table table{};
    std::map<std::string, std::string> header{};  ///< version, nRows, nColumns, inDegrees, ...
    bool in_degrees = false;                      ///< inDegrees=yes
    std::vector<std::string> notes{};             ///< as MarkerTable::notes
};

/// Reads an OpenSim storage file: a first line naming the data, key=value lines (version=,
/// nRows=, nColumns=, inDegrees=yes/no) and free text up to the line "endheader", then a line
/// of column labels and rows of numbers separated by tabs or spaces. A label may state its
/// column's unit, "qA [m]", when the labels are separated by tabs; the table's unit is then
/// that unit. A cell "NaN" is kept as NaN (a missing sample: force_plate_from_table and
/// differentiate_motion refuse it where it would be read as data), except in the time column.
/// @throws alembert::ArgumentError "path:line: ..." if the file is not text (a binary byte is
///         named, never printed), there is no endheader, inDegrees is
///         neither yes nor no, nColumns disagrees with the labels, a row has the wrong number
///         of cells or a cell is not a number, the first column is not time, times do not
///         increase, or there are no rows.
StorageFile read_storage(const std::string& path);

/// The storage file's table with units set for a motion: "time" becomes "t [s]", each column
/// named in `angle_columns` gets "deg" (inDegrees=yes) or "rad" (no) unless its label states a
/// unit, so read_motion's differentiate_motion reads it in SI. As in OpenSim, inDegrees applies
/// to rotational coordinates only: list only those; the others (translations, in m) keep the
/// unit their label states, or none (SI).
/// @throws alembert::ArgumentError naming a listed column the file does not have.
Table motion_table_from_storage(const StorageFile& storage,
                                const std::vector<std::string>& angle_columns);

/// Writes `table` as an OpenSim storage file (.sto) named `name`: the header "name",
/// version=1, nRows, nColumns, inDegrees=no, endheader, then tab-separated columns with every
/// value converted to SI by its unit (deg to rad, mm to m; parse_unit), the first column
/// labelled "time" if its unit is a time. Numbers are written as write_csv writes them (the
/// shortest exact form), so the same table gives the same bytes. Written to a temporary beside
/// `path` and renamed.
/// @throws alembert::ArgumentError naming the path if it cannot be written, or a column with
///         an unknown unit.
void write_storage(const Table& table, const std::string& path, const std::string& name);

/// A table from a lab file chosen by its extension: .trc (read_trc's table), .sto/.mot
/// (read_storage's table, units as the file gives them), .c3d (read_c3d's marker table) or
/// .csv (read_csv: "name [unit]" headers).
/// @throws alembert::ArgumentError for another extension (listing the known ones), or as the
///         reader.
Table read_lab_table(const std::string& path);

}  // namespace alembert
