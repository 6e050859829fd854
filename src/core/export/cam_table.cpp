#include "export/cam_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <optional>
#include <string_view>

#include "common/angles.h"
#include "export/free_text.h"
#include "export/number_text.h"
#include "follower/follower.h"

namespace cam {

namespace {

constexpr double kRadPerDeg = kPi / 180.0;

/// The lift and its derivatives per radian made per master degree: times (π/180)^k.
std::array<double, 4> perDegree(const std::array<double, 4>& perRad) {
    return {perRad[0], perRad[1] * kRadPerDeg, perRad[2] * kRadPerDeg * kRadPerDeg,
            perRad[3] * kRadPerDeg * kRadPerDeg * kRadPerDeg};
}

/// 360·i/N exactly for the row.
double masterAt(std::size_t i, std::size_t points) {
    return 360.0 * static_cast<double>(i) / static_cast<double>(points);
}

}  // namespace

std::vector<CamKnot> camKnots(const FollowerModel& model, std::size_t points) {
    std::vector<CamKnot> knots(points);
    for (std::size_t i = 0; i < points; ++i) {
        const double deg = masterAt(i, points);
        const auto lift = perDegree(model.liftPhi(model.at(degToRad(deg), 1.0)));
        knots[i] = {deg, lift[0], lift[1], lift[2], lift[3]};
    }
    return knots;
}

std::vector<CamKnot> camKnots(const CamMotion& motion, std::size_t points) {
    std::vector<CamKnot> knots(points);
    for (std::size_t i = 0; i < points; ++i) {
        const double deg = masterAt(i, points);
        const auto lift = motion.at(deg);
        knots[i] = {deg, lift[0], lift[1], lift[2], lift[3]};
    }
    return knots;
}

CamMotion lawMotion(const MotionDesign& design, bool armDegrees) {
    return {[design](double deg) { return perDegree(design.liftAt(degToRad(deg))); }, armDegrees,
            CamTableSource::Law};
}

Result<CamMotion> contourMotion(const Contour& contour, const FollowerSpec& follower) {
    auto model = FollowerModel::build(contour, follower);
    if (!model.ok()) return model.errors();
    auto shared = std::make_shared<const FollowerModel>(std::move(model).value());
    return CamMotion{
        [shared](double deg) { return perDegree(shared->liftPhi(shared->at(degToRad(deg), 1.0))); },
        follower.motion == FollowerMotion::Oscillating, CamTableSource::Contour};
}

namespace {

void appendRow(std::string& out, std::initializer_list<double> values) {
    bool first = true;
    for (double v : values) {
        if (!first) out += ',';
        first = false;
        appendExact(out, v);
    }
    out += '\n';
}

/// What every writer needs besides the knots.
struct TableContext {
    const CamTableOptions& options;
    bool arm;               ///< the slave is a swinging arm's angle in degrees
    CamTableSource source;  ///< law or contour
    const CamCharacteristics& characteristics;
};

const char* sourceName(CamTableSource source) {
    return source == CamTableSource::Law ? "law" : "contour";
}

/// The characteristics as lines of text, each begun with `prefix` and ended with `suffix`:
/// "position min=0 at_deg=0 max=10 at_deg=120" and so on.
std::string characteristicLines(const CamCharacteristics& c, const std::string& prefix,
                                const std::string& suffix, bool arm) {
    const auto line = [&](const char* what, const CamExtreme& lo, const CamExtreme& hi) {
        std::string out = prefix + what + " min=";
        appendExact(out, lo.value);
        out += " at_deg=";
        appendExact(out, lo.atDeg);
        out += " max=";
        appendExact(out, hi.value);
        out += " at_deg=";
        appendExact(out, hi.atDeg);
        return out + suffix + "\n";
    };
    std::string out = prefix;
    out += arm ? "characteristics of the motion (deg of swing per master deg^k, every 0.01 deg):"
               : "characteristics of the motion (mm per master deg^k, every 0.01 deg):";
    out += suffix + "\n";
    out += line("position", c.positionMin, c.positionMax);
    out += line("velocity", c.velocityMin, c.velocityMax);
    out += line("acceleration", c.accelerationMin, c.accelerationMax);
    out += line("jerk", c.jerkMin, c.jerkMax);
    return out;
}

std::string csvTable(const std::vector<CamKnot>& knots, const TableContext& context) {
    const auto n = static_cast<double>(knots.size());
    std::string out = "# camwright cam table";
    // The name is free text: one line, no formula cells (export/free_text.h).
    if (!context.options.name.empty()) out += " of " + csvCommentText(context.options.name);
    if (context.source == CamTableSource::Law) {
        out += context.arm ? ": master angle -> arm angle swung away from the cam as designed "
                             "(deg)\n"
                           : ": master angle -> follower lift as designed\n";
    } else {
        out += context.arm ? ": master angle -> arm angle swung away from the cam (deg)\n"
                           : ": master angle -> follower lift s(phi) - min s\n";
    }
    out += "# master_start_deg=0\n# master_step_deg=";
    appendExact(out, 360.0 / n);
    out += "\n# points=" + std::to_string(knots.size()) + "\n# periodic=true\n# slave=";
    out += context.arm ? "lift_deg\n" : "lift_mm\n";
    out += std::string("# source=") + sourceName(context.source) + "\n";
    out += characteristicLines(context.characteristics, "# ", "", context.arm);
    out += "master_deg,position,velocity_per_deg,acceleration_per_deg2\n";
    for (const CamKnot& k : knots)
        appendRow(out, {k.masterDeg, k.position, k.velocity, k.acceleration});
    return out;
}

/// Words an identifier of ours must not be, compared without regard to case as IEC 61131-3
/// does: the keywords of its third edition (Annex C), its elementary and generic data types,
/// the operators of its Instruction List, CODESYS's own keywords and operators, and the two
/// types the table declares.
constexpr std::string_view kReservedWords[] = {"ABSTRACT",
                                               "ACTION",
                                               "ADD",
                                               "ADR",
                                               "AND",
                                               "AND_THEN",
                                               "ANDN",
                                               "ANY",
                                               "ANY_BIT",
                                               "ANY_CHAR",
                                               "ANY_CHARS",
                                               "ANY_DATE",
                                               "ANY_DERIVED",
                                               "ANY_DURATION",
                                               "ANY_ELEMENTARY",
                                               "ANY_INT",
                                               "ANY_MAGNITUDE",
                                               "ANY_NUM",
                                               "ANY_REAL",
                                               "ANY_SIGNED",
                                               "ANY_STRING",
                                               "ANY_UNSIGNED",
                                               "ARRAY",
                                               "AT",
                                               "BITADR",
                                               "BOOL",
                                               "BY",
                                               "BYTE",
                                               "CAL",
                                               "CALC",
                                               "CALCN",
                                               "CASE",
                                               "CHAR",
                                               "CLASS",
                                               "CONFIGURATION",
                                               "CONSTANT",
                                               "CONTINUE",
                                               "D",
                                               "DATE",
                                               "DATE_AND_TIME",
                                               "DINT",
                                               "DIV",
                                               "DO",
                                               "DT",
                                               "DWORD",
                                               "ELSE",
                                               "ELSIF",
                                               "EN",
                                               "END_ACTION",
                                               "END_CASE",
                                               "END_CLASS",
                                               "END_CONFIGURATION",
                                               "END_FOR",
                                               "END_FUNCTION",
                                               "END_FUNCTION_BLOCK",
                                               "END_IF",
                                               "END_INTERFACE",
                                               "END_METHOD",
                                               "END_NAMESPACE",
                                               "END_PROGRAM",
                                               "END_PROPERTY",
                                               "END_REPEAT",
                                               "END_RESOURCE",
                                               "END_STEP",
                                               "END_STRUCT",
                                               "END_TRANSITION",
                                               "END_TYPE",
                                               "END_UNION",
                                               "END_VAR",
                                               "END_WHILE",
                                               "ENO",
                                               "EQ",
                                               "EXIT",
                                               "EXTENDS",
                                               "F_EDGE",
                                               "FALSE",
                                               "FINAL",
                                               "FOR",
                                               "FROM",
                                               "FUNCTION",
                                               "FUNCTION_BLOCK",
                                               "GE",
                                               "GT",
                                               "IF",
                                               "IMPLEMENTS",
                                               "INI",
                                               "INITIAL_STEP",
                                               "INT",
                                               "INTERFACE",
                                               "INTERNAL",
                                               "INTERVAL",
                                               "JMP",
                                               "JMPC",
                                               "JMPCN",
                                               "L",
                                               "LD",
                                               "LDATE",
                                               "LDATE_AND_TIME",
                                               "LDN",
                                               "LDT",
                                               "LE",
                                               "LINT",
                                               "LREAL",
                                               "LT",
                                               "LTIME",
                                               "LTIME_OF_DAY",
                                               "LTOD",
                                               "LWORD",
                                               "MC_CAM_REF",
                                               "MC_MOTIONFUNCTIONPOINT",
                                               "METHOD",
                                               "MOD",
                                               "MUL",
                                               "N",
                                               "NAMESPACE",
                                               "NE",
                                               "NON_RETAIN",
                                               "NOT",
                                               "NULL",
                                               "OF",
                                               "ON",
                                               "OR",
                                               "OR_ELSE",
                                               "ORN",
                                               "OVERLAP",
                                               "OVERRIDE",
                                               "P",
                                               "PERSISTENT",
                                               "POINTER",
                                               "PRIORITY",
                                               "PRIVATE",
                                               "PROGRAM",
                                               "PROPERTY",
                                               "PROTECTED",
                                               "PUBLIC",
                                               "R",
                                               "R_EDGE",
                                               "READ_ONLY",
                                               "READ_WRITE",
                                               "REAL",
                                               "REF",
                                               "REF_TO",
                                               "REFERENCE",
                                               "REPEAT",
                                               "RESOURCE",
                                               "RET",
                                               "RETAIN",
                                               "RETC",
                                               "RETCN",
                                               "RETURN",
                                               "S",
                                               "SINGLE",
                                               "SINT",
                                               "SIZEOF",
                                               "SMC_CAMXYVA",
                                               "ST",
                                               "STEP",
                                               "STN",
                                               "STRING",
                                               "STRUCT",
                                               "SUB",
                                               "SUPER",
                                               "T",
                                               "TASK",
                                               "THEN",
                                               "THIS",
                                               "TIME",
                                               "TIME_OF_DAY",
                                               "TO",
                                               "TOD",
                                               "TRANSITION",
                                               "TRUE",
                                               "TYPE",
                                               "UDINT",
                                               "UINT",
                                               "ULINT",
                                               "UNION",
                                               "UNTIL",
                                               "USINT",
                                               "USING",
                                               "VAR",
                                               "VAR_ACCESS",
                                               "VAR_CONFIG",
                                               "VAR_EXTERNAL",
                                               "VAR_GLOBAL",
                                               "VAR_IN_OUT",
                                               "VAR_INPUT",
                                               "VAR_INST",
                                               "VAR_OUTPUT",
                                               "VAR_STAT",
                                               "VAR_TEMP",
                                               "WCHAR",
                                               "WHILE",
                                               "WITH",
                                               "WORD",
                                               "WSTRING",
                                               "XOR",
                                               "XORN"};

/// The longest identifier made of a name (the knots' array adds "_knots").
constexpr std::size_t kMaxIdentifier = 64;

bool isReserved(const std::string& id) {
    std::string upper;
    for (char c : id) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return std::find(std::begin(kReservedWords), std::end(kReservedWords), upper) !=
           std::end(kReservedWords);
}

/// The name as an IEC 61131-3 identifier (letter {[_] (letter | digit)}): ASCII letters and
/// digits kept, every run of other characters one underscore, none at either end, at most
/// kMaxIdentifier characters; "cam_" in front of one that would begin with a digit or be a
/// reserved word ("cam" when nothing is left).
std::string identifier(const std::string& name) {
    std::string id;
    for (unsigned char c : name) {
        if (id.size() >= kMaxIdentifier) break;
        if (c < 128 && std::isalnum(c)) {
            id += static_cast<char>(c);
        } else if (!id.empty() && id.back() != '_') {
            id += '_';
        }
    }
    while (!id.empty() && id.back() == '_') id.pop_back();
    if (id.empty()) return "cam";
    if (std::isdigit(static_cast<unsigned char>(id.front())) || isReserved(id)) id = "cam_" + id;
    return id;
}

/// The text of a comment: "(*" and "*)" cannot appear inside one.
std::string commentText(std::string text) {
    for (std::size_t i = 0; i + 1 < text.size(); ++i) {
        if ((text[i] == '(' && text[i + 1] == '*') || (text[i] == '*' && text[i + 1] == ')')) {
            text[i] = ' ';
        }
    }
    return text;
}

/// An LREAL literal of IEC 61131-3: exact and shortest, always with a decimal point ("45.0",
/// "1.0e-05").
void appendReal(std::string& out, double value) {
    std::string text;
    appendExact(text, value);
    if (text.find('.') == std::string::npos) {
        const std::size_t e = text.find('e');
        text.insert(e == std::string::npos ? text.size() : e, ".0");
    }
    out += text;
}

void appendKnot(std::string& out, const CamKnot& k, bool last) {
    out += "        (dX := ";
    appendReal(out, k.masterDeg);
    out += ", dY := ";
    appendReal(out, k.position);
    out += ", dV := ";
    appendReal(out, k.velocity);
    out += ", dA := ";
    appendReal(out, k.acceleration);
    out += last ? ")\n" : "),\n";
}

/// The comment block's opening lines: what the master and the slave are.
std::string stHeading(const char* title, const std::vector<CamKnot>& knots,
                      const TableContext& context, const char* units) {
    std::string out = std::string("(* ") + title;
    if (!context.options.name.empty()) out += ": " + commentText(oneLine(context.options.name));
    out += " *)\n(* master: cam angle in degrees, 0 .. 360, periodic, " +
           std::to_string(knots.size()) + " points; slave: ";
    out += context.arm ? "the arm's angle swung away from the cam" : "follower lift";
    out += context.source == CamTableSource::Law ? " as designed (its motion law)"
                                                 : " on the contour (s(phi) - min s)";
    out += context.arm ? ", in deg;\n   " : ", in mm;\n   ";
    out += units;
    out += " *)\n";
    out += characteristicLines(context.characteristics, "(* ", " *)", context.arm);
    return out;
}

std::string codesysTable(const std::vector<CamKnot>& knots, const TableContext& context) {
    const std::string id = identifier(context.options.name);
    const std::size_t n = knots.size();
    std::string out = stHeading(
        "Camwright electronic cam", knots, context,
        context.arm ? "dV in deg/deg, dA in deg/deg^2. Knots for SMC_CAMXYVA, interpolated by\n"
                      "   fifth-order polynomials (byType 3). The knot at 360 deg repeats the one "
                      "at 0."
                    : "dV in mm/deg, dA in mm/deg^2. Knots for SMC_CAMXYVA, interpolated by\n"
                      "   fifth-order polynomials (byType 3). The knot at 360 deg repeats the one "
                      "at 0.");
    out += "VAR_GLOBAL\n";
    out += "    " + id + "_knots : ARRAY[0.." + std::to_string(n) + "] OF SMC_CAMXYVA := [\n";
    for (const CamKnot& k : knots) appendKnot(out, k, false);
    CamKnot closing = knots.front();
    closing.masterDeg = 360.0;
    appendKnot(out, closing, true);
    out += "    ];\n";
    out += "    " + id +
           " : MC_CAM_REF := (xStart := 0.0, xEnd := 360.0, byType := 3, byVarType := 6,\n";
    out += "        nElements := " + std::to_string(n + 1) + ", nTappets := 0, pce := ADR(" + id +
           "_knots));\n";
    out += "END_VAR\n";
    return out;
}

/// Beckhoff TwinCAT 3 NC camming (TF5050), "MC_MotionFunctionPoint",
/// https://infosys.beckhoff.com/content/1033/tf5050_tc3_nc_camming/1003721995.html: PointIndex
/// strictly increasing from 1 without gaps; FunctionType the function from this point to the
/// next; RelIndexNextPoint usually 1; MasterPos, SlavePos, SlaveVelo, SlaveAcc, SlaveJerk (the
/// slave's position and its first three derivatives over the master's). "MC_MotionFunctionType",
/// https://infosys.beckhoff.com/content/1033/tf5050_tc3_nc_camming/1003744011.html:
/// MOTIONFUNCTYPE_POLYNOM5_MM = 15, a polynomial of order 5 from motion to motion (it matches
/// position, velocity and acceleration at both points). "MC_MotionPointType",
/// https://infosys.beckhoff.com/content/1033/tcplclibmc2_camming/460455947.html:
/// MOTIONPOINTTYPE_MOTION = 16#0008, a motion point.
std::string beckhoffTable(const std::vector<CamKnot>& knots, const TableContext& context) {
    const std::string id = identifier(context.options.name);
    const std::size_t n = knots.size();
    std::string out = stHeading(
        "Camwright electronic cam for TwinCAT NC camming", knots, context,
        context.arm ? "SlaveVelo, SlaveAcc, SlaveJerk per master degree (deg/deg, deg/deg^2,\n"
                      "   deg/deg^3): the master axis in degrees. POLYNOM5_MM between the points;\n"
                      "   the point at 360 deg repeats the one at 0."
                    : "SlaveVelo, SlaveAcc, SlaveJerk per master degree (mm/deg, mm/deg^2,\n"
                      "   mm/deg^3): the master axis in degrees. POLYNOM5_MM between the points;\n"
                      "   the point at 360 deg repeats the one at 0.");
    out += "VAR_GLOBAL\n";
    out +=
        "    " + id + " : ARRAY[1.." + std::to_string(n + 1) + "] OF MC_MotionFunctionPoint := [\n";
    for (std::size_t i = 0; i <= n; ++i) {
        CamKnot k = knots[i % n];
        if (i == n) k.masterDeg = 360.0;
        out += "        (PointIndex := " + std::to_string(i + 1) +
               ", FunctionType := MOTIONFUNCTYPE_POLYNOM5_MM, PointType := "
               "MOTIONPOINTTYPE_MOTION,\n         RelIndexNextPoint := 1, MasterPos := ";
        appendReal(out, k.masterDeg);
        out += ", SlavePos := ";
        appendReal(out, k.position);
        out += ",\n         SlaveVelo := ";
        appendReal(out, k.velocity);
        out += ", SlaveAcc := ";
        appendReal(out, k.acceleration);
        out += ", SlaveJerk := ";
        appendReal(out, k.jerk);
        out += i == n ? ")\n" : "),\n";
    }
    out += "    ];\nEND_VAR\n";
    return out;
}

/// The value as a REAL (IEEE single precision) holds it.
double asReal(double value) { return static_cast<double>(static_cast<float>(value)); }

/// A REAL literal of Logix: the shortest text that reads back as the same single-precision
/// value, always with a decimal point.
void appendLogixReal(std::string& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value));
    std::string text(buffer, result.ptr);
    if (text.find('.') == std::string::npos) {
        const std::size_t e = text.find('e');
        text.insert(e == std::string::npos ? text.size() : e, ".0");
    }
    out += text;
}

