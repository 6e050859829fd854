#include "timing/timing_job.h"

#include <algorithm>
#include <utility>

#include "timing/seed_method.h"

namespace cam {

TimingJob timingJobFor(const MachiningSpec& machining, std::vector<TimingMethod> methods) {
    TimingJob job;
    job.toolRadiusMm = machining.toolRadius;
    job.limits = limitsFromProject(machining);
    job.methods = std::move(methods);
    return job;
}

Result<TimedPath> timeContour(const Contour& contour, const TimingJob& job,
                              const std::atomic<bool>* cancel) {
    auto path = toolPathFromContour(contour, job.toolRadiusMm, cancel);
    if (!path.ok()) return path.errors();
    return timePath(std::move(path).value(), job, cancel);
}

Result<TimedPath> timePath(ToolPath path, const TimingJob& job, const std::atomic<bool>* cancel) {
    const bool seed =
        job.profileMethod == TimingMethod::Seed ||
        std::find(job.methods.begin(), job.methods.end(), TimingMethod::Seed) != job.methods.end();
    if (seed) {
        // Refused before anything is computed, and named after where the step came from.
        const Diagnostics step = checkSeedStep(path, job.limits.seedStep, job.stepField);
        if (!step.empty()) return step;
    }
    TimedPath timed;
    timed.path = std::move(path);
    for (const TimingMethod method : job.methods) {
        auto result = machiningTime(timed.path, job.limits, method, cancel);
        if (!result.ok()) return result.errors();
        timed.results.push_back(std::move(result).value());
    }
    if (job.profileMethod) {
        auto profile =
            timingProfile(timed.path, job.limits, *job.profileMethod, job.profilePoints, cancel);
        if (!profile.ok()) return profile.errors();
        timed.profile = std::move(profile).value();
    }
    return timed;
}

}  // namespace cam
