#include <ivis/render/curved_ray.h>

#include <ivis/render/line_sampler.h>

#include <ivis/core/ray_box.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/common.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivis::render {

core::Bounds3 hullBounds(const core::Bounds3& meshBounds, float hullOffset, float voxelSize)
{
    core::Bounds3 box = meshBounds;
    const double grow = double(hullOffset) + voxelSize, half = vdb::kBoxHalfExtent;
    box.lo = glm::max(box.lo - grow, glm::dvec3(-half));
    box.hi = glm::min(box.hi + grow, glm::dvec3(half));
    return box;
}

namespace {

constexpr float kMinHullStep = 1e-4f;  ///< the backward hull search's smallest step

/// The crossing of phi = phi0 between @a lo (excess phi - phi0 <= 0) and @a hi (excess > 0) by
/// regula falsi with the Illinois rule (Dowell & Jarratt 1971): phi is smooth along the ray, so a
/// few samples reach what bisection to the same 1e-5 needed about ten for. Returns a parameter on
/// the outside within 1e-5 of the crossing, or one whose excess is below 1e-6.
float refineHullCrossing(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                         float hullOffset, float lo, float excessLo, float hi, float excessHi)
{
    int lastSide = 0;  // -1: lo moved last, +1: hi moved last
    for (int i = 0; i < 64 && hi - lo > 1e-5f; ++i) {
        const float mid = std::clamp(lo + (hi - lo) * excessLo / (excessLo - excessHi), lo, hi);
        const float excess = sampler.phi(origin + mid * direction) - hullOffset;
        if (std::abs(excess) < 1e-6f) return mid;
        if (excess <= 0.0f) {
            lo = mid, excessLo = excess;
            if (lastSide < 0) excessHi *= 0.5f;
            lastSide = -1;
        } else {
            hi = mid, excessHi = excess;
            if (lastSide > 0) excessLo *= 0.5f;
            lastSide = 1;
        }
    }
    return hi;
}

/// findHullExit's search of the parameters [tEnter, tStart], none beyond tStart inside the hull.
bool findHullExitFrom(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                      float hullOffset, float tEnter, float tStart, glm::vec3& seed)
{
    float tOutside = tStart;  // last parameter known to be outside the hull (phi > phi0)
    float excessOutside = 0.0f;
    float t = tStart;
    while (t >= tEnter) {
        const float excess = sampler.phi(origin + t * direction) - hullOffset;
        if (excess <= 0.0f) {
            seed = origin + refineHullCrossing(sampler, origin, direction, hullOffset, t, excess, tOutside,
                                               excessOutside) * direction;
            return true;
        }
        tOutside = t;
        excessOutside = excess;
        t -= std::max(excess, kMinHullStep);
    }
    return false;
}

}  // namespace

bool findHullExit(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                  float hullOffset, const core::Bounds3& hullBox, glm::vec3& seed)
{
    float tEnter, tExit;
    if (!core::rayBoxInterval(origin, direction, hullBox, tEnter, tExit)) return false;
    return findHullExitFrom(sampler, origin, direction, hullOffset, tEnter, tExit, seed);
}

void findHullExits(DistanceField::Sampler& sampler, const glm::vec3* origins, const glm::vec3* directions,
                   std::size_t count, float hullOffset, const core::Bounds3& hullBox, glm::vec3* seeds, bool* found)
{
    constexpr std::size_t kGroup = 8;
    const float stopExcess = sampler.field().voxelSize();
    for (std::size_t first = 0; first < count; first += kGroup) {
        const std::size_t n = std::min(kGroup, count - first);
        const std::size_t centre = first + n / 2;
        // The group's rays stay within a + b t of the central ray at parameter t (unit directions).
        float a = 0.0f, b = 0.0f, tNear = std::numeric_limits<float>::max(), tFar = -1.0f;
        float tEnter[kGroup], tExit[kGroup];
        bool inBox[kGroup];
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t r = first + i;
            inBox[i] = core::rayBoxInterval(origins[r], directions[r], hullBox, tEnter[i], tExit[i]);
            if (!inBox[i]) continue;
            a = std::max(a, glm::length(origins[r] - origins[centre]));
            b = std::max(b, glm::length(directions[r] - directions[centre]));
            tNear = std::min(tNear, tEnter[i]);
            tFar = std::max(tFar, tExit[i]);
        }
        // March the cone backward from the farthest exit: where phi on the central ray exceeds the
        // hull offset by more than the cone's radius, no ray of the group meets the hull within
        // that excess (phi is 1-Lipschitz), so each ray's own search starts where the cone stops.
        float t = tFar;
        while (t >= tNear) {
            const float excess = sampler.phi(origins[centre] + t * directions[centre]) - hullOffset - (a + b * t);
            if (excess < stopExcess) break;
            t -= excess;
        }
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t r = first + i;
            found[r] = false;
            if (!inBox[i] || t < tEnter[i]) continue;  // outside the box, or the cone cleared its interval
            found[r] = findHullExitFrom(sampler, origins[r], directions[r], hullOffset, tEnter[i],
                                        std::min(t, tExit[i]), seeds[r]);
        }
    }
}