/// A Logix tag name (letters, digits, single underscores, at most 40 characters): the IEC
/// identifier, shortened to leave room for "_profile".
std::string logixName(const std::string& name) {
    std::string id = identifier(name);
    // Logix's own data types for cams: "cam_" in front, as identifier() does for keywords (and
    // its name for an empty one, "cam").
    std::string upper;
    for (char c : id) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper == "CAM" || upper == "CAM_PROFILE") id = "cam_" + id;
    if (id.size() > 32) id.resize(32);
    while (!id.empty() && id.back() == '_') id.pop_back();
    return id;
}

/// Rockwell Logix 5000, "Logix 5000 Controllers Motion Instructions", MOTION-RM002H-EN-P
/// (February 2018), chapter 10, "Overview of motion-related data types": the CAM data type is
/// Master : REAL, Slave : REAL, SegmentType : DINT (0 linear, 1 cubic), the type of
/// interpolation from this element to the next; an MCCP instruction calculates the CAM_PROFILE
/// from a CAM array.
std::string rockwellTable(const std::vector<CamKnot>& knots, const TableContext& context) {
    const std::string id = logixName(context.options.name);
    const std::size_t n = knots.size();
    std::string out = stHeading(
        "Camwright electronic cam for a Logix position cam (MAPC)", knots, context,
        "Master and Slave are REAL (single precision); SegmentType 1: cubic.\n"
        "   Structured Text filling a tag of data type CAM[N+1]; calculate its CAM_PROFILE with\n"
        "   MCCP, start and end slope as given below. The point at 360 deg repeats the one at 0.");
    out += "(* tag: " + id + " : CAM[" + std::to_string(n + 1) + "]; profile: " + id +
           "_profile : CAM_PROFILE[" + std::to_string(n + 1) + "] *)\n";
    out += "(* MCCP StartSlope := ";
    appendLogixReal(out, knots.front().velocity);
    out += ", EndSlope := ";
    appendLogixReal(out, knots.front().velocity);
    out += " (per master degree) *)\n";
    for (std::size_t i = 0; i <= n; ++i) {
        const CamKnot& k = knots[i % n];
        const std::string element = id + "[" + std::to_string(i) + "]";
        out += element + ".Master := ";
        appendLogixReal(out, i == n ? 360.0 : k.masterDeg);
        out += "; " + element + ".Slave := ";
        appendLogixReal(out, k.position);
        out += "; " + element + ".SegmentType := 1;\n";
    }
    return out;
}

