// SPDX-License-Identifier: MIT
// gnuplot driven through a pipe: one panel per unit, PNG then SVG.
#include "alembert/sim/plot.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"

extern char** environ;

namespace alembert {

namespace {

// the most rows a plot draws (calc_plot_rows): a 900-pixel-wide panel shows no more
constexpr std::size_t kPlotRows = 4000;

// gnuplot strings in single quotes: a quote is doubled
std::string gp_quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
    return q + "'";
}

std::string label(const Table& t, std::size_t c) {
    return t.units[c].empty() ? t.names[c] : t.names[c] + " [" + t.units[c] + "]";
}

// runs gnuplot on `script` with its standard error in `errors`; false if it cannot start.
// The child is registered so that an interrupted run terminates it.
bool run_gnuplot(const std::string& script, const std::string& errors, int& status) {
    int fds[2];
    if (::pipe(fds) != 0) return false;
    ::fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, 2, errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::string program = gnuplot_program();
    char* argv[] = {program.data(), nullptr};
    pid_t pid = 0;
    const int rc = ::posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (rc != 0) {
        ::close(fds[1]);
        return false;
    }
    ChildProcess child(pid);
    // a gnuplot that exits early must not kill us with SIGPIPE
    struct sigaction ignore {}, old {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, &old);
    for (std::size_t done = 0; done < script.size();) {
        const ssize_t n = ::write(fds[1], script.data() + done, script.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
    }
    ::close(fds[1]);
    ::sigaction(SIGPIPE, &old, nullptr);
    int wstatus = 0;
    while (::waitpid(pid, &wstatus, 0) < 0)
        if (errno != EINTR) {
            status = -1;
            return true;
        }
    status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
    return true;
}

}  // namespace

std::string gnuplot_program() {
    const char* env = std::getenv("ALEMBERT_GNUPLOT");
    return env && *env ? env : "gnuplot";
}

// Started with posix_spawnp, not std::system: system() ignores SIGINT in the calling process
// while its child runs, so an interrupt that came while gnuplot was being probed was lost and
// the run went on to exit 0.
bool gnuplot_available() {
    std::string program = gnuplot_program(), version = "--version";
    posix_spawn_file_actions_t quiet;
    posix_spawn_file_actions_init(&quiet);
    posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
    char* argv[] = {program.data(), version.data(), nullptr};
    pid_t pid = -1;
    const int rc = posix_spawnp(&pid, program.c_str(), &quiet, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&quiet);
    if (rc != 0) return false;
    ChildProcess child(pid);  // terminated if this process is interrupted meanwhile
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

PlotResult plot_csv(const Table& table, const std::string& csv_path, const std::string& output_base,
                    const PlotOptions& options) {
    // columns: x, then the y columns grouped by unit (first appearance order)
    const std::size_t xc = options.x.empty() ? 0 : table.column_index(options.x);
    std::vector<std::size_t> ys;
    if (options.y.empty()) {
        for (std::size_t c = 0; c < table.names.size(); ++c)
            if (c != xc) ys.push_back(c);
    } else {
        for (const std::string& name : options.y) ys.push_back(table.column_index(name));
    }
    std::vector<std::string> units;
    std::map<std::string, std::vector<std::size_t>> by_unit;
    for (std::size_t c : ys) {
        if (!by_unit.count(table.units[c])) units.push_back(table.units[c]);
        by_unit[table.units[c]].push_back(c);
    }

    PlotResult result;
    if (options.skip) {
        result.message = "not asked for (plot none)";
        return result;
    }
    if (!gnuplot_available()) {
        result.message = "plot not drawn: gnuplot ('" + gnuplot_program() +
                         "') was not found; install it (Debian: apt install gnuplot-nox) or set "
                         "ALEMBERT_GNUPLOT to its path. The numbers are in " +
                         csv_path;
        return result;
    }
    if (ys.empty()) {
        result.message = "plot not drawn: the table has no columns to draw";
        return result;
    }

    // gnuplot draws into temporary files renamed into place once both are complete, so an
    // interrupted or failed run leaves no empty or partial plot
    namespace fs = std::filesystem;
    const std::string stamp = ".tmp" + std::to_string(static_cast<long>(::getpid()));
    auto temporary_for = [&](const std::string& suffix) {
        const fs::path target(output_base + suffix);
        return (target.parent_path() / ("." + target.filename().string() + stamp)).string();
    };
    TemporaryFile png(temporary_for(".png")), svg(temporary_for(".svg"));
    TemporaryFile err(temporary_for(".gnuplot-errors"));
    // a long run is drawn from a thinned copy that keeps each curve's extremes: a plot cannot
    // show more points than it has pixels, and gnuplot writing every row of a million-row run
    // into the SVG took most of the run's time
    TemporaryFile thinned(temporary_for(".csv"));
    std::string data_path = csv_path;
    std::size_t xc_drawn = xc;
    std::map<std::size_t, std::size_t> y_drawn;
    for (std::size_t c : ys) y_drawn[c] = c;
    if (table.row_count() > kPlotRows) {
        std::vector<std::size_t> keep(ys.begin(), ys.end());
        keep.insert(keep.begin(), xc);
        Table drawn;
        for (std::size_t c : keep) {
            drawn.names.push_back(table.names[c]);
            drawn.units.push_back(table.units[c]);
            drawn.columns.push_back(table.columns[c]);
        }
        write_csv(calc_table_rows(drawn, calc_plot_rows(drawn, kPlotRows)), thinned.path());
        data_path = thinned.path();
        // the thinned copy holds x, then the y columns in order
        xc_drawn = 0;
        for (std::size_t i = 0; i < ys.size(); ++i) y_drawn[ys[i]] = i + 1;
    }

    // the gnuplot script: one multiplot per terminal, one panel per unit
    std::string panels;
    panels +=
        "set datafile separator ','\nset grid\nset key outside right top\nset autoscale xfix\n";
    panels += "set xlabel " + gp_quoted(label(table, xc)) + "\n";
    std::string title = options.title;
    const std::size_t rows = units.size();
    std::string body;
    body += "set multiplot layout " + std::to_string(rows) + ",1" +
            (title.empty() ? "" : " title " + gp_quoted(title)) + "\n";
    for (const std::string& unit : units) {
        body += "set ylabel " + gp_quoted(unit.empty() ? "value" : "[" + unit + "]") + "\n";
        body += "plot ";
        bool first = true;
        for (std::size_t c : by_unit[unit]) {
            body += (first ? "" : ", ") + gp_quoted(data_path) + " every ::1 using " +
                    std::to_string(xc_drawn + 1) + ":" + std::to_string(y_drawn[c] + 1) +
                    " with lines lw 2 title " + gp_quoted(table.names[c]);
            first = false;
        }
        body += "\n";
    }
    body += "unset multiplot\n";
    const std::string height = std::to_string(300 + 300 * rows);
    std::string script = panels;
    script += "set terminal pngcairo size 900," + height + " font 'sans,10' noenhanced\n";
    script += "set output " + gp_quoted(png.path()) + "\n" + body;
    script += "set terminal svg size 900," + height + " dynamic font 'sans,10' noenhanced\n";
    script += "set output " + gp_quoted(svg.path()) + "\n" + body;
    script += "set output\n";

    // run it; its complaints go to a temporary file that becomes the message
    int status = -1;
    if (!run_gnuplot(script, err.path(), status)) {
        result.message = "plot not drawn: cannot start gnuplot";
        return result;
    }
    std::string complaints;
    if (std::FILE* f = std::fopen(err.path().c_str(), "r")) {
        char buf[512];
        while (std::fgets(buf, sizeof buf, f)) complaints += buf;
        std::fclose(f);
    }
    std::error_code ec;
    const bool files = fs::file_size(png.path(), ec) > 0 && !ec && fs::file_size(svg.path(), ec) > 0 && !ec;
    if (status != 0 || !files) {
        result.message = "plot not drawn: gnuplot failed: " +
                         (complaints.empty() ? std::string("no message") : complaints);
        return result;
    }
    for (TemporaryFile* t : {&png, &svg}) {
        const std::string target = t == &png ? output_base + ".png" : output_base + ".svg";
        fs::rename(t->path(), target, ec);
        if (ec) {
            result.message = "plot not drawn: cannot write '" + target + "' (" + ec.message() + ")";
            return result;
        }
        t->release();
    }
    result.drawn = true;
    result.files = {output_base + ".png", output_base + ".svg"};
    return result;
}

}  // namespace alembert
