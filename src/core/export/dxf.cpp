#include "export/dxf.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <vector>

#include "common/angles.h"
#include "export/export_checks.h"
#include "export/number_text.h"
#include "toolpath/tool_path.h"

namespace cam {
namespace {

// Handles of the drawing's fixed objects (hexadecimal in the file); entities count up from
// kFirstEntityHandle, and $HANDSEED is the next free one.
enum Handle : unsigned {
    kVportTable = 0x8,
    kLtypeTable = 0x5,
    kLayerTable = 0x2,
    kStyleTable = 0x3,
    kViewTable = 0x6,
    kUcsTable = 0x7,
    kAppidTable = 0x9,
    kDimstyleTable = 0xA,
    kBlockRecordTable = 0x1,
    kRootDictionary = 0xC,
    kGroupDictionary = 0xD,
    kVport = 0x20,
    kLtypeByBlock = 0x21,
    kLtypeByLayer = 0x22,
    kLtypeContinuous = 0x23,
    kLayer0 = 0x24,
    kLayerContour = 0x25,
    kLayerToolpath = 0x26,
    kLayerCentres = 0x27,
    kStyleStandard = 0x28,
    kAppidAcad = 0x29,
    kDimstyleStandard = 0x2A,
    kModelSpaceRecord = 0x2B,
    kPaperSpaceRecord = 0x2C,
    kModelSpaceBlock = 0x2D,
    kModelSpaceEnd = 0x2E,
    kPaperSpaceBlock = 0x2F,
    kPaperSpaceEnd = 0x30,
    kLayerFlankOuter = 0x31,
    kLayerPitch = 0x32,
    kLayerPlate2 = 0x33,
    kFirstEntityHandle = 0x100,
};

/// Group code / value pairs, the way every DXF line pair is written.
class DxfText {
public:
    void pair(int code, std::string_view value) {
        char head[8];
        std::snprintf(head, sizeof head, "%3d\n", code);
        m_text += head;
        m_text += value;
        m_text += '\n';
    }
    void pair(int code, int value) { pair(code, std::to_string(value)); }
    void number(int code, double value) {
        std::string v;
        appendExact(v, value);
        pair(code, v);
    }
    void handle(int code, unsigned h) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "%X", h);
        pair(code, hex);
    }
    void point(int code, double x, double y, double z = 0.0) {
        number(code, x);
        number(code + 10, y);
        number(code + 20, z);
    }
    [[nodiscard]] std::string& text() { return m_text; }

private:
    std::string m_text;
};

struct Layer {
    const char* name;
    unsigned handle;
    int colour;  // AutoCAD colour index
};

void beginSection(DxfText& d, const char* name) {
    d.pair(0, "SECTION");
    d.pair(2, name);
}
void endSection(DxfText& d) { d.pair(0, "ENDSEC"); }

void beginTable(DxfText& d, const char* name, unsigned handle, int count) {
    d.pair(0, "TABLE");
    d.pair(2, name);
    d.handle(5, handle);
    d.handle(330, 0);
    d.pair(100, "AcDbSymbolTable");
    d.pair(70, count);
}
void endTable(DxfText& d) { d.pair(0, "ENDTAB"); }

void beginRecord(DxfText& d, const char* type, unsigned handle, unsigned table,
                 const char* subclass) {
    d.pair(0, type);
    d.handle(5, handle);
    d.handle(330, table);
    d.pair(100, "AcDbSymbolTableRecord");
    d.pair(100, subclass);
}

void header(DxfText& d, unsigned handseed, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
    beginSection(d, "HEADER");
    d.pair(9, "$ACADVER");
    d.pair(1, "AC1015");
    d.pair(9, "$DWGCODEPAGE");
    d.pair(3, "ANSI_1252");
    d.pair(9, "$INSBASE");
    d.point(10, 0, 0);
    d.pair(9, "$EXTMIN");
    d.point(10, lo.x(), lo.y());
    d.pair(9, "$EXTMAX");
    d.point(10, hi.x(), hi.y());
    d.pair(9, "$INSUNITS");
    d.pair(70, 4);  // millimetres
    d.pair(9, "$MEASUREMENT");
    d.pair(70, 1);  // metric
    d.pair(9, "$LUNITS");
    d.pair(70, 2);  // decimal
    d.pair(9, "$LUPREC");
    d.pair(70, 6);
    d.pair(9, "$HANDSEED");
    d.handle(5, handseed);
    endSection(d);
}