/// Kollmorgen Automation Suite, KAS IDE help, "Import Cam Profile": a user-defined cam profile
/// in CSV is `CYCLIC;YES;`, `TABLE_BEGIN;;`, rows `X;Y;SPLINE`, `TABLE_END;;`, at least 4
/// spline segments; X and Y are normalised by their largest values on import, then scaled by
/// the profile's master and slave scale. "CAM Profile Segments",
/// https://webhelp.kollmorgen.com/kas/content/4.Using-KAS-IDE/Create-Project-Advanced/Cam-Profile/CAM-Profile-Segments.htm:
/// a spline segment is a third-order polynomial through the given positions. The format has no
/// comments: nothing but the points is written.
std::string kollmorgenTable(const std::vector<CamKnot>& knots) {
    const std::size_t n = knots.size();
    std::string out = "CYCLIC;YES;\nTABLE_BEGIN;;\n";
    for (std::size_t i = 0; i <= n; ++i) {
        appendExact(out, i == n ? 360.0 : knots[i].masterDeg);
        out += ';';
        appendExact(out, knots[i % n].position);
        out += ";SPLINE\n";
    }
    out += "TABLE_END;;\n";
    return out;
}

// The controllers' interpolation.

/// Position, velocity and acceleration of an interpolant at a master angle.
using Pva = std::array<double, 3>;

