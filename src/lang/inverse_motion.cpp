// SPDX-License-Identifier: MIT
// The motion `inverse` reads: the file's format by its extension, each coordinate's kind
// (rotation or translation) from the model, and an OpenSim storage file's columns in SI.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "alembert/biomech/lab_files.hpp"
#include "alembert/biomech/time_base.hpp"
#include "interpreter_impl.hpp"

namespace alembert::lang {

namespace {

constexpr const char* kMotionFormats =
    ".csv (a header row 't [s],qA [deg]' and rows of numbers), .mot and .sto (OpenSim storage "
    "files), .trc (OpenSim marker files, with the script's markers) and .c3d (C3D trials: their "
    "markers, with the script's markers)";

}  // namespace

std::string Interpreter::Impl::motion_format(const std::string& path) const {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".csv" || ext == ".mot" || ext == ".sto" || ext == ".trc" || ext == ".c3d") return ext;
    throw ArgumentError(
        "'" + path + "' is " +
        (ext.empty() ? "a file without an extension" : "a '" + ext + "' file") +
        "; inverse reads a motion from " + kMotionFormats +
        ": export the motion in one of these formats (a spreadsheet as CSV) and name "
        "the file with its extension");
}

std::vector<std::string> Interpreter::Impl::coordinate_quantities(
    const std::vector<TimeVariable>& q, Location where) {
    System& sys = model(where);
    // the frames of the model and its rigid bodies, each oriented in its parent
    std::vector<const Frame*> frames;
    for (const auto& [name, info] : names) {
        const Frame* F = nullptr;
        if (info.kind == NameKind::frame)
            F = &sys.frame(name);
        else if (info.kind == NameKind::body)
            F = sys.body(name).frame();
        if (F && F->parent()) frames.push_back(F);
    }
    std::vector<std::string> out;
    for (const TimeVariable& v : q) {
        // a declared unit says; else a coordinate that turns a frame is a rotation (an angle),
        // one that turns none is a translation (a length), as OpenSim's coordinate types are
        const Dimension d = symbol_dimension(v.name());
        if (d.known) {
            out.emplace_back();
            continue;
        }
        const bool turns = std::any_of(frames.begin(), frames.end(), [&](const Frame* F) {
            const Mat3 R = F->rotation_from_parent();
            return std::any_of(R.m.begin(), R.m.end(), [&](const ex& e) {
                return sys.symbols().depends_on(e, v.symbol());
            });
        });
        out.emplace_back(turns ? "angle" : "length");
    }
    return out;
}

Table Interpreter::Impl::storage_motion_table(const std::string& path,
                                              const std::vector<TimeVariable>& q, Location where,
                                              std::string& note) {
    const StorageFile storage = read_storage(path);
    // the time and the coordinates' columns (other columns are not read)
    StorageFile coordinates;
    coordinates.in_degrees = storage.in_degrees;
    coordinates.header = storage.header;
    Table& t = coordinates.table;
    t.add_column(storage.table.names[0], storage.table.units[0]);
    t.columns[0] = storage.table.columns[0];
    t.lines = storage.table.lines;
    std::string found;
    for (const std::string& n : storage.table.names) found += (found.empty() ? "" : ", ") + n;
    for (const TimeVariable& v : q) {
        const auto& names_in_file = storage.table.names;
        const auto it = std::find(names_in_file.begin() + 1, names_in_file.end(), v.name());
        if (it == names_in_file.end())
            throw ArgumentError(path + ": no column for the coordinate '" + v.name() +
                                "'; name a column '" + v.name() + "' (columns found: " + found +
                                ")");
        const std::size_t c = static_cast<std::size_t>(it - names_in_file.begin());
        t.add_column(v.name(), storage.table.units[c]);
        t.columns.back() = storage.table.columns[c];
    }
    // inDegrees applies to the rotational coordinates only (as in OpenSim): not to lengths
    std::vector<std::string> angles;
    const std::vector<std::string> kinds = coordinate_quantities(q, where);
    for (std::size_t i = 0; i < q.size(); ++i) {
        const bool length =
            kinds[i] == "length" || symbol_dimension(q[i].name()) == Dimension::length();
        if (!length) angles.push_back(q[i].name());
    }
    Table motion = motion_table_from_storage(coordinates, angles);
    // short gaps filled and the time base checked, stated when anything was done
    const TimeBaseReport base = regularize_time_base(motion, 0, path);
    if (!base.gaps.empty() || base.resampled || base.times_rounded) {
        note = base.describe();
        while (!note.empty() && note.back() == '\n') note.pop_back();
    }
    return motion;
}

}  // namespace alembert::lang
