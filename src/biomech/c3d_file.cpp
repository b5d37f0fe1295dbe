// SPDX-License-Identifier: MIT
// C3D files read from their bytes: header, parameter section, point and analog data, checked.
#include "alembert/biomech/c3d_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>

#include "alembert/error.hpp"

namespace alembert {

namespace {

constexpr std::size_t kBlock = 512;
constexpr double kInvalid = std::numeric_limits<double>::quiet_NaN();

enum class Processor { intel, dec, mips };

// the file's bytes, read with bounds checks in the processor's byte order and float format
class C3dBytes {
public:
    C3dBytes(std::string path, std::string bytes) : path_(std::move(path)), bytes_(std::move(bytes)) {}

    [[noreturn]] void fail(const std::string& what) const { throw ArgumentError(path_ + ": " + what); }
    [[noreturn]] void fail_at(std::size_t at, const std::string& what) const {
        fail(what + " (byte " + std::to_string(at) + ")");
    }
    std::size_t size() const { return bytes_.size(); }
    const std::string& path() const { return path_; }
    void set_processor(Processor p) { processor_ = p; }

    // that `n` bytes from `at` are in the file, else "truncated" naming `what`
    void need(std::size_t at, std::size_t n, const std::string& what) const {
        if (at > bytes_.size() || n > bytes_.size() - at)
            fail_at(at, "the file ends at byte " + std::to_string(bytes_.size()) + ", inside " + what +
                            ", which needs " + std::to_string(n) + " bytes from byte " + std::to_string(at) +
                            "; the file is truncated: copy or export it again");
    }
    std::uint8_t u8(std::size_t at) const {
        need(at, 1, "the parameter section");
        return static_cast<std::uint8_t>(bytes_[at]);
    }
    std::int8_t i8(std::size_t at) const { return static_cast<std::int8_t>(u8(at)); }
    std::uint16_t u16(std::size_t at) const {
        need(at, 2, "a 16-bit word");
        const auto b0 = static_cast<std::uint8_t>(bytes_[at]), b1 = static_cast<std::uint8_t>(bytes_[at + 1]);
        return processor_ == Processor::mips ? static_cast<std::uint16_t>(b0 << 8 | b1)
                                             : static_cast<std::uint16_t>(b1 << 8 | b0);
    }
    std::int16_t i16(std::size_t at) const { return static_cast<std::int16_t>(u16(at)); }
    double f32(std::size_t at) const {
        need(at, 4, "a 32-bit float");
        unsigned char b[4];
        std::memcpy(b, bytes_.data() + at, 4);
        std::uint32_t bits = 0;
        if (processor_ == Processor::mips) {
            bits = std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3];
        } else if (processor_ == Processor::intel) {
            bits = std::uint32_t(b[3]) << 24 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[1]) << 8 | b[0];
        } else {
            // DEC (VAX F_floating): two little-endian 16-bit words, sign, exponent and high
            // fraction first; as IEEE bits its value is four times too large (bias 128 and a
            // 0.1f mantissa against 127 and 1.f); exponent 0 is zero
            bits = std::uint32_t(b[1]) << 24 | std::uint32_t(b[0]) << 16 | std::uint32_t(b[3]) << 8 | b[2];
            if (((bits >> 23) & 0xFF) == 0) return 0.0;
        }
        float f;
        std::memcpy(&f, &bits, 4);
        return processor_ == Processor::dec ? static_cast<double>(f) / 4 : static_cast<double>(f);
    }
    std::string text(std::size_t at, std::size_t n) const {
        need(at, n, "the parameter section");
        return bytes_.substr(at, n);
    }

private:
    std::string path_, bytes_;
    Processor processor_ = Processor::intel;
};

// one parameter: its numbers (types 1, 2, 4) or strings (type -1, the first dimension the
// length of each), and its dimensions
struct C3dParameter {
    int type = 0;
    std::vector<std::size_t> dims{};
    std::vector<double> numbers{};
    std::vector<std::string> strings{};
    std::size_t byte = 0;  // where its record starts, for messages
};

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string trim_label(std::string s) {
    const std::size_t end = s.find_last_not_of(std::string(" \t\r\n\0", 5));
    s.erase(end == std::string::npos ? 0 : end + 1);
    const std::size_t start = s.find_first_not_of(' ');
    return start == std::string::npos ? std::string() : s.substr(start);
}