/// The quintic through two knots matching p, v, a at both (SMC_CAMXYVA, POLYNOM5_MM), at x.
Pva quintic(const CamKnot& k0, const CamKnot& k1, double x1, double x) {
    const double h = x1 - k0.masterDeg;
    const double t = (x - k0.masterDeg) / h;
    const double dp = k1.position - k0.position;
    const double v0 = h * k0.velocity, v1 = h * k1.velocity;
    const double a0 = h * h * k0.acceleration, a1 = h * h * k1.acceleration;
    const double c1 = v0, c2 = a0 / 2.0;
    const double c3 = 10.0 * dp - 6.0 * v0 - 4.0 * v1 - (3.0 * a0 - a1) / 2.0;
    const double c4 = -15.0 * dp + 8.0 * v0 + 7.0 * v1 + (3.0 * a0 - 2.0 * a1) / 2.0;
    const double c5 = 6.0 * dp - 3.0 * (v0 + v1) - (a0 - a1) / 2.0;
    const double p = k0.position + t * (c1 + t * (c2 + t * (c3 + t * (c4 + t * c5))));
    const double dpdt = c1 + t * (2.0 * c2 + t * (3.0 * c3 + t * (4.0 * c4 + t * 5.0 * c5)));
    const double d2pdt2 = 2.0 * c2 + t * (6.0 * c3 + t * (12.0 * c4 + t * 20.0 * c5));
    return {p, dpdt / h, d2pdt2 / (h * h)};
}

