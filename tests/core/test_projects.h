#pragma once
// Small projects built in code for the core tests.

#include "project/project.h"

namespace cam::test {

/// One circle of radius R centred at (e, 0), origin inside, split into windows at the angles
/// given (degrees, ascending, spanning 360): every segment is an arc of the same circle.
inline Project splitCircle(double e, double radius, std::vector<double> boundariesDeg,
                           MotionSpec motion = {SpeedUnit::PeriodS, 1.0}) {
    Project p;
    p.name = "split circle";
    p.motion = motion;
    for (std::size_t k = 0; k + 1 < boundariesDeg.size(); ++k) {
        p.contour.push_back(SegmentSpec{Arc{{e, 0.0}, radius, Branch::Outer}, boundariesDeg[k],
                                        boundariesDeg[k + 1]});
    }
    return p;
}

}  // namespace cam::test
