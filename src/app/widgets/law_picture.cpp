#include "widgets/law_picture.h"

#include "design/motion_table.h"

#include <QIcon>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <vector>

namespace cam {
namespace {

/// The law rest to rest over [0, 1].
LawPoint restToRest(MotionLawType law, double x, const LawParameters& parameters) {
    switch (motionLaw(law).shape) {
        case LawShape::Dwell:
            return {};
        case LawShape::Normalised:
            return normalisedLaw(law, x, parameters);
        case LawShape::BoundaryValues:
            if (law == MotionLawType::Poly7) {
                return Poly7Law(1.0, 0.0, 1.0, {0, 0, 0}, {0, 0, 0}).at(x);
            }
            return Poly5Law(1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0).at(x);
        case LawShape::Table: {
            // A table of a few points with a shoulder, through the law's own spline.
            static const MotionTableSpline spline =
                MotionTableSpline::build(
                    {{0.0, 0.0}, {0.2, 0.08}, {0.45, 0.45}, {0.6, 0.55}, {0.8, 0.9}, {1.0, 1.0}},
                    {})
                    .value();
            return spline.at(x);
        }
    }
    return {};
}

}  // namespace

QPixmap lawPicture(MotionLawType law, QSize size, const LawParameters& parameters) {
    QPixmap picture(size);
    picture.fill(Qt::transparent);
    QPainter painter(&picture);
    painter.setRenderHint(QPainter::Antialiasing);
    const double w = size.width() - 4.0, h = size.height() - 4.0;
    constexpr int kSamples = 96;
    std::vector<LawPoint> points(kSamples + 1);
    double vMax = 0.0, aMax = 0.0;
    for (int i = 0; i <= kSamples; ++i) {
        points[i] = restToRest(law, static_cast<double>(i) / kSamples, parameters);
        vMax = std::max(vMax, std::abs(points[i].v));
        aMax = std::max(aMax, std::abs(points[i].a));
    }
    painter.setPen(QPen(QColor(200, 200, 200), 1.0));
    painter.drawLine(QPointF(2.0, 2.0 + h / 2.0), QPointF(2.0 + w, 2.0 + h / 2.0));
    // value in [−1, 1] → the picture's height
    const auto curve = [&](auto value, QColor colour) {
        QPainterPath path;
        for (int i = 0; i <= kSamples; ++i) {
            const QPointF p(2.0 + w * i / kSamples, 2.0 + h / 2.0 - value(points[i]) * h / 2.0);
            if (i == 0) {
                path.moveTo(p);
            } else {
                path.lineTo(p);
            }
        }
        painter.setPen(QPen(colour, 1.4));
        painter.drawPath(path);
    };
    if (aMax > 0.0) curve([&](const LawPoint& p) { return p.a / aMax; }, QColor(200, 60, 50));
    if (vMax > 0.0) curve([&](const LawPoint& p) { return p.v / vMax; }, QColor(40, 150, 60));
    curve([](const LawPoint& p) { return 2.0 * p.y - 1.0; }, QColor(30, 80, 170));
    return picture;
}

QVariantList motionLawPictures() {
    QVariantList pictures;
    for (const MotionLawKind& law : motionLaws()) {
        pictures << QIcon(lawPicture(law.type));
    }
    return pictures;
}

}  // namespace cam