/// Solves sub[i]·x[i−1] + diag[i]·x[i] + sup[i]·x[i+1] = rhs[i] (the Thomas algorithm).
std::vector<double> solveTridiagonal(const std::vector<double>& sub, std::vector<double> diag,
                                     const std::vector<double>& sup, std::vector<double> rhs) {
    const std::size_t n = diag.size();
    for (std::size_t i = 1; i < n; ++i) {
        const double m = sub[i] / diag[i - 1];
        diag[i] -= m * sup[i - 1];
        rhs[i] -= m * rhs[i - 1];
    }
    std::vector<double> x(n);
    x[n - 1] = rhs[n - 1] / diag[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) x[i] = (rhs[i] - sup[i] * x[i + 1]) / diag[i];
    return x;
}

/// A C2 cubic spline through (xs, ys), held by its second derivatives m at the knots.
struct CubicSpline {
    std::vector<double> xs, ys, m;

    /// Clamped: first derivatives s0 and s1 at the two ends.
    static CubicSpline clamped(std::vector<double> xs, std::vector<double> ys, double s0,
                               double s1) {
        const std::size_t n = xs.size();
        std::vector<double> sub(n, 0.0), diag(n), sup(n, 0.0), rhs(n);
        const auto h = [&](std::size_t i) { return xs[i + 1] - xs[i]; };
        diag[0] = 2.0 * h(0);
        sup[0] = h(0);
        rhs[0] = 6.0 * ((ys[1] - ys[0]) / h(0) - s0);
        for (std::size_t i = 1; i + 1 < n; ++i) {
            sub[i] = h(i - 1);
            diag[i] = 2.0 * (h(i - 1) + h(i));
            sup[i] = h(i);
            rhs[i] = 6.0 * ((ys[i + 1] - ys[i]) / h(i) - (ys[i] - ys[i - 1]) / h(i - 1));
        }
        sub[n - 1] = h(n - 2);
        diag[n - 1] = 2.0 * h(n - 2);
        rhs[n - 1] = 6.0 * (s1 - (ys[n - 1] - ys[n - 2]) / h(n - 2));
        std::vector<double> m = solveTridiagonal(sub, diag, sup, rhs);
        return {std::move(xs), std::move(ys), std::move(m)};
    }

