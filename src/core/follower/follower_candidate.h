#pragma once
/// @file
/// @brief One contact the follower could make at a cam angle (private to follower*.cpp).

#include <Eigen/Core>
#include <cstddef>

#include "follower/follower.h"
#include "follower/jet.h"

namespace cam {

struct FollowerModel::Candidate {
    Jet s;                              ///< s, or ψ on a swinging arm
    Eigen::Vector2d contact{0.0, 0.0};  ///< flat face: the support point
    JetVec point;                       ///< swinging arm: the tip or roller centre (cam frame)
    double rank = 0.0;                  ///< the outermost contact has the largest rank
    std::size_t segment = 0;
    bool found = false;
};

}  // namespace cam