void tables(DxfText& d, const std::vector<Layer>& layers, const Eigen::Vector2d& lo,
            const Eigen::Vector2d& hi) {
    beginSection(d, "TABLES");

    // The view a reader opens with: the drawing's extents and a tenth around them.
    const Eigen::Vector2d centre = 0.5 * (lo + hi), size = hi - lo;
    const double height = 1.1 * std::max({size.y(), size.x() / 1.5, 1.0});
    beginTable(d, "VPORT", kVportTable, 1);
    beginRecord(d, "VPORT", kVport, kVportTable, "AcDbViewportTableRecord");
    d.pair(2, "*Active");
    d.pair(70, 0);
    d.point(10, 0, 0);  // lower left and upper right of the viewport on screen (fractions)
    d.number(11, 1);
    d.number(21, 1);
    d.number(12, centre.x());  // the view's centre and height in the drawing (mm)
    d.number(22, centre.y());
    d.number(40, height);
    d.number(41, 1.5);  // its width over its height
    endTable(d);

    beginTable(d, "LTYPE", kLtypeTable, 3);
    for (const auto& [name, handle] :
         {std::pair{"ByBlock", kLtypeByBlock}, std::pair{"ByLayer", kLtypeByLayer},
          std::pair{"Continuous", kLtypeContinuous}}) {
        beginRecord(d, "LTYPE", handle, kLtypeTable, "AcDbLinetypeTableRecord");
        d.pair(2, name);
        d.pair(70, 0);
        d.pair(3, handle == kLtypeContinuous ? "Solid line" : "");
        d.pair(72, 65);
        d.pair(73, 0);
        d.number(40, 0.0);
    }
    endTable(d);

    beginTable(d, "LAYER", kLayerTable, static_cast<int>(layers.size()));
    for (const Layer& layer : layers) {
        beginRecord(d, "LAYER", layer.handle, kLayerTable, "AcDbLayerTableRecord");
        d.pair(2, layer.name);
        d.pair(70, 0);
        d.pair(62, layer.colour);
        d.pair(6, "Continuous");
        d.pair(370, -3);  // line weight: default
        d.handle(390, 0);
    }
    endTable(d);

    beginTable(d, "STYLE", kStyleTable, 1);
    beginRecord(d, "STYLE", kStyleStandard, kStyleTable, "AcDbTextStyleTableRecord");
    d.pair(2, "Standard");
    d.pair(70, 0);
    d.number(40, 0.0);
    d.number(41, 1.0);
    d.number(50, 0.0);
    d.pair(71, 0);
    d.number(42, 2.5);
    d.pair(3, "txt");
    d.pair(4, "");
    endTable(d);

    beginTable(d, "VIEW", kViewTable, 0);
    endTable(d);
    beginTable(d, "UCS", kUcsTable, 0);
    endTable(d);

    beginTable(d, "APPID", kAppidTable, 1);
    beginRecord(d, "APPID", kAppidAcad, kAppidTable, "AcDbRegAppTableRecord");
    d.pair(2, "ACAD");
    d.pair(70, 0);
    endTable(d);

    beginTable(d, "DIMSTYLE", kDimstyleTable, 1);
    d.pair(100, "AcDbDimStyleTable");
    d.pair(0, "DIMSTYLE");
    d.handle(105, kDimstyleStandard);
    d.handle(330, kDimstyleTable);
    d.pair(100, "AcDbSymbolTableRecord");
    d.pair(100, "AcDbDimStyleTableRecord");
    d.pair(2, "Standard");
    d.pair(70, 0);
    endTable(d);

    beginTable(d, "BLOCK_RECORD", kBlockRecordTable, 2);
    for (const auto& [name, handle] : {std::pair{"*Model_Space", kModelSpaceRecord},
                                       std::pair{"*Paper_Space", kPaperSpaceRecord}}) {
        beginRecord(d, "BLOCK_RECORD", handle, kBlockRecordTable, "AcDbBlockTableRecord");
        d.pair(2, name);
        d.handle(340, 0);  // no layout object
    }
    endTable(d);

    endSection(d);
}