    /// Periodic: ys.back() == ys.front(), and slope and curvature agree at the ends (a cyclic
    /// system, solved by Sherman–Morrison around the Thomas algorithm).
    static CubicSpline periodic(std::vector<double> xs, std::vector<double> ys) {
        const std::size_t n = xs.size() - 1;  // unknowns m[0 .. n-1]; m[n] = m[0]
        const auto h = [&](std::size_t i) { return xs[i + 1] - xs[i]; };
        std::vector<double> sub(n), diag(n), sup(n), rhs(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t prev = (i + n - 1) % n;
            const double hp = h(prev), hi = h(i);
            sub[i] = hp;
            diag[i] = 2.0 * (hp + hi);
            sup[i] = hi;
            rhs[i] = 6.0 * ((ys[i + 1] - ys[i]) / hi - (ys[i] - ys[prev]) / hp);
        }
        // The corners A[0][n−1] = alpha = sub[0] and A[n−1][0] = beta = sup[n−1] made a
        // rank-one correction.
        const double alpha = sub[0], beta = sup[n - 1], gamma = -diag[0];
        std::vector<double> diag2 = diag, sub2 = sub, sup2 = sup;
        diag2[0] -= gamma;
        diag2[n - 1] -= alpha * beta / gamma;
        sub2[0] = 0.0;
        sup2[n - 1] = 0.0;
        const std::vector<double> x = solveTridiagonal(sub2, diag2, sup2, rhs);
        std::vector<double> u(n, 0.0);
        u[0] = gamma;
        u[n - 1] = beta;
        const std::vector<double> z = solveTridiagonal(sub2, diag2, sup2, u);
        const double fact =
            (x[0] + alpha * x[n - 1] / gamma) / (1.0 + z[0] + alpha * z[n - 1] / gamma);
        std::vector<double> m(n + 1);
        for (std::size_t i = 0; i < n; ++i) m[i] = x[i] - fact * z[i];
        m[n] = m[0];
        return {std::move(xs), std::move(ys), std::move(m)};
    }