namespace {

/// The golden-section search for the least phi along @a line within [lo, hi]: the parameter of a
/// local minimum there (to 1e-5).
float goldenMinimum(LineSampler& line, float lo, float hi)
{
    // Each step keeps one inner point of the last (it lies at the golden ratio of the new interval).
    const float ratio = kGoldenSectionRatio;
    float a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
    float phiA = line.phi(a), phiB = line.phi(b);
    for (int k = 0; k < 64 && hi - lo > 1e-5f; ++k) {  // far from the origin a float step exceeds 1e-5
        if (phiA < phiB) {
            hi = b, b = a, phiB = phiA;
            a = hi - ratio * (hi - lo);
            phiA = line.phi(a);
        } else {
            lo = a, a = b, phiA = phiB;
            b = lo + ratio * (hi - lo);
            phiB = line.phi(b);
        }
    }
    return 0.5f * (lo + hi);
}

/// The seed of findClosestApproach from the valley's bottom @a tMin of @a line within [tEnter,
/// tExit]: the centre of the valley round it.
bool valleyCentre(LineSampler& line, float hullOffset, float tEnter, float tExit, float tMin, glm::vec3& seed,
                  float& distance)
{
    DistanceField::Sampler& sampler = line.sampler();
    // The seed: the centre of the valley round that minimum, where phi stays within a voxel of it
    // (each sample weighted by how far below that it lies). Where a view ray skims a surface (a
    // concave crease, a flat face) phi barely rises along it, and its lowest point jumps from
    // pixel to pixel between the voxel-sized bumps of the trilinear field: the rings there showed
    // flames of the surface behind. The valley's centre moves continuously with the ray.
    const float tolerance = kClosestApproachSpacing * sampler.field().voxelSize();
    const float phiMin = line.phi(tMin);
    const float depth = kClosestApproachValley * sampler.field().voxelSize();
    float weights = 0.0f, weighted = 0.0f;
    for (const float side : {-1.0f, 1.0f})
        for (float s = side > 0.0f ? tolerance : 0.0f;; s += tolerance) {
            const float t = tMin + side * s;
            if (t < tEnter || t > tExit) break;
            const float below = depth - (line.phi(t) - phiMin);
            if (!(below > 0.0f)) break;
            weights += below;
            weighted += below * t;
        }
    seed = line.point(weights > 0.0f ? weighted / weights : tMin);
    distance = sampler.phi(seed);
    return distance < hullOffset;
}

/// The golden-section minimum of @a line within @a within of @a guess and within [tEnter, tExit]
/// into @a tMin; false when that bracket is empty.
bool goldenMinimumNear(LineSampler& line, float tEnter, float tExit, float guess, float within, float& tMin)
{
    const float lo = std::max(tEnter, guess - within), hi = std::min(tExit, guess + within);
    if (!(lo < hi)) return false;
    tMin = goldenMinimum(line, lo, hi);
    return true;
}

/// A march along @a line within [tEnter, tExit] every @a step or farther, from the least phi
/// @a best seen so far (at @a tBest), which it lowers: phi is 1-Lipschitz, so nothing before
/// t + (phi - best) comes below best (or below the hull, while best is the hull offset), nor
/// anything in the rest of a far cell whose quartic is bounded below by best (LineSampler::skipAbove).
void marchForLeast(LineSampler& line, float tEnter, float tExit, float step, float& best, float& tBest)
{
    for (float t = tEnter, lastStep = tExit - tEnter; t < tExit;) {
        const float phi = line.phiMarching(t, lastStep);
        if (phi < best) best = phi, tBest = t;
        const float next = line.skipAbove(t, t + std::max(phi - best, step), best);
        lastStep = next - t;
        t = next;
    }
}

/// findClosestApproach from the fine march on, @a best (at @a tBest) bounding the least phi from
/// above; @a bestIsMinimum when tBest is a golden-section minimum already, which stands unless the
/// march finds less.
bool closestApproachFrom(LineSampler& line, float hullOffset, float tEnter, float tExit, float best, float tBest,
                         bool bestIsMinimum, glm::vec3& seed, float& distance, float* bottom)
{
    const float tolerance = kClosestApproachSpacing * line.sampler().field().voxelSize();
    const float before = best;
    marchForLeast(line, tEnter, tExit, tolerance, best, tBest);
    if (!(best < hullOffset)) return false;
    // Golden-section search for the minimum around the best sample.
    const float tMin = bestIsMinimum && best == before
                           ? tBest
                           : goldenMinimum(line, std::max(tEnter, tBest - 2.0f * tolerance),
                                           std::min(tExit, tBest + 2.0f * tolerance));
    if (bottom) *bottom = tMin;
    return valleyCentre(line, hullOffset, tEnter, tExit, tMin, seed, distance);
}

}  // namespace

