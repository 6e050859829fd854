#pragma once
/// @file
/// @brief What the camwright-cli commands share: the project loaded and evaluated (the one
/// verdict of evaluation/evaluation.h, which the window has too), JSON results checked for
/// finite numbers, and files written whole or not at all.

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>

#include "closure/conjugate.h"
#include "closure/groove.h"
#include "common/diagnostic.h"
#include "contour/contour.h"
#include "follower/follower.h"
#include "kinematics/kinematics.h"
#include "project/project.h"

namespace cam::cli {

using Json = nlohmann::ordered_json;

struct Loaded {
    Project project;
    Contour contour;
    double omega;
    /// The project's follower placed on the contour (a radial knife when it names none).
    FollowerModel follower;
    /// A grooved cam's flanks and its roller pressed on the outer flank (evaluation.h).
    std::optional<GrooveFlanks> groove;
    std::shared_ptr<const FollowerModel> outerFlank;
};

/// @brief "PATH: LOCATION" as the CLI names a project's problem (a problem of the file as a
/// whole is located at the path itself).
[[nodiscard]] std::string placeOf(const std::string& path, const Diagnostic& d);

/// @brief PROJECT as read and checked against the format, not evaluated (for commands that
/// repair or make its contour: fit-windows, synthesize, size), or throws its first problem
/// (exit 2).
[[nodiscard]] Project loadStructure(const std::string& path);

/// @brief Loads PROJECT and evaluates it, or throws its first problem (exit 2); the rest go to
/// stderr via `validate`, which is the command for seeing them all.
[[nodiscard]] Loaded load(const std::string& path);

/// @brief What load() gives (`loaded`), or for a valid motion design whose contour was never
/// synthesised (evaluation status AwaitsContour, which load() refuses) the project alone
/// (`designOnly`): a cam table can still be made from its law. Anything else load() refuses is
/// refused the same way.
struct LoadedOrDesign {
    std::optional<Loaded> loaded;
    std::optional<Project> designOnly;
};
[[nodiscard]] LoadedOrDesign loadAllowingDesignOnly(const std::string& path);

/// @brief A conjugate pair's second plate (closure/conjugate.h), fitted within the project's
/// conjugateTolerance; none for another closure. Throws what cannot be made, located at its
/// key (exit 2).
[[nodiscard]] std::optional<ConjugatePlate> secondPlate(const Loaded& loaded,
                                                        const std::string& path);

/// @brief No command prints a non-finite number with exit 0: a result that is not a finite
/// number is "not computable" (exit 3), named by its place in the output
/// ("extremes/j/max/value").
void requireFinite(const Json& value, const std::string& where);

/// @brief Prints a JSON result after checking every number in it.
void printJson(std::ostream& out, const Json& result);

/// @brief The --out of a command that makes a project: `report` checked to be finite first,
/// then `project` written to `outPath` atomically; throws (exit 2) naming the file when it
/// cannot be written. Nothing is written when either fails.
void writeProjectOut(const std::string& outPath, const Project& project, const Json& report);

/// @brief printJson(out, object) where object[key] is the array of the `count` elements that
/// element(i) makes, each made, checked and turned into text in turn: the same text, without
/// the whole tree in memory (analyze's 100,000 joints took 400 MB as one). Nothing is written
/// unless every element is finite.
void printJsonWithArray(std::ostream& out, Json object, const std::string& key, std::size_t count,
                        const std::function<Json(std::size_t)>& element);

/// @brief Every sampled value is finite, checked before the first row is written.
void requireFiniteColumns(const SampledTurn& turn);

/// @brief One turn at n instants as CSV (the `sample` columns, then the follower's when one is
/// given), to `outPath` (atomically) or `out`.
void writeSampleCsv(const Loaded& loaded, long long n, std::ostream& out,
                    const std::optional<std::string>& outPath,
                    const FollowerModel* follower = nullptr);

/// @brief Writes `text` to `path` atomically (io/atomic_file.h); a failure throws (exit 2).
void writeExport(const std::string& path, const std::string& text);

}  // namespace cam::cli