// the parameter section from byte `start`: "GROUP:NAME" -> parameter
std::map<std::string, C3dParameter> read_parameters(const C3dBytes& in, std::size_t start, std::size_t blocks) {
    const std::size_t end = std::min(in.size(), start + blocks * kBlock);
    std::map<int, std::string> groups;
    std::vector<std::pair<int, std::pair<std::string, C3dParameter>>> params;
    std::size_t at = start + 4;
    while (at + 2 <= end) {
        const int name_length = std::abs(static_cast<int>(in.i8(at)));  // negative: locked
        const int id = in.i8(at + 1);
        if (name_length == 0 || id == 0) break;  // the end of the section
        const std::size_t record = at;
        const std::string name = upper(in.text(at + 2, static_cast<std::size_t>(name_length)));
        const std::size_t offset_at = at + 2 + static_cast<std::size_t>(name_length);
        const std::uint16_t offset = in.u16(offset_at);
        std::size_t p = offset_at + 2;
        if (id < 0) {
            groups[-id] = name;
        } else {
            C3dParameter par;
            par.byte = record;
            par.type = in.i8(p);
            const std::size_t ndims = in.u8(p + 1);
            p += 2;
            if (par.type != -1 && par.type != 1 && par.type != 2 && par.type != 4)
                in.fail_at(record, "the parameter '" + name + "' has the data type " + std::to_string(par.type) +
                                       "; C3D parameters are -1 (characters), 1 (bytes), 2 (integers) or 4 (floats)");
            std::size_t count = 1;
            for (std::size_t d = 0; d < ndims; ++d) {
                par.dims.push_back(in.u8(p + d));
                count *= par.dims.back();  // at most 255^7, well inside 64 bits
            }
            p += ndims;
            const std::size_t width = static_cast<std::size_t>(std::abs(par.type));
            if (count > (end - std::min(end, p)) / width)
                in.fail_at(record, "the parameter '" + name + "' holds " + std::to_string(count) + " values of " +
                                       std::to_string(width) + " bytes, more than the parameter section has left; "
                                       "the file is damaged: export it again");
            if (par.type == -1) {
                const std::size_t length = par.dims.empty() ? 1 : par.dims[0];
                const std::size_t n = length == 0 ? 0 : count / length;
                for (std::size_t i = 0; i < n; ++i) par.strings.push_back(trim_label(in.text(p + i * length, length)));
            } else {
                for (std::size_t i = 0; i < count; ++i) {
                    const std::size_t q = p + i * width;
                    par.numbers.push_back(par.type == 1 ? in.u8(q) : par.type == 2 ? in.i16(q) : in.f32(q));
                }
            }
            params.push_back({id, {name, std::move(par)}});
        }
        if (offset == 0) break;  // the last record
        const std::size_t next = offset_at + offset;
        if (next <= at) break;
        at = next;
    }
    std::map<std::string, C3dParameter> out;
    for (auto& [id, np] : params) {
        auto g = groups.find(id);
        if (g == groups.end()) continue;  // a parameter of no group: not read
        out.emplace(g->second + ":" + np.first, std::move(np.second));
    }
    return out;
}

// the parameters read by name, with the file's messages
struct Parameters {
    const C3dBytes& in;
    std::map<std::string, C3dParameter> all;

    const C3dParameter* find(const std::string& key) const {
        auto it = all.find(key);
        return it == all.end() ? nullptr : &it->second;
    }
    std::vector<double> numbers(const std::string& key) const {
        const C3dParameter* p = find(key);
        return p ? p->numbers : std::vector<double>{};
    }
    double number(const std::string& key, double otherwise) const {
        const C3dParameter* p = find(key);
        return p && !p->numbers.empty() ? p->numbers.front() : otherwise;
    }
    // a count stored as a 16-bit integer: read unsigned (a count above 32767)
    double count(const std::string& key, double otherwise) const {
        const C3dParameter* p = find(key);
        if (!p || p->numbers.empty()) return otherwise;
        double v = p->numbers.front();
        if (p->type == 2 && v < 0) v += 65536;
        return v;
    }
    std::string text(const std::string& key) const {
        const C3dParameter* p = find(key);
        return p && !p->strings.empty() ? p->strings.front() : std::string();
    }
    // GROUP:LABELS, GROUP:LABELS2, ... in order
    std::vector<std::string> labels(const std::string& group) const {
        std::vector<std::string> out;
        for (int k = 1;; ++k) {
            const C3dParameter* p = find(group + ":LABELS" + (k == 1 ? std::string() : std::to_string(k)));
            if (!p) break;
            out.insert(out.end(), p->strings.begin(), p->strings.end());
        }
        return out;
    }
};

