#include "cli/command_support.h"

#include "cli/arguments.h"
#include "evaluation/evaluation.h"
#include "export/sample_csv.h"
#include "follower/follower_turn.h"
#include "io/atomic_file.h"
#include "io/project_json.h"

namespace cam::cli {

std::string placeOf(const std::string& path, const Diagnostic& d) {
    return d.location == path ? path : path + ": " + d.location;
}

Project loadStructure(const std::string& path) {
    auto loaded = loadProjectStructure(path);
    if (!loaded.ok()) {
        const Diagnostic& d = loaded.errors().front();
        throw CliError{kInvalidInput, placeOf(path, d), d.message};
    }
    return std::move(loaded).value();
}

namespace {

/// load(), or with `allowDesignOnly` the project alone when its status is AwaitsContour.
LoadedOrDesign loadEvaluated(const std::string& path, bool allowDesignOnly) {
    auto project = loadProjectStructure(path);
    Diagnostics problems = project.ok() ? Diagnostics{} : project.errors();
    std::optional<ProjectEvaluation> evaluation;
    if (project.ok()) {
        evaluation = evaluateProject(project.value());
        switch (evaluation->status) {
            case EvaluationStatus::Computed:
                break;
            case EvaluationStatus::AwaitsContour:
                if (allowDesignOnly) return {std::nullopt, std::move(project).value()};
                problems = {contourNeverSynthesised()};
                break;
            case EvaluationStatus::Invalid:
            case EvaluationStatus::Failed:
                for (const Diagnostic& d : evaluation->problems) {
                    if (d.severity == Severity::Error) problems.push_back(d);
                }
                break;
        }
    }
    if (!problems.empty()) {
        const Diagnostic& d = problems.front();
        std::string message = d.message;
        if (problems.size() > 1) {
            message += " (and " + std::to_string(problems.size() - 1) +
                       " more problems; run 'camwright-cli validate' for all)";
        }
        throw CliError{kInvalidInput, placeOf(path, d), message};
    }
    return {Loaded{std::move(project).value(), std::move(*evaluation->contour), evaluation->omega,
                   *evaluation->follower, std::move(evaluation->groove),
                   evaluation->outerFlankFollower},
            std::nullopt};
}

}  // namespace

Loaded load(const std::string& path) { return *loadEvaluated(path, false).loaded; }

LoadedOrDesign loadAllowingDesignOnly(const std::string& path) { return loadEvaluated(path, true); }

std::optional<ConjugatePlate> secondPlate(const Loaded& loaded, const std::string& path) {
    const std::optional<SecondRoller> yoke = SecondRoller::of(loaded.project);
    if (!yoke) return std::nullopt;
    auto plate = conjugatePlate(loaded.follower, *yoke, conjugateTolerance(loaded.project));
    if (!plate.ok()) {
        const Diagnostic& d = plate.errors().front();
        throw CliError{kInvalidInput, placeOf(path, d), d.message};
    }
    return std::move(plate).value();
}

void requireFinite(const Json& value, const std::string& where) {
    if (value.is_number_float() && !std::isfinite(value.get<double>())) {
        throw CliError{kNotComputable, where,
                       "is not a finite number (" + formatNumber(value.get<double>()) +
                           "): the result is beyond what a double can hold"};
    }
    if (value.is_object()) {
        for (const auto& [key, item] : value.items()) {
            requireFinite(item, where.empty() ? key : where + "/" + key);
        }
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i) {
            requireFinite(value[i], where + "[" + std::to_string(i) + "]");
        }
    }
}

void writeProjectOut(const std::string& outPath, const Project& project, const Json& report) {
    requireFinite(report, "");
    const Diagnostics written = writeFileAtomically(outPath, serializeProject(project));
    if (!written.empty()) throw CliError{kInvalidInput, outPath, written.front().message};
}

void printJson(std::ostream& out, const Json& result) {
    requireFinite(result, "");
    out << result.dump(2) << "\n";
}

