#include "project/project.h"

#include "common/angles.h"

namespace cam {

double MotionSpec::omegaRadS() const {
    switch (unit) {
        case SpeedUnit::OmegaRadS:
            return value;
        case SpeedUnit::Rpm:
            return value * kTwoPi / 60.0;
        case SpeedUnit::PeriodS:
            return kTwoPi / value;
    }
    return 0.0;
}

}  // namespace cam
