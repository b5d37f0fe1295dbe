// SPDX-License-Identifier: MIT
// A small C3D writer for tests, following C3D.org's format description: the header block, the
// parameter section (groups POINT, ANALOG, FORCE_PLATFORM), then the frames; Intel, DEC or
// MIPS byte order, integer or floating-point data.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace alembert::test {

enum class C3dProcessor { intel = 84, dec = 85, mips = 86 };

/// One force plate as the FORCE_PLATFORM group states it (lengths in the file's POINT:UNITS).
struct C3dPlateSpec {
    int type = 2;
    std::array<double, 12> corners{};  ///< corner 1 x, y, z, corner 2 x, y, z, ...
    std::array<double, 3> origin{};
    std::vector<int> channels{};       ///< 1-based analog channels
    std::vector<double> cal_matrix{};  ///< 36 values, (r, c) at r + 6 c (type 4)
};

/// What the writer writes. Points are given in POINT:UNITS; analog values are the stored
/// (raw) values, [sample][channel].
struct C3dSpec {
    C3dProcessor processor = C3dProcessor::intel;
    bool floats = true;
    double scale = 0.1;  ///< integer data: the coordinate of a stored word is word * scale
    double rate = 100;
    int first_frame = 1;
    std::string units = "mm";
    std::vector<std::string> labels{};
    std::vector<std::vector<std::array<double, 3>>> points{};  ///< [frame][point]
    std::vector<std::vector<bool>> valid{};                  ///< [frame][point]; empty: all valid
    std::vector<std::string> analog_labels{}, analog_units{};
    std::vector<double> analog_scale{}, analog_offset{};
    double gen_scale = 1;
    int analog_per_frame = 1;
    std::vector<std::vector<double>> analog{};  ///< [frame * analog_per_frame + s][channel]
    std::vector<C3dPlateSpec> plates{};
    std::array<int, 2> zero{0, 0};
    long header_frames = 0;  ///< the header's frame count if not 0 (else the frames given)
    long param_frames = 0;   ///< POINT:FRAMES if not 0 (else the frames given)
    bool pad_data = true;    ///< pad the data to whole 512-byte blocks
};

class C3dWriter {
public:
    explicit C3dWriter(C3dProcessor p) : p_(p) {}

    void i8(std::string& out, int v) const { out.push_back(static_cast<char>(static_cast<std::int8_t>(v))); }
    void i16(std::string& out, long v) const {
        const auto u = static_cast<std::uint16_t>(static_cast<std::int16_t>(v));
        const char lo = static_cast<char>(u & 0xFF), hi = static_cast<char>(u >> 8);
        if (p_ == C3dProcessor::mips) out.push_back(hi), out.push_back(lo);
        else out.push_back(lo), out.push_back(hi);
    }
    void f32(std::string& out, double v) const {
        float f = static_cast<float>(v);
        if (p_ == C3dProcessor::dec) f *= 4;  // VAX F: bias 128 and a 0.1f mantissa
        std::uint32_t bits;
        std::memcpy(&bits, &f, 4);
        const unsigned char c[4] = {static_cast<unsigned char>(bits), static_cast<unsigned char>(bits >> 8),
                                    static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 24)};
        if (p_ == C3dProcessor::intel) out.append(reinterpret_cast<const char*>(c), 4);
        else if (p_ == C3dProcessor::mips) out.push_back(static_cast<char>(c[3])), out.push_back(static_cast<char>(c[2])),
                                             out.push_back(static_cast<char>(c[1])), out.push_back(static_cast<char>(c[0]));
        else if (v == 0) out.append(4, '\0');
        else out.push_back(static_cast<char>(c[2])), out.push_back(static_cast<char>(c[3])),
             out.push_back(static_cast<char>(c[0])), out.push_back(static_cast<char>(c[1]));
    }

    // a parameter section record
    void group(std::string& out, int id, const std::string& name) const {
        i8(out, static_cast<int>(name.size()));
        i8(out, -id);
        out += name;
        i16(out, 3);  // to the next record: this word, the description's length byte
        i8(out, 0);
    }
    void numbers(std::string& out, int id, const std::string& name, int type, std::vector<int> dims,
                 const std::vector<double>& values) const {
        std::string data;
        for (double v : values) type == 2 ? i16(data, std::lround(v)) : type == 1 ? i8(data, static_cast<int>(v)) : f32(data, v);
        record(out, id, name, type, dims, data);
    }
    void strings(std::string& out, int id, const std::string& name, const std::vector<std::string>& values,
                 std::size_t width) const {
        std::string data;
        for (std::string v : values) data += v.append(width - std::min(width, v.size()), ' ').substr(0, width);
        record(out, id, name, -1, {static_cast<int>(width), static_cast<int>(values.size())}, data);
    }
    void record(std::string& out, int id, const std::string& name, int type, const std::vector<int>& dims,
                const std::string& data) const {
        i8(out, static_cast<int>(name.size()));
        i8(out, id);
        out += name;
        i16(out, static_cast<long>(2 + 2 + dims.size() + data.size() + 1));
        i8(out, type);
        i8(out, static_cast<int>(dims.size()));
        for (int d : dims) i8(out, d);
        out += data;
        i8(out, 0);
    }

private:
    C3dProcessor p_;
};