    /// The spline of interval i at x.
    [[nodiscard]] Pva at(std::size_t i, double x) const {
        const double h = xs[i + 1] - xs[i];
        const double a = xs[i + 1] - x, b = x - xs[i];
        const double ca = ys[i] / h - m[i] * h / 6.0, cb = ys[i + 1] / h - m[i + 1] * h / 6.0;
        return {m[i] * a * a * a / (6.0 * h) + m[i + 1] * b * b * b / (6.0 * h) + ca * a + cb * b,
                -m[i] * a * a / (2.0 * h) + m[i + 1] * b * b / (2.0 * h) - ca + cb,
                m[i] * a / h + m[i + 1] * b / h};
    }
};

/// Samples per interval where the error is evaluated: the knot and 15 inside.
constexpr std::size_t kErrorSamples = 16;

struct InterpolationError {
    double position = 0.0, positionAtDeg = 0.0, velocity = 0.0, acceleration = 0.0;
};

/// The controller's interpolation of the knots against the motion, at x = 360·(16·i + k)/(16·N).
InterpolationError interpolationError(const CamMotion& motion, const std::vector<CamKnot>& knots,
                                      CamTableDialect dialect) {
    const std::size_t n = knots.size();
    std::optional<CubicSpline> spline;
    if (dialect == CamTableDialect::Rockwell || dialect == CamTableDialect::Kollmorgen) {
        // Rockwell's controller holds REALs: its spline goes through the rounded values.
        const bool real = dialect == CamTableDialect::Rockwell;
        std::vector<double> xs(n + 1), ys(n + 1);
        for (std::size_t i = 0; i <= n; ++i) {
            const double x = i == n ? 360.0 : knots[i].masterDeg;
            const double y = knots[i % n].position;
            xs[i] = real ? asReal(x) : x;
            ys[i] = real ? asReal(y) : y;
        }
        if (real) {
            const double slope = asReal(knots.front().velocity);
            spline = CubicSpline::clamped(std::move(xs), std::move(ys), slope, slope);
        } else {
            spline = CubicSpline::periodic(std::move(xs), std::move(ys));
        }
    }
    InterpolationError worst;
    const double total = static_cast<double>(kErrorSamples * n);
    for (std::size_t i = 0; i < n; ++i) {
        const CamKnot& next = knots[(i + 1) % n];
        const double x1 = i + 1 == n ? 360.0 : next.masterDeg;
        for (std::size_t k = 0; k < kErrorSamples; ++k) {
            const double x = 360.0 * static_cast<double>(kErrorSamples * i + k) / total;
            const auto exact = motion.at(x);
            const Pva got = spline ? spline->at(i, x) : quintic(knots[i], next, x1, x);
            const double dp = std::abs(got[0] - exact[0]);
            if (dp > worst.position) {
                worst.position = dp;
                worst.positionAtDeg = x;
            }
            worst.velocity = std::max(worst.velocity, std::abs(got[1] - exact[1]));
            worst.acceleration = std::max(worst.acceleration, std::abs(got[2] - exact[2]));
        }
    }
    return worst;
}

/// Samples of the characteristics: every 0.01°.
constexpr std::size_t kCharacteristicSamples = 36000;

CamCharacteristics characteristicsOf(const CamMotion& motion) {
    CamCharacteristics c;
    const std::array<CamExtreme*, 4> lo{&c.positionMin, &c.velocityMin, &c.accelerationMin,
                                        &c.jerkMin};
    const std::array<CamExtreme*, 4> hi{&c.positionMax, &c.velocityMax, &c.accelerationMax,
                                        &c.jerkMax};
    for (std::size_t j = 0; j < kCharacteristicSamples; ++j) {
        const double x = masterAt(j, kCharacteristicSamples);
        const auto values = motion.at(x);
        for (std::size_t d = 0; d < 4; ++d) {
            if (j == 0 || values[d] < lo[d]->value) *lo[d] = {values[d], x};
            if (j == 0 || values[d] > hi[d]->value) *hi[d] = {values[d], x};
        }
    }
    return c;
}

