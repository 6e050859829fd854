#pragma once
// Small projects built in code for the core tests.

#include <gtest/gtest.h>

#include <string>

#include "common/diagnostic.h"
#include "contour/contour.h"
#include "io/project_json.h"
#include "project/project.h"
#include "test_support.h"

namespace cam::test {

/// The contour of a project file (the test fails when it does not load).
inline Contour load(const std::string& path) {
    auto p = loadProjectFile(path);
    EXPECT_TRUE(p.ok()) << path;
    return Contour::build(p.value()).value();
}

/// The bundled six-lobe arc cam's contour (r from 20.9 to 29 mm).
inline Contour sixLobe() { return load(examplePath("six-lobe-arc-cam.cam.json")); }

/// A follower (knife, radius 0, or roller) on a swinging arm of `length` about `pivot`.
inline FollowerSpec armSpec(FollowerType type, double radius, Eigen::Vector2d pivot, double length,
                            ArmSide side) {
    FollowerSpec spec;
    spec.type = type;
    spec.radius = radius;
    spec.motion = FollowerMotion::Oscillating;
    spec.pivot = pivot;
    spec.armLength = length;
    spec.arm = side;
    return spec;
}

/// A result's errors; none when it succeeded.
template <class T>
Diagnostics errorsOf(const Result<T>& result) {
    return result.ok() ? Diagnostics{} : result.errors();
}

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

/// math.md §8's cam: base radius 40 mm, cycloidal rise of 10 mm over 0–120°, dwell to 180°,
/// cycloidal return over 180–300°, dwell to 360°.
/// A design segment of `law` ending at `toDeg` with `lift` there, its other fields default.
inline DesignSegmentSpec designSegment(MotionLawType law, double toDeg, double lift) {
    DesignSegmentSpec s;
    s.law = law;
    s.toDeg = toDeg;
    s.lift = lift;
    return s;
}

inline DesignSpec cycloidalDesign() {
    DesignSpec d;
    d.baseRadius = 40.0;
    d.segments = {{MotionLawType::Cycloidal, 120.0, 10.0},
                  {MotionLawType::Dwell, 180.0, 10.0},
                  {MotionLawType::Cycloidal, 300.0, 0.0},
                  {MotionLawType::Dwell, 360.0, 0.0}};
    return d;
}

}  // namespace cam::test