/// The group codes every entity starts with: type, handle, owner, subclass, layer.
void entityHeader(DxfText& d, const char* type, unsigned handle, unsigned owner,
                  const char* layer) {
    d.pair(0, type);
    d.handle(5, handle);
    d.handle(330, owner);
    d.pair(100, "AcDbEntity");
    d.pair(8, layer);
}

void blocks(DxfText& d) {
    beginSection(d, "BLOCKS");
    for (const auto& [name, record, begin, end] :
         {std::tuple{"*Model_Space", kModelSpaceRecord, kModelSpaceBlock, kModelSpaceEnd},
          std::tuple{"*Paper_Space", kPaperSpaceRecord, kPaperSpaceBlock, kPaperSpaceEnd}}) {
        entityHeader(d, "BLOCK", begin, record, "0");
        d.pair(100, "AcDbBlockBegin");
        d.pair(2, name);
        d.pair(70, 0);
        d.point(10, 0, 0);
        d.pair(3, name);
        d.pair(1, "");
        entityHeader(d, "ENDBLK", end, record, "0");
        d.pair(100, "AcDbBlockEnd");
    }
    endSection(d);
}

void objects(DxfText& d) {
    beginSection(d, "OBJECTS");
    d.pair(0, "DICTIONARY");
    d.handle(5, kRootDictionary);
    d.handle(330, 0);
    d.pair(100, "AcDbDictionary");
    d.pair(281, 1);
    d.pair(3, "ACAD_GROUP");
    d.handle(350, kGroupDictionary);
    d.pair(0, "DICTIONARY");
    d.handle(5, kGroupDictionary);
    d.handle(330, kRootDictionary);
    d.pair(100, "AcDbDictionary");
    d.pair(281, 1);
    endSection(d);
}

/// The entities of model space, with handles counting up.
class Entities {
public:
    explicit Entities(DxfText& d) : m_d(d) {}

    void begin(const char* type, const char* layer) {
        entityHeader(m_d, type, m_next++, kModelSpaceRecord, layer);
    }

    void piece(const PathSegment& s, const char* layer, bool fullCircle) {
        if (s.kind == PathSegment::Kind::Line) {
            begin("LINE", layer);
            m_d.pair(100, "AcDbLine");
            m_d.point(10, s.start.x(), s.start.y());
            m_d.point(11, s.end.x(), s.end.y());
            return;
        }
        begin(fullCircle ? "CIRCLE" : "ARC", layer);
        m_d.pair(100, "AcDbCircle");
        m_d.point(10, s.center.x(), s.center.y());
        m_d.number(40, s.radius);
        if (fullCircle) return;
        // DXF arcs run counter-clockwise from 50 to 51: a clockwise sweep runs backwards.
        const double a = s.startAngle, b = s.startAngle + s.sweep;
        const double from = s.sweep >= 0 ? a : b, to = s.sweep >= 0 ? b : a;
        m_d.pair(100, "AcDbArc");
        m_d.number(50, normalizedDeg(from));
        m_d.number(51, normalizedDeg(to));
    }

    void point(const Eigen::Vector2d& p, const char* layer) {
        begin("POINT", layer);
        m_d.pair(100, "AcDbPoint");
        m_d.point(10, p.x(), p.y());
    }

    /// One closed LWPOLYLINE through the pieces' start points, each with the bulge of its piece.
    void polyline(const std::vector<PathSegment>& pieces, const char* layer) {
        begin("LWPOLYLINE", layer);
        m_d.pair(100, "AcDbPolyline");
        m_d.pair(90, static_cast<int>(pieces.size()));
        m_d.pair(70, 1);  // closed
        for (const PathSegment& s : pieces) {
            m_d.number(10, s.start.x());
            m_d.number(20, s.start.y());
            if (s.kind == PathSegment::Kind::Arc) m_d.number(42, std::tan(s.sweep / 4.0));
        }
    }