std::optional<Diagnostics> badPointCount(std::size_t points) {
    const auto n = static_cast<long long>(points);
    if (n >= kMinCamTablePoints && n <= kMaxCamTablePoints) return std::nullopt;
    return Diagnostics{
        Diagnostic::make(FieldPlace{Field::PointsOption}, DiagnosticCode::CamTablePoints,
                         {static_cast<double>(kMinCamTablePoints),
                          static_cast<double>(kMaxCamTablePoints), static_cast<double>(n)})};
}

CamTableReport reportOf(const CamMotion& motion, const std::vector<CamKnot>& knots,
                        CamTableDialect dialect) {
    const InterpolationError e = interpolationError(motion, knots, dialect);
    CamTableReport report;
    report.points = knots.size();
    report.interpolation = camTableInterpolation(dialect);
    report.positionError = e.position;
    report.positionErrorAtDeg = e.positionAtDeg;
    report.velocityError = e.velocity;
    report.accelerationError = e.acceleration;
    report.characteristics = characteristicsOf(motion);
    return report;
}

}  // namespace

const char* camTableInterpolation(CamTableDialect dialect) {
    switch (dialect) {
        case CamTableDialect::Rockwell:
            return "cubic-spline-clamped";
        case CamTableDialect::Kollmorgen:
            return "cubic-spline-periodic";
        case CamTableDialect::Csv:
        case CamTableDialect::Codesys:
        case CamTableDialect::Beckhoff:
            break;
    }
    return "quintic";
}

Result<CamTableReport> camTableReport(const CamMotion& motion, const CamTableOptions& options) {
    if (auto bad = badPointCount(options.points)) return *bad;
    return reportOf(motion, camKnots(motion, options.points), options.dialect);
}

std::optional<std::size_t> camTablePointsFor(const CamMotion& motion,
                                             const CamTableOptions& options, double toleranceMm) {
    const auto meets = [&](std::size_t n) {
        return interpolationError(motion, camKnots(motion, n), options.dialect).position <=
               toleranceMm;
    };
    // The error is not monotone in the count: it drops where knots fall on the motion's joints
    // (a law's jerk jumps there). Every count is tried from the smallest while that costs at
    // most kScanSamples evaluations of the motion, so such a count is found; beyond, doubling
    // and bisection find a count that meets the tolerance where one point fewer does not.
    constexpr std::size_t kScanSamples = 4'000'000;
    const auto most = static_cast<std::size_t>(kMaxCamTablePoints);
    auto n = static_cast<std::size_t>(kMinCamTablePoints);
    std::size_t spent = 0;
    for (; spent + kErrorSamples * n <= kScanSamples; ++n) {
        if (meets(n)) return n;
        spent += kErrorSamples * n;
    }
    std::size_t failed = n - 1;
    while (!meets(n)) {
        if (n == most) return std::nullopt;
        failed = n;
        n = std::min(2 * n, most);
    }
    // Here `failed` fails and n meets.
    while (n - failed > 1) {
        const std::size_t mid = failed + (n - failed) / 2;
        if (meets(mid)) {
            n = mid;
        } else {
            failed = mid;
        }
    }
    return n;
}

Result<CamTable> camTable(const CamMotion& motion, const CamTableOptions& options) {
    if (auto bad = badPointCount(options.points)) return *bad;
    const std::vector<CamKnot> knots = camKnots(motion, options.points);
    CamTable table;
    table.report = reportOf(motion, knots, options.dialect);
    const TableContext context{options, motion.armDegrees, motion.source,
                               table.report.characteristics};
    switch (options.dialect) {
        case CamTableDialect::Csv:
            table.text = csvTable(knots, context);
            break;
        case CamTableDialect::Codesys:
            table.text = codesysTable(knots, context);
            break;
        case CamTableDialect::Beckhoff:
            table.text = beckhoffTable(knots, context);
            break;
        case CamTableDialect::Rockwell:
            table.text = rockwellTable(knots, context);
            break;
        case CamTableDialect::Kollmorgen:
            table.text = kollmorgenTable(knots);
            break;
    }
    return table;
}

Result<std::string> camTableText(const Contour& contour, const CamTableOptions& options) {
    if (auto bad = badPointCount(options.points)) return *bad;
    auto motion = contourMotion(contour, options.follower);
    if (!motion.ok()) return motion.errors();
    auto table = camTable(motion.value(), options);
    if (!table.ok()) return table.errors();
    return std::move(table).value().text;
}

}  // namespace cam