/// The bytes of a C3D file as `s` describes it.
inline std::string c3d_bytes(const C3dSpec& s) {
    const C3dWriter w(s.processor);
    const std::size_t frames = s.points.size(), points = s.labels.size(),
                      channels = s.analog_labels.size();
    // parameters
    std::string par;
    w.group(par, 1, "POINT");
    w.numbers(par, 1, "USED", 2, {}, {static_cast<double>(points)});
    w.numbers(par, 1, "SCALE", 4, {}, {s.floats ? -std::abs(s.scale) : s.scale});
    w.numbers(par, 1, "RATE", 4, {}, {s.rate});
    w.numbers(par, 1, "FRAMES", 2, {}, {static_cast<double>(s.param_frames != 0 ? s.param_frames : static_cast<long>(frames))});
    w.strings(par, 1, "UNITS", {s.units}, s.units.size());
    if (points > 0) w.strings(par, 1, "LABELS", s.labels, 8);
    w.group(par, 2, "ANALOG");
    w.numbers(par, 2, "USED", 2, {}, {static_cast<double>(channels)});
    if (channels > 0) {
        w.strings(par, 2, "LABELS", s.analog_labels, 8);
        w.strings(par, 2, "UNITS", s.analog_units, 4);
        w.numbers(par, 2, "SCALE", 4, {static_cast<int>(channels)}, s.analog_scale);
        w.numbers(par, 2, "OFFSET", 2, {static_cast<int>(channels)}, s.analog_offset);
    }
    w.numbers(par, 2, "GEN_SCALE", 4, {}, {s.gen_scale});
    w.numbers(par, 2, "RATE", 4, {}, {s.rate * s.analog_per_frame});
    w.group(par, 3, "FORCE_PLATFORM");
    const int used = static_cast<int>(s.plates.size());
    w.numbers(par, 3, "USED", 2, {}, {static_cast<double>(used)});
    if (used > 0) {
        std::vector<double> type, corners, origin, channel, cal;
        std::size_t rows = 6;
        for (const auto& p : s.plates) rows = std::max(rows, p.channels.size());
        for (const auto& p : s.plates) {
            type.push_back(p.type);
            corners.insert(corners.end(), p.corners.begin(), p.corners.end());
            origin.insert(origin.end(), p.origin.begin(), p.origin.end());
            for (std::size_t r = 0; r < rows; ++r) channel.push_back(r < p.channels.size() ? p.channels[r] : 0);
            std::vector<double> m = p.cal_matrix;
            if (m.empty()) m.assign(36, 0.0);
            cal.insert(cal.end(), m.begin(), m.end());
        }
        w.numbers(par, 3, "TYPE", 2, {used}, type);
        w.numbers(par, 3, "ZERO", 2, {2}, {static_cast<double>(s.zero[0]), static_cast<double>(s.zero[1])});
        w.numbers(par, 3, "CORNERS", 4, {3, 4, used}, corners);
        w.numbers(par, 3, "ORIGIN", 4, {3, used}, origin);
        w.numbers(par, 3, "CHANNEL", 2, {static_cast<int>(rows), used}, channel);
        w.numbers(par, 3, "CAL_MATRIX", 4, {6, 6, used}, cal);
    }
    // after the last record the section is padded with zeros: a name of length 0 ends it
    const std::size_t blocks = (4 + par.size() + 511) / 512;
    std::string section;
    section.push_back(1), section.push_back(0x50), section.push_back(static_cast<char>(blocks));
    section.push_back(static_cast<char>(static_cast<int>(s.processor)));
    section += par;
    section.resize(blocks * 512, '\0');

    // header
    std::string header;
    header.push_back(2), header.push_back(0x50);
    w.i16(header, static_cast<long>(points));
    w.i16(header, static_cast<long>(channels * static_cast<std::size_t>(s.analog_per_frame)));
    w.i16(header, s.first_frame);
    w.i16(header, s.first_frame + (s.header_frames != 0 ? s.header_frames : static_cast<long>(frames)) - 1);
    w.i16(header, 0);
    w.f32(header, s.floats ? -std::abs(s.scale) : s.scale);
    w.i16(header, static_cast<long>(2 + blocks));
    w.i16(header, s.analog_per_frame);
    w.f32(header, s.rate);
    header.resize(512, '\0');

    // data
    std::string data;
    for (std::size_t k = 0; k < frames; ++k) {
        for (std::size_t i = 0; i < points; ++i) {
            const bool ok = s.valid.empty() || s.valid[k][i];
            for (int a = 0; a < 3; ++a) {
                const double v = ok ? s.points[k][i][static_cast<std::size_t>(a)] : 0.0;
                if (s.floats) w.f32(data, v);
                else w.i16(data, std::lround(v / s.scale));
            }
            if (s.floats) w.f32(data, ok ? 0.0 : -1.0);
            else w.i16(data, ok ? 0 : -1);
        }
        for (int j = 0; j < s.analog_per_frame; ++j)
            for (std::size_t c = 0; c < channels; ++c) {
                const double v = s.analog[k * static_cast<std::size_t>(s.analog_per_frame) + static_cast<std::size_t>(j)][c];
                if (s.floats) w.f32(data, v);
                else w.i16(data, std::lround(v));
            }
    }
    if (s.pad_data) data.resize((data.size() + 511) / 512 * 512, '\0');
    return header + section + data;
}

inline void write_c3d(const std::string& path, const C3dSpec& s) {
    std::ofstream out(path, std::ios::binary);
    const std::string bytes = c3d_bytes(s);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace alembert::test
