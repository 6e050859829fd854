#include "spline/path_study.h"

namespace cam {

PathStudy studyPath(const std::vector<CubicBezier>& pieces, int samplesPerPiece) {
    PathStudy out;
    const int n = std::max(2, samplesPerPiece);
    const double h = 1.0 / n;
    out.step = h;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        const CubicBezier& b = pieces[p];
        for (int i = 0; i <= n; ++i) {
            const double s = static_cast<double>(i) / n;
            out.t.push_back(static_cast<double>(p) + s);
            const Eigen::Vector2d q = b.point(s), d1 = b.derivative(s, 1), d2 = b.derivative(s, 2);
            const double a[] = {q.x(), q.y(), d1.x(), d1.y(), d2.x(), d2.y()};
            // The piece's own polynomial just beyond its ends: the quotient is that of this
            // piece, not a blend across the knot.
            const Eigen::Vector2d before = b.point(s - h), after = b.point(s + h);
            const Eigen::Vector2d fd1 = (after - before) / (2.0 * h);
            const Eigen::Vector2d fd2 = (after - 2.0 * q + before) / (h * h);
            const double f[] = {q.x(), q.y(), fd1.x(), fd1.y(), fd2.x(), fd2.y()};
            for (int k = 0; k < PathStudy::Count; ++k) {
                out.analytic[static_cast<std::size_t>(k)].push_back(a[k]);
                out.quotient[static_cast<std::size_t>(k)].push_back(f[k]);
            }
        }
    }
    return out;
}

}  // namespace cam
