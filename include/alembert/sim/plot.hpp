// SPDX-License-Identifier: MIT
// Plots of CSV tables as PNG and SVG, drawn by gnuplot driven from the program.
#pragma once

#include <string>
#include <vector>

#include "alembert/sim/table.hpp"

namespace alembert {

/// What to draw.
struct PlotOptions {
    std::string title{};
    /// The column along the horizontal axis; empty: the first column.
    std::string x{};
    /// The columns to draw; empty: every column but x. Columns sharing a unit share a panel
    /// (one panel per unit, stacked), so angles and energies are not squeezed onto one axis.
    std::vector<std::string> y{};
    /// Draw nothing (a script's `plot none`): plot_csv returns at once, `drawn` false.
    bool skip = false;
};

/// What plotting did.
struct PlotResult {
    bool drawn = false;                ///< both files were written
    std::vector<std::string> files{};  ///< the files written
    std::string message{};             ///< why not, when not drawn (print it for the user)
};

/// The gnuplot program used: $ALEMBERT_GNUPLOT if set, else "gnuplot" on the PATH.
std::string gnuplot_program();

/// True if gnuplot_program() runs.
bool gnuplot_available();

/// A table longer than a plot needs (more than 4000 rows) is drawn from a thinned copy that
/// keeps each column's extremes (calc_plot_rows), written beside the plot and removed after.
/// Draws columns of `table`, whose numbers are in the CSV file `csv_path` (as write_csv wrote
/// it), into `output_base`.png (pngcairo, 900x600 per panel row) and `output_base`.svg with
/// gnuplot. gnuplot was chosen over MathGL and PLplot because Debian's gnuplot-nox is one small
/// package with no GUI, reads the CSV we write anyway, and makes both formats well; being a
/// separate program, a missing gnuplot costs only the plot, never the run.
/// Does not throw for a missing or failing gnuplot: `drawn` is false and `message` says what to
/// install or what gnuplot reported; the CSV stays written.
/// @throws alembert::ArgumentError if a named column does not exist.
PlotResult plot_csv(const Table& table, const std::string& csv_path, const std::string& output_base,
                    const PlotOptions& options = {});

}  // namespace alembert