    /// A cubic Bézier as a degree-3 SPLINE: the control points, knots 0,0,0,0,1,1,1,1.
    void spline(const CubicBezier& curve, const char* layer) {
        begin("SPLINE", layer);
        m_d.pair(100, "AcDbSpline");
        m_d.pair(70, 8);  // planar
        m_d.pair(71, 3);
        m_d.pair(72, 8);
        m_d.pair(73, 4);
        m_d.pair(74, 0);
        for (int k = 0; k < 8; ++k) m_d.number(40, k < 4 ? 0.0 : 1.0);
        for (const Eigen::Vector2d& p : curve.p) m_d.point(10, p.x(), p.y());
    }

    [[nodiscard]] unsigned next() const { return m_next; }

private:
    static double normalizedDeg(double rad) {
        double deg = radToDeg(std::remainder(rad, kTwoPi));
        if (deg < 0) deg += 360.0;
        return deg;
    }

    DxfText& m_d;
    unsigned m_next = kFirstEntityHandle;
};

/// A full circle cut in two halves (a polyline vertex cannot carry a bulge of 360°).
std::vector<PathSegment> halves(const PathSegment& circle) {
    const double half = circle.sweep / 2.0;
    return {PathSegment::arc(circle.center, circle.radius, circle.startAngle, half, 0.0),
            PathSegment::arc(circle.center, circle.radius, circle.startAngle + half, half, 0.0)};
}

void extendBounds(const PathSegment& s, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
    auto take = [&](const Eigen::Vector2d& p) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    };
    take(s.start.head<2>());
    take(s.end.head<2>());
    if (s.kind == PathSegment::Kind::Arc) {
        // The arc's own box: its ends and the quadrant points (0°, 90°, 180°, 270° about its
        // centre) it passes. (The whole circle's box made a viewer open far too wide.)
        const double from = std::min(s.startAngle, s.startAngle + s.sweep);
        const double to = std::max(s.startAngle, s.startAngle + s.sweep);
        for (double q = std::ceil(from / (kPi / 2.0)) * (kPi / 2.0); q <= to; q += kPi / 2.0) {
            take(s.center + s.radius * Eigen::Vector2d(std::cos(q), std::sin(q)));
        }
    }
}

/// The box of a cubic Bézier itself: its ends and, per axis, where its derivative (a
/// quadratic in t) vanishes inside (0, 1).
void extendBounds(const CubicBezier& b, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
    const auto take = [&](double t) {
        const Eigen::Vector2d p = b.point(t);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    };
    take(0.0);
    take(1.0);
    const Eigen::Vector2d d0 = b.p[1] - b.p[0], d1 = b.p[2] - b.p[1], d2 = b.p[3] - b.p[2];
    const Eigen::Vector2d qa = d0 - 2.0 * d1 + d2, qb = 2.0 * (d1 - d0), qc = d0;
    for (int axis = 0; axis < 2; ++axis) {
        const double a = qa[axis], bb = qb[axis], c = qc[axis];
        if (std::abs(a) < 1e-15) {
            if (std::abs(bb) > 1e-15 && -c / bb > 0.0 && -c / bb < 1.0) take(-c / bb);
            continue;
        }
        const double disc = bb * bb - 4.0 * a * c;
        if (disc < 0.0) continue;
        for (double sign : {-1.0, 1.0}) {
            const double t = (-bb + sign * std::sqrt(disc)) / (2.0 * a);
            if (t > 0.0 && t < 1.0) take(t);
        }
    }
}

}  // namespace