namespace {

/// `text` (a dump(2)) as it reads nested `indent` spaces deep: a newline is only ever between
/// its tokens (one inside a string is written \n).
std::string nested(const std::string& text, std::size_t indent) {
    std::string out;
    out.reserve(text.size() + text.size() / 8);
    for (const char c : text) {
        out += c;
        if (c == '\n') out.append(indent, ' ');
    }
    return out;
}

}  // namespace

void printJsonWithArray(std::ostream& out, Json object, const std::string& key, std::size_t count,
                        const std::function<Json(std::size_t)>& element) {
    object[key] = Json::array();
    requireFinite(object, "");
    std::string text = "{";
    bool first = true;
    for (const auto& [name, value] : object.items()) {
        text += first ? "\n  " : ",\n  ";
        first = false;
        text += Json(name).dump() + ": ";
        if (name != key) {
            text += nested(value.dump(2), 2);
            continue;
        }
        if (count == 0) {
            text += "[]";
            continue;
        }
        text += "[";
        for (std::size_t i = 0; i < count; ++i) {
            const Json item = element(i);
            requireFinite(item, key + "[" + std::to_string(i) + "]");
            std::string itemText = nested(item.dump(2), 4);
            // Room for all of them at the first one's size, so that the text grows but once.
            if (i == 0) text.reserve(text.size() + (itemText.size() + 8) * count * 9 / 8);
            text += i == 0 ? "\n    " : ",\n    ";
            text += itemText;
        }
        text += "\n  ]";
    }
    text += first ? "}" : "\n}";
    out << text << "\n";
}

void requireFiniteColumns(const SampledTurn& turn) {
    if (const auto problem = firstNonFiniteSample(turn)) {
        throw CliError{kNotComputable, problem->location, problem->message};
    }
}

void writeSampleCsv(const Loaded& loaded, long long n, std::ostream& out,
                    const std::optional<std::string>& outPath, const FollowerModel* follower) {
    std::optional<AtomicFileWriter> file;
    if (outPath) {
        file.emplace(*outPath);
        if (!file->ok()) {
            throw CliError{kInvalidInput, *outPath, file->errors().front().message};
        }
    }
    SampledTurn turn;
    sampleTurn(loaded.contour, loaded.omega, static_cast<std::size_t>(n), turn);
    requireFiniteColumns(turn);

    FollowerTurn followerTurn;
    std::string chunk(kSampleCsvHeader);
    // With the follower's columns come the forces' when the project has dynamics.
    std::optional<ForceModel> forces;
    ForceTurn forceTurn;
    if (follower) {
        sampleFollowerTurn(*follower, loaded.omega, static_cast<std::size_t>(n), followerTurn);
        chunk.pop_back();
        chunk += ',';
        chunk += followerCsvColumns(*follower);
        if (loaded.project.dynamics) {
            forces = ForceModel::of(*loaded.project.dynamics, follower->spec());
            forcesOfTurn(*forces, *follower, followerTurn, loaded.omega, forceTurn);
            chunk += ',';
            chunk += forcesCsvColumns(*forces);
        }
        chunk += '\n';
    }
    auto flush = [&] {
        if (file) {
            file->write(chunk);
        } else {
            out << chunk;
        }
        chunk.clear();
    };
    for (std::size_t k = 0; k < turn.size(); ++k) {
        appendSampleCsvRow(chunk, turn, k);
        if (follower) {
            chunk.pop_back();
            appendFollowerCsvColumns(chunk, *follower, followerTurn, k);
            if (forces) {
                appendForcesCsvColumns(chunk, *forces, forceTurn, followerTurn, k, loaded.omega);
            }
            chunk += '\n';
        }
        if (chunk.size() > (1u << 20)) flush();
        // A failed stdout (full disk, closed) is reported by main; a failed --out file below.
        if (!out || (file && !file->ok())) break;
    }
    flush();
    if (file) {
        const Diagnostics problems = file->commit();
        if (!problems.empty()) throw CliError{kInvalidInput, *outPath, problems.front().message};
    }
}

void writeExport(const std::string& path, const std::string& text) {
    AtomicFileWriter file(path);
    file.write(text);
    Diagnostics problems = file.commit();
    if (!problems.empty()) throw CliError{kInvalidInput, path, problems.front().message};
}

}  // namespace cam::cli
