#pragma once
/// @file
/// @brief r(phi) of a segment and its first three derivatives with respect to phi.

namespace cam {

/// @brief Distance along the follower ray and its phi-derivatives (mm, mm/rad, ...).
struct PolarDerivatives {
    double r = 0.0;
    double dr = 0.0;   ///< r'
    double d2r = 0.0;  ///< r''
    double d3r = 0.0;  ///< r'''
};

}  // namespace cam
