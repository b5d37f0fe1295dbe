// SPDX-License-Identifier: MIT
// Winter's (Dempster's) and de Leva's segment tables, typed from the publications, and scaling.
#include "alembert/biomech/segment_parameters.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "alembert/error.hpp"

namespace alembert {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// Winter, D. A. (2009). Biomechanics and Motor Control of Human Movement, 4th ed., Wiley,
// Table 4.1 (Dempster 1955 via Miller and Nelson 1976 and Plagenhoef 1971): mass fraction,
// centre of mass from the proximal end, radius of gyration about the centre of mass.
const SegmentTable& winter_table() {
    static const SegmentTable table{
        "winter",
        "Winter, D. A. (2009), Biomechanics and Motor Control of Human Movement, 4th ed., Wiley, "
        "Table 4.1 (Dempster 1955)",
        "segment length between the landmarks shown (proximal-distal); radius of gyration about "
        "the centre of mass for planar (flexion-extension) motion",
        {
            {"hand", "wrist axis-knuckle II middle finger", 0.006, 0.506, 0.297, kNone, kNone},
            {"forearm", "elbow axis-ulnar styloid", 0.016, 0.430, 0.303, kNone, kNone},
            {"upper_arm", "glenohumeral axis-elbow axis", 0.028, 0.436, 0.322, kNone, kNone},
            {"forearm_hand", "elbow axis-ulnar styloid", 0.022, 0.682, 0.468, kNone, kNone},
            {"total_arm", "glenohumeral joint-ulnar styloid", 0.050, 0.530, 0.368, kNone, kNone},
            {"foot", "lateral malleolus-head metatarsal II", 0.0145, 0.50, 0.475, kNone, kNone},
            {"leg", "femoral condyles-medial malleolus", 0.0465, 0.433, 0.302, kNone, kNone},
            {"thigh", "greater trochanter-femoral condyles", 0.100, 0.433, 0.323, kNone, kNone},
            {"foot_leg", "femoral condyles-medial malleolus", 0.061, 0.606, 0.416, kNone, kNone},
            {"total_leg", "greater trochanter-medial malleolus", 0.161, 0.447, 0.326, kNone, kNone},
            {"head_neck", "C7-T1 and first rib-ear canal", 0.081, 1.000, 0.495, kNone, kNone},
            {"thorax", "C7-T1-T12-L1 and diaphragm", 0.216, 0.82, kNone, kNone, kNone},
            {"abdomen", "T12-L1-L4-L5", 0.139, 0.44, kNone, kNone, kNone},
            {"pelvis", "L4-L5-greater trochanter", 0.142, 0.105, kNone, kNone, kNone},
            {"thorax_abdomen", "C7-T1-L4-L5", 0.355, 0.63, kNone, kNone, kNone},
            {"abdomen_pelvis", "T12-L1-greater trochanter", 0.281, 0.27, kNone, kNone, kNone},
            {"trunk", "greater trochanter-glenohumeral joint", 0.497, 0.50, kNone, kNone, kNone},
            {"trunk_head_neck", "greater trochanter-glenohumeral joint", 0.578, 0.66, 0.503, kNone, kNone},
            {"hat", "greater trochanter-glenohumeral joint", 0.678, 0.626, 0.496, kNone, kNone},
        }};
    return table;
}

// de Leva, P. (1996). Adjustments to Zatsiorsky-Seluyanov's segment inertia parameters.
// J. Biomechanics 29(9), 1223-1230, Table 4 (and the alternative endpoints of its text).
// Radii: de Leva's "transverse" axis is the medio-lateral one (flexion-extension) and his
// "sagittal" axis the antero-posterior one, as the trunk's and head's values show (the trunk
// is wider than deep, so its sagittal-axis radius is the larger; the head deeper than wide,
// so its transverse-axis radius is).
constexpr const char* kDeLevaSource =
    "de Leva, P. (1996), Adjustments to Zatsiorsky-Seluyanov's segment inertia parameters, "
    "J. Biomechanics 29(9):1223-1230, Table 4";
constexpr const char* kDeLevaNote =
    "landmarks: VERT vertex, MIDG mid-gonion, CERV C7, SUPR suprasternale, XYPH xyphion, OMPH "
    "omphalion, MIDH mid-hip joint centres, SJC/EJC/WJC/HJC/KJC/AJC joint centres, MET3 third "
    "metacarpale, DAC3 third dactylion, STYL ulnar styloid, LMAL lateral malleolus, SPHY "
    "sphyrion, HEEL, TTIP tip of the longest toe; radii: flexion = de Leva's transverse, "
    "abduction = his sagittal, long = his longitudinal";

const SegmentTable& de_leva_male_table() {
    static const SegmentTable table{
        "de_leva_male", kDeLevaSource, kDeLevaNote,
        {
            // name, endpoints, mass, CM, r transverse (flexion), r sagittal, r longitudinal
            {"head", "VERT-MIDG", 0.0694, 0.5976, 0.376, 0.362, 0.312},
            {"trunk", "SUPR-MIDH", 0.4346, 0.4486, 0.347, 0.372, 0.191},
            {"upper_trunk", "SUPR-XYPH", 0.1596, 0.2999, 0.454, 0.716, 0.659},
            {"middle_trunk", "XYPH-OMPH", 0.1633, 0.4502, 0.383, 0.482, 0.468},
            {"lower_trunk", "OMPH-MIDH", 0.1117, 0.6115, 0.551, 0.615, 0.587},
            {"upper_arm", "SJC-EJC", 0.0271, 0.5772, 0.269, 0.285, 0.158},
            {"forearm", "EJC-WJC", 0.0162, 0.4574, 0.265, 0.276, 0.121},
            {"hand", "WJC-MET3", 0.0061, 0.7900, 0.513, 0.628, 0.401},
            {"thigh", "HJC-KJC", 0.1416, 0.4095, 0.329, 0.329, 0.149},
            {"shank", "KJC-AJC", 0.0433, 0.4395, 0.246, 0.251, 0.102},
            {"foot", "HEEL-TTIP", 0.0137, 0.4415, 0.245, 0.257, 0.124},
            {"head_vert_cerv", "VERT-CERV", 0.0694, 0.5002, 0.315, 0.303, 0.261},
            {"trunk_cerv_midh", "CERV-MIDH", 0.4346, 0.5138, 0.306, 0.328, 0.169},
            {"trunk_mids_midh", "MIDS-MIDH", 0.4346, 0.4310, 0.358, 0.384, 0.197},
            {"upper_trunk_cerv_xyph", "CERV-XYPH", 0.1596, 0.5066, 0.320, 0.505, 0.465},
            {"forearm_ejc_styl", "EJC-STYL", 0.0162, 0.4608, 0.267, 0.278, 0.122},
            {"hand_wjc_dac3", "WJC-DAC3", 0.0061, 0.3624, 0.235, 0.288, 0.184},
            {"hand_styl_dac3", "STYL-DAC3", 0.0061, 0.3691, 0.233, 0.285, 0.182},
            {"hand_styl_met3", "STYL-MET3", 0.0061, 0.7948, 0.502, 0.614, 0.392},
            {"shank_kjc_lmal", "KJC-LMAL", 0.0433, 0.4459, 0.249, 0.255, 0.103},
            {"shank_kjc_sphy", "KJC-SPHY", 0.0433, 0.4524, 0.253, 0.258, 0.105},
        }};
    return table;
}

const SegmentTable& de_leva_female_table() {
    static const SegmentTable table{
        "de_leva_female", kDeLevaSource, kDeLevaNote,
        {
            {"head", "VERT-MIDG", 0.0668, 0.5894, 0.359, 0.330, 0.318},
            {"trunk", "SUPR-MIDH", 0.4257, 0.4151, 0.339, 0.357, 0.171},
            {"upper_trunk", "SUPR-XYPH", 0.1545, 0.2077, 0.502, 0.746, 0.718},
            {"middle_trunk", "XYPH-OMPH", 0.1465, 0.4512, 0.354, 0.433, 0.415},
            {"lower_trunk", "OMPH-MIDH", 0.1247, 0.4920, 0.402, 0.433, 0.444},
            {"upper_arm", "SJC-EJC", 0.0255, 0.5754, 0.260, 0.278, 0.148},
            {"forearm", "EJC-WJC", 0.0138, 0.4559, 0.257, 0.261, 0.094},
            {"hand", "WJC-MET3", 0.0056, 0.7474, 0.454, 0.531, 0.335},
            {"thigh", "HJC-KJC", 0.1478, 0.3612, 0.364, 0.369, 0.162},
            {"shank", "KJC-AJC", 0.0481, 0.4352, 0.263, 0.267, 0.092},
            {"foot", "HEEL-TTIP", 0.0129, 0.4014, 0.279, 0.299, 0.139},
            {"head_vert_cerv", "VERT-CERV", 0.0668, 0.4841, 0.295, 0.271, 0.261},
            {"trunk_cerv_midh", "CERV-MIDH", 0.4257, 0.4964, 0.292, 0.307, 0.147},
            {"trunk_mids_midh", "MIDS-MIDH", 0.4257, 0.3782, 0.361, 0.379, 0.182},
            {"upper_trunk_cerv_xyph", "CERV-XYPH", 0.1545, 0.5050, 0.314, 0.466, 0.449},
            {"forearm_ejc_styl", "EJC-STYL", 0.0138, 0.4592, 0.259, 0.263, 0.095},
            {"hand_wjc_dac3", "WJC-DAC3", 0.0056, 0.3427, 0.208, 0.244, 0.154},
            {"hand_styl_dac3", "STYL-DAC3", 0.0056, 0.3502, 0.206, 0.241, 0.152},
            {"hand_styl_met3", "STYL-MET3", 0.0056, 0.7534, 0.443, 0.519, 0.327},
            {"shank_kjc_lmal", "KJC-LMAL", 0.0481, 0.4416, 0.267, 0.271, 0.093},
            {"shank_kjc_sphy", "KJC-SPHY", 0.0481, 0.4481, 0.271, 0.275, 0.094},
        }};
    return table;
}

std::string fraction(double v) {
    if (std::isnan(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

}  // namespace

std::vector<std::string_view> segment_table_keys() {
    return {"winter", "de_leva_male", "de_leva_female"};
}

const SegmentTable& segment_table(std::string_view key) {
    if (key == "winter") return winter_table();
    if (key == "de_leva_male") return de_leva_male_table();
    if (key == "de_leva_female") return de_leva_female_table();
    throw ArgumentError("segment_table(): no table '" + std::string(key) +
                        "'; use winter, de_leva_male or de_leva_female");
}

SegmentParameters calc_segment_parameters(const SegmentTable& table, std::string_view segment,
                                          double body_mass, double length) {
    const SegmentRow* row = nullptr;
    for (const auto& r : table.rows)
        if (r.name == segment) row = &r;
    if (!row) {
        std::string list;
        for (const auto& r : table.rows) list += (list.empty() ? "" : ", ") + std::string(r.name);
        throw ArgumentError("calc_segment_parameters(): the table '" + std::string(table.key) +
                            "' has no segment '" + std::string(segment) + "'; its segments are: " + list);
    }
    if (!(body_mass > 0) || !(length > 0))
        throw ArgumentError("calc_segment_parameters(): segment '" + std::string(segment) +
                            "' with body mass " + fraction(body_mass) + " kg and length " +
                            fraction(length) + " m; both must be positive");
    SegmentParameters p;
    p.name = std::string(segment);
    p.mass = row->mass_fraction * body_mass;
    p.length = length;
    p.com_distance = row->com_fraction * length;
    // I = m (rho L)^2; NaN where the table gives no radius
    const double rho_L = row->rg_flexion * length;
    p.inertia_flexion = p.mass * rho_L * rho_L;
    return p;
}

std::string format_segment_table(const SegmentTable& table) {
    std::string out = "segment table " + std::string(table.key) + "\n  source: " +
                      std::string(table.source) + "\n  note: " + std::string(table.note) +
                      "\n  segment (proximal-distal): mass/body, CM/length from proximal, "
                      "radius of gyration/length (flexion, abduction, long)\n";
    for (const auto& r : table.rows)
        out += "  " + std::string(r.name) + " (" + std::string(r.endpoints) + "): " +
               fraction(r.mass_fraction) + ", " + fraction(r.com_fraction) + ", " +
               fraction(r.rg_flexion) + ", " + fraction(r.rg_abduction) + ", " +
               fraction(r.rg_long) + "\n";
    return out;
}

}  // namespace alembert
