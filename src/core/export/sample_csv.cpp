#include "export/sample_csv.h"

#include <cmath>
#include <iterator>
#include <utility>

#include "common/angles.h"
#include "export/number_text.h"

namespace cam {

std::optional<Diagnostic> firstNonFiniteSample(const SampledTurn& turn) {
    const std::pair<const char*, const std::vector<double>*> columns[] = {
        {"t", &turn.t},        {"phi_deg", &turn.phi}, {"r", &turn.r},        {"x", &turn.x},
        {"y", &turn.y},        {"v_r", &turn.vR},      {"v_phi", &turn.vPhi}, {"v", &turn.v},
        {"a_r", &turn.aR},     {"a_phi", &turn.aPhi},  {"a", &turn.a},        {"j_r", &turn.jR},
        {"j_phi", &turn.jPhi}, {"j", &turn.j}};
    for (const auto& [name, values] : columns) {
        for (std::size_t k = 0; k < values->size(); ++k) {
            if (std::isfinite((*values)[k])) continue;
            return Diagnostic::make(SamplePlace{k, name}, DiagnosticCode::SampleNotFinite,
                                    {(*values)[k]});
        }
    }
    return std::nullopt;
}

void appendSampleCsvRow(std::string& out, const SampledTurn& turn, std::size_t k) {
    const double row[] = {
        turn.t[k],  radToDeg(turn.phi[k]), 0.0,       turn.r[k],  turn.x[k],    turn.y[k],
        turn.vR[k], turn.vPhi[k],          turn.v[k], turn.aR[k], turn.aPhi[k], turn.a[k],
        turn.jR[k], turn.jPhi[k],          turn.j[k]};
    for (std::size_t c = 0; c < std::size(row); ++c) {
        if (c > 0) out += ',';
        if (c == 2) {
            out += std::to_string(turn.segment[k]);
        } else {
            appendExact(out, row[c]);
        }
    }
    out += '\n';
}

std::string_view followerCsvColumns(const FollowerModel& follower) {
    return follower.oscillating() ? kArmCsvColumns : kFollowerCsvColumns;
}

void appendFollowerCsvColumns(std::string& out, const FollowerModel& follower,
                              const FollowerTurn& turn, std::size_t k) {
    const double s = turn.s[k];
    const double q = follower.oscillating() ? radToDeg(s) : s;
    for (const double v : {q, follower.liftOf(s), turn.v[k], turn.a[k], turn.j[k],
                           radToDeg(turn.pressureAngle[k]), turn.rhoProfile[k], turn.rhoPitch[k]}) {
        out += ',';
        if (std::isfinite(v)) appendExact(out, v);  // an empty cell: straight, infinite radius
    }
}

std::string_view forcesCsvColumns(const ForceModel& model) {
    return model.swinging ? kArmForcesCsvColumns : kForcesCsvColumns;
}

void appendForcesCsvColumns(std::string& out, const ForceModel& model, const ForceTurn& forces,
                            const FollowerTurn& turn, std::size_t k, double omega) {
    const ForcePoint f = forces.point(k, model, turn, omega);
    const auto cell = [&out](double v) {
        out += ',';
        if (std::isfinite(v)) appendExact(out, v);  // an empty cell: no contact stress
    };
    cell(f.load);
    cell(f.normal);
    if (!model.swinging) cell(f.lateral);
    cell(f.torque);
    cell(f.power);
    cell(f.stress);
}

Result<std::string> sampleCsv(const Contour& contour, double omega, std::size_t points,
                              const FollowerModel* follower, const ForceModel* forces) {
    if (points < 1) {
        return Diagnostics{Diagnostic::make(FieldPlace{Field::Points}, DiagnosticCode::NoPoints)};
    }
    SampledTurn turn;
    sampleTurn(contour, omega, points, turn);
    if (auto problem = firstNonFiniteSample(turn)) return Diagnostics{std::move(*problem)};
    std::string text(kSampleCsvHeader);
    FollowerTurn followerTurn;
    if (follower) {
        sampleFollowerTurn(*follower, omega, points, followerTurn);
        text.pop_back();  // the line end
        text += ',';
        text += followerCsvColumns(*follower);
        if (forces) {
            text += ',';
            text += forcesCsvColumns(*forces);
        }
        text += '\n';
    }
    ForceTurn forceTurn;
    if (follower && forces) forcesOfTurn(*forces, *follower, followerTurn, omega, forceTurn);
    text.reserve(text.size() + turn.size() * (follower ? 460 : 300));
    for (std::size_t k = 0; k < turn.size(); ++k) {
        appendSampleCsvRow(text, turn, k);
        if (follower) {
            text.pop_back();
            appendFollowerCsvColumns(text, *follower, followerTurn, k);
            if (forces) appendForcesCsvColumns(text, *forces, forceTurn, followerTurn, k, omega);
            text += '\n';
        }
    }
    return text;
}

std::string forGermanSpreadsheets(std::string_view csv) {
    std::string out(csv);
    for (char& c : out) {
        if (c == ',') {
            c = ';';
        } else if (c == '.') {
            c = ',';
        }
    }
    return out;
}

}  // namespace cam
