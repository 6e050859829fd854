#include "export/cam_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <string_view>

#include "common/angles.h"
#include "export/free_text.h"
#include "export/number_text.h"
#include "follower/follower.h"

namespace cam {

std::vector<CamKnot> camKnots(const FollowerModel& model, std::size_t points) {
    constexpr double perDeg = kPi / 180.0;
    std::vector<CamKnot> knots(points);
    for (std::size_t i = 0; i < points; ++i) {
        // 360·i/N exactly for the row, and the angle from it.
        const double deg = 360.0 * static_cast<double>(i) / static_cast<double>(points);
        const std::array<double, 4> lift = model.liftPhi(model.at(degToRad(deg), 1.0));
        knots[i] = {deg, lift[0], lift[1] * perDeg, lift[2] * perDeg * perDeg};
    }
    return knots;
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

std::string csvTable(const std::vector<CamKnot>& knots, const CamTableOptions& options) {
    const auto n = static_cast<double>(knots.size());
    std::string out = "# camwright cam table";
    // The name is free text: one line, no formula cells (export/free_text.h).
    if (!options.name.empty()) out += " of " + csvCommentText(options.name);
    const bool arm = options.follower.motion == FollowerMotion::Oscillating;
    out += arm ? ": master angle -> arm angle swung away from the cam (deg)\n"
               : ": master angle -> follower lift s(phi) - min s\n";
    out += "# master_start_deg=0\n# master_step_deg=";
    appendExact(out, 360.0 / n);
    out += "\n# points=" + std::to_string(knots.size()) + "\n# periodic=true\n# slave=";
    out += arm ? "lift_deg\n" : "lift_mm\n";
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

std::string codesysTable(const std::vector<CamKnot>& knots, const CamTableOptions& options) {
    const std::string id = identifier(options.name);
    const std::size_t n = knots.size();
    std::string out = "(* Camwright electronic cam";
    if (!options.name.empty()) out += ": " + commentText(oneLine(options.name));
    out +=
        options.follower.motion == FollowerMotion::Oscillating
            ? " *)\n(* master: cam angle in degrees, 0 .. 360, periodic; slave: the arm's angle\n"
              "   swung away from the cam, in deg; dV in deg/deg, dA in deg/deg^2. Knots for\n"
              "   SMC_CAMXYVA, interpolated\n"
            : " *)\n(* master: cam angle in degrees, 0 .. 360, periodic; slave: follower lift "
              "in mm\n   (s(phi) - min s); dV in mm/deg, dA in mm/deg^2. Knots for SMC_CAMXYVA, "
              "interpolated\n";
    out +=
        "   by fifth-order polynomials (byType 3). The knot at 360 deg repeats the one at 0. *)\n";
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

}  // namespace

Result<std::string> camTableText(const Contour& contour, const CamTableOptions& options) {
    const auto n = static_cast<long long>(options.points);
    if (n < kMinCamTablePoints || n > kMaxCamTablePoints) {
        return Diagnostics{
            Diagnostic::make(FieldPlace{Field::PointsOption}, DiagnosticCode::CamTablePoints,
                             {static_cast<double>(kMinCamTablePoints),
                              static_cast<double>(kMaxCamTablePoints), static_cast<double>(n)})};
    }
    auto model = FollowerModel::build(contour, options.follower);
    if (!model.ok()) return model.errors();
    const std::vector<CamKnot> knots = camKnots(model.value(), options.points);
    return options.dialect == CamTableDialect::Csv ? csvTable(knots, options)
                                                   : codesysTable(knots, options);
}

}  // namespace cam
