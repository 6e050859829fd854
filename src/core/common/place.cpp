#include "common/place.h"

#include <type_traits>

namespace cam {
namespace {

/// "[i]". Texts here are built by appends: GCC 12 warns falsely on "[" + string (PR105651).
std::string bracketed(std::size_t i) {
    std::string out = "[";
    out += std::to_string(i);
    out += ']';
    return out;
}

/// "key.sub", or "key" alone when `sub` is empty.
std::string dotted(std::string out, std::string_view sub) {
    if (!sub.empty()) out.append(1, '.').append(sub);
    return out;
}

std::string segmentFieldText(const SegmentPlace& place) {
    std::string text = dotted(segmentLocation(place.segment), segmentPartKey(place.part));
    if (place.part == SegmentPart::Points && place.point >= 0) {
        text += bracketed(static_cast<std::size_t>(place.point));
    }
    if (place.part != SegmentPart::Whole && place.axis >= 0) {
        text += bracketed(static_cast<std::size_t>(place.axis));
    }
    return text;
}

std::string designSegmentText(std::size_t segment) {
    std::string out = "design.segments";
    return out.append(bracketed(segment));
}

std::string filePositionText(const FilePositionPlace& place) {
    std::string text = "line ";
    text += std::to_string(place.line);
    if (place.column > 0) text.append(", column ").append(std::to_string(place.column));
    return text;
}

}  // namespace

std::string segmentLocation(std::size_t index) {
    std::string out = "contour";
    return out.append(bracketed(index));
}

std::string_view segmentPartKey(SegmentPart part) {
    switch (part) {
        case SegmentPart::Whole:
            return "";
        case SegmentPart::Type:
            return "type";
        case SegmentPart::Center:
            return "center";
        case SegmentPart::Radius:
            return "radius";
        case SegmentPart::Branch:
            return "branch";
        case SegmentPart::From:
            return "from";
        case SegmentPart::To:
            return "to";
        case SegmentPart::Points:
            return "points";
        case SegmentPart::P0:
            return "p0";
        case SegmentPart::T0:
            return "t0";
        case SegmentPart::P3:
            return "p3";
        case SegmentPart::T1:
            return "t1";
        case SegmentPart::PhiStart:
            return "phi_start";
        case SegmentPart::PhiEnd:
            return "phi_end";
    }
    return "";
}

std::string_view fieldKey(Field field) {
    switch (field) {
        case Field::Contour:
            return "contour";
        case Field::Motion:
            return "motion";
        case Field::MotionOmega:
            return "motion.omega_rad_s";
        case Field::MotionRpm:
            return "motion.rpm";
        case Field::MotionPeriod:
            return "motion.period_s";
        case Field::FollowerOffset:
            return "follower.offset";
        case Field::FollowerRadius:
            return "follower.radius";
        case Field::FollowerMaxPressureAngle:
            return "follower.max_pressure_angle_deg";
        case Field::FollowerType:
            return "follower.type";
        case Field::FollowerPivot:
            return "follower.pivot";
        case Field::FollowerArmLength:
            return "follower.arm_length";
        case Field::FollowerClosure:
            return "follower.closure";
        case Field::FollowerGrooveClearance:
            return "follower.groove_clearance_mm";
        case Field::FollowerInnerLandRadius:
            return "follower.inner_land_radius_mm";
        case Field::FollowerOuterLandRadius:
            return "follower.outer_land_radius_mm";
        case Field::FollowerConjugateDistance:
            return "follower.conjugate_distance_mm";
        case Field::FollowerConjugateRadius:
            return "follower.conjugate_radius_mm";
        case Field::FollowerConjugateAngle:
            return "follower.conjugate_angle_deg";
        case Field::FollowerConjugateArmLength:
            return "follower.conjugate_arm_length_mm";
        case Field::SamplesPerTurn:
            return "sampling.samples_per_turn";
        case Field::MachiningAxisAccel:
            return "machining.axis_accel";
        case Field::MachiningAxisVmax:
            return "machining.axis_vmax";
        case Field::MachiningFeedMax:
            return "machining.feed_max";
        case Field::MachiningToolRadius:
            return "machining.tool_radius";
        case Field::MachiningStep:
            return "machining.step";
        case Field::Design:
            return "design";
        case Field::DesignBaseRadius:
            return "design.base_radius";
        case Field::DesignTolerance:
            return "design.tolerance";
        case Field::DesignSegments:
            return "design.segments";
        case Field::Points:
            return "points";
        case Field::Point:
            return "point";
        case Field::Bulge:
            return "bulge";
        case Field::ApproximationError:
            return "error";
        case Field::MachineAccel:
            return "accel";
        case Field::MachineVmax:
            return "vmax";
        case Field::MachineFeed:
            return "feed";
        case Field::Path:
            return "path";
        case Field::SeedStep:
            return "step";
        case Field::StepOption:
            return "--step";
        case Field::ToleranceOption:
            return "--tolerance";
        case Field::ToolRadiusOption:
            return "--tool-radius";
        case Field::CompensationOption:
            return "--compensation";
        case Field::DepthOption:
            return "--depth";
        case Field::StepDownOption:
            return "--step-down";
        case Field::PointsOption:
            return "--points";
        case Field::GcodeSafeZ:
            return "safeZMm";
        case Field::GcodeFeed:
            return "feedMmMin";
        case Field::GcodeToolNumber:
            return "toolNumber";
    }
    return "";
}

std::string_view designPartKey(DesignPart part) {
    switch (part) {
        case DesignPart::Whole:
            return "";
        case DesignPart::Law:
            return "law";
        case DesignPart::ToDeg:
            return "to_deg";
        case DesignPart::Lift:
            return "lift";
        case DesignPart::V0:
            return "v0";
        case DesignPart::A0:
            return "a0";
        case DesignPart::V1:
            return "v1";
        case DesignPart::A1:
            return "a1";
        case DesignPart::J0:
            return "j0";
        case DesignPart::J1:
            return "j1";
        case DesignPart::Lambda:
            return "lambda";
        case DesignPart::SccaB:
            return "b";
        case DesignPart::SccaD:
            return "d";
        case DesignPart::Points:
            return "points";
    }
    return "";
}

std::string dynamicsKeyPath(DynamicsKey key) {
    std::string path = "dynamics.";
    if (const std::string_view group = dynamicsKeyGroup(key); !group.empty()) {
        path.append(group).append(1, '.');
    }
    return path.append(dynamicsKeyName(key));
}

std::string locationText(const Place& place) {
    return std::visit(
        [](const auto& p) -> std::string {
            using P = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<P, std::monostate>) {
                return {};
            } else if constexpr (std::is_same_v<P, SegmentPlace>) {
                return segmentFieldText(p);
            } else if constexpr (std::is_same_v<P, JointPlace>) {
                return segmentLocation(p.left) + "/" + segmentLocation(p.right);
            } else if constexpr (std::is_same_v<P, TurnPlace>) {
                return std::string(fieldKey(Field::Contour));
            } else if constexpr (std::is_same_v<P, FieldPlace>) {
                std::string text(fieldKey(p.field));
                if (p.index >= 0) text += bracketed(static_cast<std::size_t>(p.index));
                return text;
            } else if constexpr (std::is_same_v<P, DesignSegmentPlace>) {
                return dotted(designSegmentText(p.segment), designPartKey(p.part));
            } else if constexpr (std::is_same_v<P, DesignJointPlace>) {
                return designSegmentText(p.left) + "/" + designSegmentText(p.right);
            } else if constexpr (std::is_same_v<P, FilePositionPlace>) {
                return filePositionText(p);
            } else if constexpr (std::is_same_v<P, FileKeyPlace>) {
                return p.key;
            } else if constexpr (std::is_same_v<P, FilePlace>) {
                return p.path;
            } else if constexpr (std::is_same_v<P, SamplePlace>) {
                std::string text = "sample ";
                text.append(std::to_string(p.sample)).append(", ").append(p.quantity);
                return text;
            } else {
                static_assert(std::is_same_v<P, DynamicsPlace>);
                return dynamicsKeyPath(p.key);
            }
        },
        place);
}

std::vector<SegmentPlace> segmentFields(const Place& place) {
    if (const auto* field = std::get_if<SegmentPlace>(&place)) return {*field};
    if (const auto* joint = std::get_if<JointPlace>(&place)) {
        return {{joint->left, SegmentPart::PhiEnd}, {joint->right, SegmentPart::PhiStart}};
    }
    if (const auto* turn = std::get_if<TurnPlace>(&place)) {
        return {{0, SegmentPart::PhiStart}, {turn->last, SegmentPart::PhiEnd}};
    }
    return {};
}

}  // namespace cam
