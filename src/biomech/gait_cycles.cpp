// SPDX-License-Identifier: MIT
// Gait events from force plates, cycles, time normalised to the cycle, and mean +- SD curves.
#include "alembert/biomech/gait_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"

namespace alembert {

namespace {

std::string num(double v) { return format_csv_number(v); }

}  // namespace

GaitEvents calc_gait_events(const std::vector<ForcePlate>& plates, int vertical) {
    ALEMBERT_CHECK_ARG(vertical >= 0 && vertical <= 2,
                       "calc_gait_events(): the vertical axis " + std::to_string(vertical) +
                           " is not 0, 1 or 2 (x, y, z of the plate's force)");
    GaitEvents events;
    for (const ForcePlate& plate : plates) {
        const double threshold = plate.contact_threshold;
        ALEMBERT_CHECK_ARG(threshold > 0 && std::isfinite(threshold),
                           "calc_gait_events(): plate '" + plate.name +
                               "' has the contact threshold " + num(threshold) +
                               " N; give a positive vertical force of contact (20 N is usual)");
        const std::vector<double>& F = plate.F[vertical];
        // a missing sample is refused by name, never read as no contact
        for (std::size_t k = 0; k < plate.t.size(); ++k) plate.in_contact(k);
        // each crossing of the threshold, at its time by linear interpolation
        for (std::size_t k = 1; k < plate.t.size(); ++k) {
            const double a = F[k - 1] - threshold, b = F[k] - threshold;
            const bool on = a < 0 && b >= 0, off = a >= 0 && b < 0;
            if (!on && !off) continue;
            const double t = plate.t[k - 1] + (plate.t[k] - plate.t[k - 1]) * (-a / (b - a));
            (on ? events.strikes : events.offs).push_back(t);
        }
    }
    std::sort(events.strikes.begin(), events.strikes.end());
    std::sort(events.offs.begin(), events.offs.end());
    return events;
}

std::vector<GaitCycle> calc_gait_cycles(const GaitEvents& events) {
    std::vector<GaitCycle> cycles;
    for (std::size_t i = 0; i + 1 < events.strikes.size(); ++i) {
        GaitCycle c{events.strikes[i], events.strikes[i + 1],
                    std::numeric_limits<double>::quiet_NaN()};
        // the first foot off inside the cycle
        for (double t : events.offs)
            if (t > c.start && t < c.end) {
                c.foot_off = t;
                break;
            }
        cycles.push_back(c);
    }
    return cycles;
}

Table calc_cycle_table(const Table& table, const GaitCycle& cycle, std::size_t points) {
    const std::string who = "calc_cycle_table(): ";
    ALEMBERT_CHECK_ARG(points >= 2, who + "give at least 2 points per cycle (101: every 1 %)");
    ALEMBERT_CHECK_ARG(!table.columns.empty() && table.row_count() >= 2,
                       who + "the table has fewer than 2 rows");
    const std::vector<double>& t = table.columns[0];
    for (std::size_t k = 1; k < t.size(); ++k)
        ALEMBERT_CHECK_ARG(t[k] > t[k - 1], who + "the times of the table do not increase at row " +
                                                std::to_string(k + 1) + " (t = " + num(t[k]) +
                                                " s)");
    ALEMBERT_CHECK_ARG(cycle.end > cycle.start && cycle.start >= t.front() && cycle.end <= t.back(),
                       who + "the cycle from t = " + num(cycle.start) + " to " + num(cycle.end) +
                           " s is not inside the results, t = " + num(t.front()) + " to " +
                           num(t.back()) +
                           " s; trim the cycles to the trial or record the whole cycle");
    Table out;
    out.add_column("cycle", "%");
    for (std::size_t c = 1; c < table.names.size(); ++c)
        out.add_column(table.names[c], table.units[c]);
    std::size_t k = 1;
    for (std::size_t i = 0; i < points; ++i) {
        // the time at p % of the cycle and the samples around it
        const double p = 100.0 * static_cast<double>(i) / static_cast<double>(points - 1);
        const double ti =
            i + 1 == points ? cycle.end : cycle.start + p / 100 * (cycle.end - cycle.start);
        while (k + 1 < t.size() && t[k] < ti) ++k;
        const double w = (ti - t[k - 1]) / (t[k] - t[k - 1]);
        out.columns[0].push_back(p);
        for (std::size_t c = 1; c < table.names.size(); ++c)
            out.columns[c].push_back(table.columns[c][k - 1] +
                                     w * (table.columns[c][k] - table.columns[c][k - 1]));
    }
    return out;
}

Table calc_cycle_statistics(const std::vector<Table>& curves,
                            const std::vector<std::string>& names) {
    const std::string who = "calc_cycle_statistics(): ";
    ALEMBERT_CHECK_ARG(!curves.empty(),
                       who + "no curves; run the trials with their gait cycles first");
    ALEMBERT_CHECK_ARG(names.size() == curves.size(), who + "give one name per curve");
    const Table& first = curves.front();
    for (std::size_t j = 1; j < curves.size(); ++j) {
        const Table& c = curves[j];
        ALEMBERT_CHECK_ARG(c.names == first.names && c.units == first.units,
                           who + "'" + names[j] + "' has other columns or units than '" + names[0] +
                               "'; run every trial with the same model and statement");
        ALEMBERT_CHECK_ARG(c.columns[0] == first.columns[0],
                           who + "'" + names[j] + "' is resampled at other percentages than '" +
                               names[0] + "'; normalise every cycle to the same points");
    }
    Table out;
    out.add_column("cycle", "%");
    out.columns[0] = first.columns[0];
    const double n = static_cast<double>(curves.size());
    for (std::size_t c = 1; c < first.names.size(); ++c) {
        // mean, then the sample standard deviation about it
        const std::size_t m = out.add_column(first.names[c] + "_mean", first.units[c]);
        const std::size_t s = out.add_column(first.names[c] + "_sd", first.units[c]);
        for (std::size_t i = 0; i < first.row_count(); ++i) {
            double sum = 0;
            for (const Table& curve : curves) sum += curve.columns[c][i];
            const double mean = sum / n;
            double ss = 0;
            for (const Table& curve : curves)
                ss += (curve.columns[c][i] - mean) * (curve.columns[c][i] - mean);
            out.columns[m].push_back(mean);
            out.columns[s].push_back(curves.size() > 1 ? std::sqrt(ss / (n - 1)) : 0.0);
        }
    }
    return out;
}

std::vector<CycleSummaryRow> calc_cycle_summary(const Table& statistics, std::size_t curves) {
    std::vector<CycleSummaryRow> rows;
    const std::vector<double>& p = statistics.columns[0];
    for (std::size_t c = 1; c + 1 < statistics.names.size(); c += 2) {
        const std::vector<double>& mean = statistics.columns[c];
        if (mean.empty()) continue;
        CycleSummaryRow r;
        r.quantity = statistics.names[c].substr(0, statistics.names[c].size() - 5);  // "_mean"
        r.unit = statistics.units[c];
        std::size_t at = 0;
        for (std::size_t i = 1; i < mean.size(); ++i)
            if (std::abs(mean[i]) > std::abs(mean[at])) at = i;
        r.peak = mean[at];
        r.peak_percent = p[at];
        r.sd_at_peak = statistics.columns[c + 1][at];
        r.min = *std::min_element(mean.begin(), mean.end());
        r.max = *std::max_element(mean.begin(), mean.end());
        r.curves = curves;
        rows.push_back(r);
    }
    return rows;
}

void write_cycle_summary(const std::vector<CycleSummaryRow>& rows, const std::string& path) {
    std::string text = "quantity,unit,peak,peak_percent,sd_at_peak,min,max,curves\n";
    for (const CycleSummaryRow& r : rows)
        text += r.quantity + "," + r.unit + "," + num(r.peak) + "," + num(r.peak_percent) + "," +
                num(r.sd_at_peak) + "," + num(r.min) + "," + num(r.max) + "," +
                std::to_string(r.curves) + "\n";
    write_file_atomically(path, text, "write_cycle_summary()");
}

}  // namespace alembert