bool findClosestApproach(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                         float hullOffset, const core::Bounds3& hullBox, glm::vec3& seed, float& distance, float* bottom)
{
    float tEnter, tExit;
    if (!core::rayBoxInterval(origin, direction, hullBox, tEnter, tExit)) return false;
    const float tolerance = kClosestApproachSpacing * sampler.field().voxelSize();
    LineSampler line(sampler, origin, direction);
    // A coarse march first: its best sample bounds the minimum from above, so the fine march
    // skips by phi - best from the start instead of creeping down the slope toward it.
    float best = hullOffset, tBest = tEnter;
    marchForLeast(line, tEnter, tExit, kClosestApproachCoarseSteps * tolerance, best, tBest);
    return closestApproachFrom(line, hullOffset, tEnter, tExit, best, tBest, false, seed, distance, bottom);
}

bool findClosestApproachHinted(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                               float hullOffset, const core::Bounds3& hullBox, float bottomHint, float reach,
                               glm::vec3& seed, float& distance, float* bottom)
{
    float tEnter, tExit;
    if (!core::rayBoxInterval(origin, direction, hullBox, tEnter, tExit)) return false;
    LineSampler line(sampler, origin, direction);
    const float tolerance = kClosestApproachSpacing * sampler.field().voxelSize();
    float best = hullOffset, tBest = tEnter, tHint;
    bool insideBracket = false;  // a minimum strictly inside the hint's bracket, not at its end
    if (goldenMinimumNear(line, tEnter, tExit, bottomHint, reach, tHint)) {
        const float phiHint = line.phi(tHint);
        if (phiHint < best) {
            best = phiHint, tBest = tHint;
            insideBracket = std::abs(tHint - bottomHint) < reach - tolerance && tHint > tEnter + tolerance &&
                            tHint < tExit - tolerance;
        }
    }
    if (!(best < hullOffset))  // nothing near the hint: the coarse march after all
        marchForLeast(line, tEnter, tExit, kClosestApproachCoarseSteps * tolerance, best, tBest);
    return closestApproachFrom(line, hullOffset, tEnter, tExit, best, tBest, insideBracket, seed, distance, bottom);
}

bool findClosestApproachNear(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                             float hullOffset, const core::Bounds3& hullBox, float bottomGuess, float reach,
                             glm::vec3& seed, float& distance, float* bottom)
{
    float tEnter, tExit;
    if (!core::rayBoxInterval(origin, direction, hullBox, tEnter, tExit)) return false;
    const float within = reach + 2.0f * kClosestApproachSpacing * sampler.field().voxelSize();
    LineSampler line(sampler, origin, direction);
    float tMin;
    if (!goldenMinimumNear(line, tEnter, tExit, bottomGuess, within, tMin)) return false;
    if (bottom) *bottom = tMin;
    return valleyCentre(line, hullOffset, tEnter, tExit, tMin, seed, distance);
}

glm::vec3 initialVelocity(const glm::vec3& gradient, const glm::vec3& viewDirection, float alpha)
{
    const float length = glm::length(gradient);
    if (!(length > 0.0f)) return alpha * viewDirection;
    const glm::vec3 g = gradient / length;
    return alpha * glm::cross(g, glm::cross(viewDirection, g));
}

float landingEpsilon(const CurvedRayParams& params, const DistanceField& field)
{
    return params.landingVoxels * field.voxelSize();
}

}  // namespace ivis::render
