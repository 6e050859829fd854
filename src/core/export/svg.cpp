#include "export/svg.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/angles.h"
#include "export/export_checks.h"
#include "export/free_text.h"
#include "export/number_text.h"
#include "toolpath/tool_path.h"

namespace cam {
namespace {

/// Characters (code points) of valid UTF-8 text.
std::size_t characterCount(const std::string& text) {
    return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

void appendPoint(std::string& out, const Eigen::Vector3d& p) {
    appendExact(out, p.x());
    out += ' ';
    appendExact(out, -p.y());  // SVG's y points down
}

/// The SVG arc command to the end of `s`. In SVG's y-down frame a counter-clockwise arc of ours
/// turns the negative way: sweep-flag 0.
void appendArc(std::string& out, const PathSegment& s) {
    out += " A ";
    appendExact(out, s.radius);
    out += ' ';
    appendExact(out, s.radius);
    out += " 0 ";
    out += std::abs(s.sweep) > kPi ? '1' : '0';
    out += ' ';
    out += s.sweep > 0 ? '0' : '1';
    out += ' ';
    appendPoint(out, s.end);
}

void appendCross(std::string& out, const Eigen::Vector2d& c, double size, const char* cssClass) {
    out += "  <path class=\"";
    out += cssClass;
    out += "\" d=\"M ";
    appendExact(out, c.x() - size);
    out += ' ';
    appendExact(out, -c.y());
    out += " h ";
    appendExact(out, 2 * size);
    out += " M ";
    appendExact(out, c.x());
    out += ' ';
    appendExact(out, -c.y() - size);
    out += " v ";
    appendExact(out, 2 * size);
    out += "\"/>\n";
}

/// A closed <path> through `pieces`: lines, and arcs in pieces of at most a quarter turn.
void appendClosedPath(std::string& out, const std::vector<PathSegment>& pieces, const char* id,
                      const char* cssClass) {
    out += "  <path id=\"";
    out += id;
    out += "\" class=\"";
    out += cssClass;
    out += "\" d=\"M ";
    appendPoint(out, pieces.front().start);
    for (const PathSegment& s : pieces) {
        if (s.kind == PathSegment::Kind::Line) {
            out += " L ";
            appendPoint(out, s.end);
        } else {
            // An SVG arc is given by its end points and radius; its centre is well determined
            // only well away from a half turn (and a full turn has no second point): pieces of
            // at most a quarter turn each.
            const int parts =
                std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep) / (kPi / 2) - 1e-9)));
            for (int i = 0; i < parts; ++i) {
                const double part = s.sweep / parts;
                PathSegment piece =
                    PathSegment::arc(s.center, s.radius, s.startAngle + i * part, part, 0.0);
                if (i + 1 == parts) piece.end = s.end;  // exactly where the next piece starts
                appendArc(out, piece);
            }
        }
    }
    out += " Z\"/>\n";
}

}  // namespace

Result<std::string> svgDocument(const Contour& contour, const SvgOptions& options) {
    Diagnostics errors;
    checkTolerance(options.toleranceMm, errors);
    if (!errors.empty()) return errors;
    auto profile = offsetContour(contour, 0.0, options.toleranceMm);
    if (!profile.ok()) return profile.errors();
    const std::vector<PathSegment>& pieces = profile.value().path.segments;
    auto grooved = grooveFlanksIf(contour, options.groove, options.toleranceMm);
    if (!grooved.ok()) return grooved.errors();
    const std::optional<GrooveFlanks>& groove = grooved.value();

    // The drawing's box: the profile, a groove's outer flank or a second plate (arcs through
    // their extreme points) and the rotation centre.
    Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();
    std::vector<PathSegment> drawn = pieces;
    if (groove)
        drawn.insert(drawn.end(), groove->outer.segments.begin(), groove->outer.segments.end());
    if (options.secondPlate) {
        drawn.insert(drawn.end(), options.secondPlate->segments.begin(),
                     options.secondPlate->segments.end());
    }
    for (const PathSegment& s : drawn) {
        const int samples = s.kind == PathSegment::Kind::Arc ? 64 : 1;
        for (int i = 0; i <= samples; ++i) {
            const Eigen::Vector2d p = s.point(s.length() * i / samples).head<2>();
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
    }
    const double size = std::max((hi - lo).maxCoeff(), 1e-3);
    const double margin = 0.05 * size + 2.0;
    const double text = 0.04 * size + 1.0;  // title height, mm
    const double mark = 0.02 * size;
    const double stroke = 0.0025 * size;
    // The title is free text: one line of at most kFreeTextMaxChars characters, escaped
    // (export/free_text.h). The drawing is wide enough for it too (a sans-serif letter is at
    // most about 0.6 em wide on average).
    const std::string title = xmlText(options.title);
    const double titleWidth =
        0.6 * text * static_cast<double>(characterCount(oneLine(options.title)));
    const double x0 = lo.x() - margin, y0 = -hi.y() - margin - 1.5 * text;
    const double w = std::max(hi.x() - lo.x(), titleWidth) + 2 * margin;
    const double h = (hi.y() - lo.y()) + 2 * margin + 1.5 * text;

    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"";
    appendExact(out, w);
    out += "mm\" height=\"";
    appendExact(out, h);
    out += "mm\" viewBox=\"";
    for (double v : {x0, y0, w, h}) {
        appendExact(out, v);
        out += ' ';
    }
    out.back() = '"';
    out += ">\n  <title>" + title + "</title>\n";
    out +=
        "  <desc>Cam profile, 1:1 in millimetres (1 user unit = 1 mm, y up drawn up), "
        "written by Camwright</desc>\n";
    out += "  <style>.profile{fill:none;stroke:#000;stroke-width:";
    appendExact(out, stroke);
    out += "} .pitch{fill:none;stroke:#888;stroke-dasharray:";
    appendExact(out, 4 * stroke);
    out += ' ';
    appendExact(out, 2 * stroke);
    out += ";stroke-width:";
    appendExact(out, stroke / 2);
    out += "} .centre{fill:none;stroke:#c00;stroke-width:";
    appendExact(out, stroke / 2);
    out += "} .title{font-family:sans-serif;font-size:";
    appendExact(out, text);
    out += "px}</style>\n";

    appendClosedPath(out, pieces, "profile", "profile");
    if (groove) {
        appendClosedPath(out, groove->outer.segments, "outer-flank", "profile");
        appendClosedPath(out, groove->pitch.segments, "pitch", "pitch");
    }
    if (options.secondPlate) {
        appendClosedPath(out, options.secondPlate->segments, "second-plate", "profile");
    }
    appendCross(out, Eigen::Vector2d::Zero(), mark, "centre");
    for (std::size_t k = 0; k < contour.size(); ++k) {
        if (contour.segment(k).type == SegmentType::Arc) {
            appendCross(out, contour.segment(k).arc.center, mark / 2, "centre");
        }
    }
    out += "  <text class=\"title\" x=\"";
    appendExact(out, lo.x());
    out += "\" y=\"";
    appendExact(out, -hi.y() - margin);
    out += "\">" + title + "</text>\n</svg>\n";
    return out;
}

}  // namespace cam