// labels made unique ("_2", "_3") and given to unnamed points ("P3"), with a note per rename
std::vector<std::string> unique_labels(std::vector<std::string> labels, std::size_t n, const std::string& stem,
                                       const std::string& path, std::vector<std::string>& notes) {
    labels.resize(n);
    std::map<std::string, int> seen;
    for (std::size_t i = 0; i < n; ++i) {
        if (labels[i].empty()) labels[i] = stem + std::to_string(i + 1);
        const int k = ++seen[labels[i]];
        if (k > 1) {
            const std::string renamed = labels[i] + "_" + std::to_string(k);
            notes.push_back(path + ": the label '" + labels[i] + "' is used again by " + stem + std::to_string(i + 1) +
                            ", read as '" + renamed + "'");
            labels[i] = renamed;
        }
    }
    return labels;
}

// a count or index read from a parameter (a damaged file may give a float, NaN or a huge
// value): within 0..65535, else `otherwise`
std::size_t to_count(double v, std::size_t otherwise) {
    return v >= 0 && v <= 65535 ? static_cast<std::size_t>(v) : otherwise;
}

}  // namespace

C3dFile read_c3d(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ArgumentError("read_c3d(): cannot open '" + path + "'; check the file name");
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    C3dBytes in(path, std::move(bytes));
    C3dFile out;

    // the header (block 1): its first two bytes are the parameter block and the key 0x50
    in.need(0, kBlock, "the header (the first 512-byte block)");
    const std::size_t param_block = in.u8(0);
    if (in.u8(1) != 0x50)
        in.fail_at(1, "not a C3D file: its second byte is " + std::to_string(in.u8(1)) +
                          ", where a C3D file has 80 (0x50); export the trial from the lab's software as C3D");
    if (param_block < 2)
        in.fail_at(0, "the header puts the parameter section at block " + std::to_string(param_block) +
                          ", inside the header; the file is damaged: export it again");
    const std::size_t param_start = (param_block - 1) * kBlock;
    if (param_start + 4 > in.size())
        in.fail_at(0, "the header puts the parameter section at block " + std::to_string(param_block) + " (byte " +
                          std::to_string(param_start) + "), past the end of the file (" + std::to_string(in.size()) +
                          " bytes); the file is truncated or damaged: export it again");
    // the processor type, before any word of more than one byte is read
    const int processor = in.u8(param_start + 3);
    if (processor == 84) {
        in.set_processor(Processor::intel), out.processor = "Intel";
    } else if (processor == 85) {
        in.set_processor(Processor::dec), out.processor = "DEC";
    } else if (processor == 86) {
        in.set_processor(Processor::mips), out.processor = "MIPS";
    } else {
        in.fail_at(param_start + 3, "unknown processor type " + std::to_string(processor) +
                                        "; C3D files are written for 84 (Intel), 85 (DEC) or 86 (MIPS): export the "
                                        "trial again");
    }
    const std::size_t param_blocks = in.u8(param_start + 2);
    in.need(param_start, param_blocks * kBlock, "the parameter section (" + std::to_string(param_blocks) + " blocks)");
    const Parameters par{in, read_parameters(in, param_start, param_blocks)};

    const std::size_t points = in.u16(2);
    const std::size_t analog_words = in.u16(4);
    const long first_frame = in.u16(6);
    long last_frame = in.u16(8);
    const double scale = in.f32(12);
    std::size_t data_block = in.u16(16);
    const std::size_t per_frame = in.u16(18);
    double rate = par.number("POINT:RATE", in.f32(20));
    if (data_block == 0) data_block = to_count(par.count("POINT:DATA_START", 0), 0);
    if (!(rate > 0) || !std::isfinite(rate))
        in.fail(std::string("the frame rate (POINT:RATE, or the header's) is ") + format_csv_number(rate) +
                "; it must be positive: set the capture rate in the lab's software and export again");
    if (!std::isfinite(scale) || scale == 0)
        in.fail_at(12, "the header's scale factor is " + format_csv_number(scale) +
                           "; it must be non-zero (negative for floating-point data)");
    if (last_frame < first_frame)
        in.fail_at(8, "the last frame " + std::to_string(last_frame) + " comes before the first " +
                          std::to_string(first_frame) + "; the file is damaged: export it again");
    if (data_block < 2)
        in.fail_at(16, "the data start at block " + std::to_string(data_block) + ", inside the header; the file "
                                                                                   "is damaged: export it again");
    out.float_data = scale < 0;
    std::size_t frames = static_cast<std::size_t>(last_frame - first_frame + 1);
    const double used_points = par.count("POINT:USED", static_cast<double>(points));
    if (used_points != static_cast<double>(points))
        out.notes.push_back(path + ": POINT:USED is " + format_csv_number(used_points) + " but the header stores " +
                            std::to_string(points) + " points per frame; the header's count is read");

    // analog channels: ANALOG:USED, their samples per frame from the header
    std::size_t channels = to_count(par.count("ANALOG:USED", 0), 0);
    if (!par.find("ANALOG:USED") && per_frame > 0) channels = analog_words / per_frame;
    if (channels * per_frame != analog_words)
        in.fail_at(4, "the header stores " + std::to_string(analog_words) + " analog values per frame, but "
                      "ANALOG:USED (" + std::to_string(channels) + " channels) times the samples per frame (" +
                      std::to_string(per_frame) + ") is " + std::to_string(channels * per_frame) +
                      "; the file is damaged: export it again");
    out.analog_per_frame = channels > 0 ? per_frame : 0;
    out.analog_rate_hz = par.number("ANALOG:RATE", rate * static_cast<double>(per_frame));
    if (channels > 0 && (!(out.analog_rate_hz > 0) || !std::isfinite(out.analog_rate_hz)))
        in.fail("ANALOG:RATE is " + format_csv_number(out.analog_rate_hz) + "; it must be positive");

    // the data's size, before anything is allocated
    const std::size_t word = out.float_data ? 4 : 2;
    const std::size_t frame_bytes = (4 * points + analog_words) * word;
    const std::size_t data_start = (data_block - 1) * kBlock;
    if (data_start > in.size())
        in.fail_at(16, "the data start at block " + std::to_string(data_block) + " (byte " + std::to_string(data_start) +
                           "), past the end of the file (" + std::to_string(in.size()) +
                           " bytes); the file is truncated: export it again");
    // the frame count: the header's (last - first + 1); where the data hold fewer, POINT:FRAMES
    // if they hold that many, else the whole frames the data hold if the file ends with the
    // last of them (some exporters leave the header's count wrong); a frame cut short is an error
    const double param_frames = par.count("POINT:FRAMES", 0);
    const std::size_t fit = frame_bytes > 0 ? (in.size() - data_start) / frame_bytes : frames;
    const bool param_ok = param_frames >= 1 && param_frames <= 1e9 && param_frames == std::floor(param_frames);
    if (frames > fit) {
        const std::string claimed = path + ": the header gives " + std::to_string(frames) + " frames (" +
                                    std::to_string(first_frame) + " to " + std::to_string(last_frame) + ")";
        const bool by_param = param_ok && static_cast<std::size_t>(param_frames) <= fit;
        const bool whole = fit >= 1 && data_start + fit * frame_bytes == in.size();
        if (by_param || whole) {
            frames = by_param ? static_cast<std::size_t>(param_frames) : fit;
            last_frame = first_frame + static_cast<long>(frames) - 1;
            const std::string range = std::to_string(first_frame) + " to " + std::to_string(last_frame);
            out.notes.push_back(
                by_param ? claimed + ", more than the data hold; POINT:FRAMES (" + std::to_string(frames) +
                               ") is read, frames " + range
                         : claimed + (param_ok ? " and POINT:FRAMES " + format_csv_number(param_frames) : std::string()) +
                               ", but the file ends after " + std::to_string(frames) + " whole frames; these are read, "
                               "frames " + range + " (if the file was cut short, copy or export it again)");
        }
    } else if (param_ok && param_frames != static_cast<double>(frames)) {
        out.notes.push_back(path + ": POINT:FRAMES is " + format_csv_number(param_frames) + " but the header gives " +
                            std::to_string(frames) + " frames (" + std::to_string(first_frame) + " to " +
                            std::to_string(last_frame) + "); the header's count is read");
    }
    if (frame_bytes > 0 && (in.size() - data_start) / frame_bytes < frames) {
        const std::size_t whole = (in.size() - data_start) / frame_bytes;
        in.fail_at(data_start + (whole + 1) * frame_bytes,
                   "the file holds " + std::to_string(frames) + " frames (" + std::to_string(first_frame) + " to " +
                       std::to_string(last_frame) + ") of " + std::to_string(frame_bytes) + " bytes from byte " +
                       std::to_string(data_start) + ", but ends at byte " + std::to_string(in.size()) +
                       ", inside frame " + std::to_string(first_frame + static_cast<long>(whole)) +
                       "; the file is truncated: copy or export it again");
    }

    // markers: labels, units, and a table in metres
    MarkerTable& markers = out.markers;
    markers.data_rate_hz = rate;
    markers.file_unit = par.text("POINT:UNITS");
    if (markers.file_unit.empty()) markers.file_unit = "mm";
    Unit unit;
    try {
        unit = parse_unit(markers.file_unit);
    } catch (const ArgumentError&) {
        in.fail("POINT:UNITS is '" + markers.file_unit + "'; marker coordinates are in mm, cm or m");
    }
    if (unit.quantity != "length")
        in.fail("POINT:UNITS is '" + markers.file_unit + "', not a length; marker coordinates are in mm, cm or m");
    markers.markers = unique_labels(par.labels("POINT"), points, "P", path, out.notes);
    Table& mt = markers.table;
    mt.add_column("time", "s");
    for (const std::string& m : markers.markers)
        for (const char* axis : {".X", ".Y", ".Z"}) mt.add_column(m + axis, "m");
    for (auto& c : mt.columns) c.reserve(frames);

    // analog channels: labels, units, scale and offset
    std::vector<std::string> analog_labels = unique_labels(par.labels("ANALOG"), channels, "A", path, out.notes);
    std::vector<double> a_scale = par.numbers("ANALOG:SCALE"), a_offset = par.numbers("ANALOG:OFFSET");
    const double gen_scale = par.number("ANALOG:GEN_SCALE", 1.0);
    const bool unsigned_analog = upper(par.text("ANALOG:FORMAT")) == "UNSIGNED";
    std::vector<std::string> a_units;
    if (const C3dParameter* u = par.find("ANALOG:UNITS")) a_units = u->strings;
    a_scale.resize(channels, 1.0), a_offset.resize(channels, 0.0), a_units.resize(channels);
    if (const C3dParameter* o = par.find("ANALOG:OFFSET"); o && o->type == 2 && unsigned_analog)
        for (double& v : a_offset) v = v < 0 ? v + 65536 : v;  // offsets of unsigned data
    Table& at = out.analog;
    at.add_column("time", "s");
    for (std::size_t c = 0; c < channels; ++c) at.add_column(analog_labels[c], a_units[c]);
    for (auto& c : at.columns) c.reserve(frames * per_frame);

    // the data, frame by frame
    auto value = [&](std::size_t p) { return out.float_data ? in.f32(p) : static_cast<double>(in.i16(p)); };
    const double point_factor = (out.float_data ? 1.0 : std::abs(scale)) * unit.factor;
    for (std::size_t k = 0; k < frames; ++k) {
        std::size_t p = data_start + k * frame_bytes;
        mt.columns[0].push_back((static_cast<double>(first_frame - 1) + static_cast<double>(k)) / rate);
        for (std::size_t i = 0; i < points; ++i, p += 4 * word) {
            // the fourth word: negative is an invalid point (a gap)
            const double residual = out.float_data ? std::round(in.f32(p + 3 * word)) : in.i16(p + 3 * word);
            const bool valid = !(residual < 0) && std::isfinite(residual);
            for (std::size_t a = 0; a < 3; ++a) {
                const double x = value(p + a * word);
                mt.columns[1 + 3 * i + a].push_back(valid && std::isfinite(x) ? x * point_factor : kInvalid);
            }
        }
        for (std::size_t s = 0; s < per_frame && channels > 0; ++s) {
            at.columns[0].push_back(static_cast<double>(k * per_frame + s) / out.analog_rate_hz +
                                    mt.columns[0][0]);
            for (std::size_t c = 0; c < channels; ++c, p += word) {
                double raw = out.float_data ? in.f32(p) : unsigned_analog ? in.u16(p) : in.i16(p);
                at.columns[1 + c].push_back((raw - a_offset[c]) * a_scale[c] * gen_scale);
            }
        }
    }

    // force plates
    const std::size_t plates = to_count(par.count("FORCE_PLATFORM:USED", 0), 0);
    const std::vector<double> types = par.numbers("FORCE_PLATFORM:TYPE"), corners = par.numbers("FORCE_PLATFORM:CORNERS"),
                              origins = par.numbers("FORCE_PLATFORM:ORIGIN"), zero = par.numbers("FORCE_PLATFORM:ZERO"),
                              cal = par.numbers("FORCE_PLATFORM:CAL_MATRIX");
    const C3dParameter* channel_par = par.find("FORCE_PLATFORM:CHANNEL");
    for (std::size_t i = 0; i < plates; ++i) {
        const std::string plate = "force plate " + std::to_string(i + 1);
        auto missing = [&](const std::string& what) {
            in.fail("FORCE_PLATFORM:" + what + " has no values for " + plate + " (FORCE_PLATFORM:USED is " +
                    std::to_string(plates) + "); the file is damaged: export it again");
        };
        C3dForcePlate fp;
        if (types.size() <= i) missing("TYPE");
        fp.type = static_cast<int>(to_count(types[i], 0));
        if (fp.type < 1 || fp.type > 4 || types[i] != fp.type)
            in.fail(plate + " is of type " + format_csv_number(types[i]) +
                    ", which this reader does not compute; it reads types 1, 2, 3 and 4: export the plate as type 2 "
                    "(forces and moments) or 4 (with its calibration matrix)");
        if (corners.size() < 12 * (i + 1)) missing("CORNERS");
        if (origins.size() < 3 * (i + 1)) missing("ORIGIN");
        for (int c = 0; c < 4; ++c)
            for (int a = 0; a < 3; ++a) fp.corners[c][a] = corners[12 * i + 3 * static_cast<std::size_t>(c) + static_cast<std::size_t>(a)] * unit.factor;
        for (int a = 0; a < 3; ++a) fp.origin[a] = origins[3 * i + static_cast<std::size_t>(a)] * unit.factor;
        const std::size_t n_channels = fp.type == 3 ? 8 : 6;
        const std::size_t rows = channel_par && !channel_par->dims.empty() ? channel_par->dims[0] : 0;
        if (!channel_par || rows < n_channels || channel_par->numbers.size() < rows * (i + 1))
            in.fail("FORCE_PLATFORM:CHANNEL does not give " + plate + "'s " + std::to_string(n_channels) +
                    " analog channels (a type " + std::to_string(fp.type) + " plate has " + std::to_string(n_channels) +
                    "); the file is damaged: export it again");
        for (std::size_t c = 0; c < n_channels; ++c) {
            const double ch = channel_par->numbers[rows * i + c];
            if (!(ch >= 1) || ch > static_cast<double>(channels))
                in.fail(plate + "'s channel " + std::to_string(c + 1) + " is analog channel " + format_csv_number(ch) +
                        ", but the file has " + std::to_string(channels) + " analog channels (numbered from 1); the "
                        "file is damaged: export it again");
            fp.channels.push_back(static_cast<std::size_t>(ch));
        }
        if (zero.size() >= 2)
            fp.zero[0] = static_cast<int>(to_count(zero[0], 0)), fp.zero[1] = static_cast<int>(to_count(zero[1], 0));
        if (fp.type == 4) {
            if (cal.size() < 36 * (i + 1))
                in.fail(plate + " is of type 4 but FORCE_PLATFORM:CAL_MATRIX has no 6 x 6 matrix for it; export the "
                                "plate with its calibration matrix, or as type 2");
            fp.cal_matrix.assign(cal.begin() + static_cast<long>(36 * i), cal.begin() + static_cast<long>(36 * (i + 1)));
        }
        out.plates.push_back(std::move(fp));
    }
    out.forces = calc_c3d_ground_forces(out, path, out.notes);
    markers.notes = out.notes;
    return out;
}

}  // namespace alembert