Result<std::string> dxfDocument(const Contour& contour, const DxfOptions& options) {
    Diagnostics errors;
    checkTolerance(options.toleranceMm, errors);
    if (options.toolRadiusMm) checkToolRadius(*options.toolRadiusMm, errors);
    if (!errors.empty()) return errors;

    auto profile = offsetContour(contour, 0.0, options.toleranceMm);
    if (!profile.ok()) return profile.errors();
    std::optional<ToolPath> toolPath;
    if (options.toolRadiusMm) {
        auto offset = offsetContour(contour, *options.toolRadiusMm, options.toleranceMm);
        if (!offset.ok()) return offset.errors();
        toolPath = std::move(offset.value().path);
    }
    auto grooved = grooveFlanksIf(contour, options.groove, options.toleranceMm);
    if (!grooved.ok()) return grooved.errors();
    const std::optional<GrooveFlanks>& groove = grooved.value();
    const ContourOffset& p = profile.value();
    const bool fullCircle = contour.size() == 1 && contour.segment(0).type == SegmentType::Arc;
    const char* contourLayer = groove ? "FLANK_INNER" : options.secondPlate ? "PLATE_1" : "CONTOUR";

    std::vector<Layer> layers{{"0", kLayer0, 7}, {contourLayer, kLayerContour, 7}};
    if (groove) {
        layers.push_back({"FLANK_OUTER", kLayerFlankOuter, 5});
        layers.push_back({"PITCH", kLayerPitch, 8});
    }
    if (options.secondPlate) layers.push_back({"PLATE_2", kLayerPlate2, 5});
    if (toolPath) layers.push_back({"TOOLPATH", kLayerToolpath, 1});
    if (options.centres) layers.push_back({"CENTRES", kLayerCentres, 3});

    Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
    for (std::size_t i = 0; i < p.path.segments.size(); ++i) {
        // A spline written as a SPLINE entity: its own box below, not its arcs'.
        if (options.splineEntities && isSpline(contour.segment(p.origin[i]).type)) continue;
        extendBounds(p.path.segments[i], lo, hi);
    }
    if (toolPath) {
        for (const PathSegment& s : toolPath->segments) extendBounds(s, lo, hi);
    }
    if (groove) {
        for (const PathSegment& s : groove->outer.segments) extendBounds(s, lo, hi);
    }
    if (options.secondPlate) {
        for (const PathSegment& s : options.secondPlate->segments) extendBounds(s, lo, hi);
    }
    if (options.splineEntities) {
        // Written as SPLINE entities: the curves' own extremes, not their arcs'.
        for (std::size_t k = 0; k < contour.size(); ++k) {
            const ContourSegment& seg = contour.segment(k);
            if (isSpline(seg.type)) extendBounds(CubicBezier{seg.bezierKernel.p}, lo, hi);
        }
    }
    if (options.centres) {
        for (std::size_t k = 0; k < contour.size(); ++k) {
            if (contour.segment(k).type != SegmentType::Arc) continue;
            lo = lo.cwiseMin(contour.segment(k).arc.center);
            hi = hi.cwiseMax(contour.segment(k).arc.center);
        }
    }

    // Entities first (their count gives $HANDSEED), then the document around them.
    DxfText body;
    Entities entities(body);
    if (options.polyline) {
        std::vector<PathSegment> pieces =
            fullCircle ? halves(p.path.segments.front()) : p.path.segments;
        entities.polyline(pieces, contourLayer);
    } else {
        for (std::size_t i = 0; i < p.path.segments.size(); ++i) {
            const ContourSegment& seg = contour.segment(p.origin[i]);
            if (options.splineEntities && isSpline(seg.type)) {
                // One SPLINE per segment, written where its first arc pair was.
                if (i == 0 || p.origin[i - 1] != p.origin[i]) {
                    entities.spline(CubicBezier{seg.bezierKernel.p}, contourLayer);
                }
                continue;
            }
            entities.piece(p.path.segments[i], contourLayer, fullCircle);
        }
    }
    if (groove) {
        for (const PathSegment& s : groove->outer.segments) {
            entities.piece(s, "FLANK_OUTER", fullCircle);
        }
        for (const PathSegment& s : groove->pitch.segments) entities.piece(s, "PITCH", fullCircle);
    }
    if (options.secondPlate) {
        for (const PathSegment& s : options.secondPlate->segments) {
            entities.piece(s, "PLATE_2", false);
        }
    }
    if (toolPath) {
        for (const PathSegment& s : toolPath->segments) {
            entities.piece(s, "TOOLPATH", fullCircle);
        }
    }
    if (options.centres) {
        for (std::size_t k = 0; k < contour.size(); ++k) {
            if (contour.segment(k).type == SegmentType::Arc) {
                entities.point(contour.segment(k).arc.center, "CENTRES");
            }
        }
    }

    DxfText d;
    header(d, entities.next(), lo, hi);
    beginSection(d, "CLASSES");
    endSection(d);
    tables(d, layers, lo, hi);
    blocks(d);
    beginSection(d, "ENTITIES");
    d.text() += body.text();
    endSection(d);
    objects(d);
    d.pair(0, "EOF");
    return std::move(d.text());
}

}  // namespace cam
