#include <ivis/render/curved_ray_method.h>

#include <ivis/render/tangent_planes.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <memory>
#include <vector>

namespace ivis::render {

const char* describe(Refusal refusal)
{
    switch (refusal) {
    case Refusal::None: return nullptr;
    case Refusal::NoSeed: return "no seed: its view ray does not come within the hull";
    case Refusal::NoSurfaceNearSeed: return "no surface near its seed";
    case Refusal::BeyondRing: return "beyond its ring";
    case Refusal::DoesNotLand: return "its ray does not land";
    case Refusal::NeighbourDoesNotLand: return "a neighbouring pixel's ray does not land";
    case Refusal::Unstable: return "its landing is unstable";
    }
    return nullptr;
}

std::vector<ParameterSpec> curvedRaySpecs(const CurvedRayParams& defaults)
{
    return {ParameterSpec{"hull_offset", "hull distance phi0 (normalised units; below the volume's --reach)",
                          {defaults.hullOffset}, 0.01f, 1.9f}
                .belowTheReach(),
            ParameterSpec{"step", "symplectic Euler step h", {defaults.stepSize}, 0.001f, 1.0f}.ofTheTracer(),
            ParameterSpec{"max_steps", "steps before a curved ray counts as a miss", {float(defaults.maxSteps)}, 1.0f,
                          100000.0f}
                .wholeNumbers()
                .ofTheTracer()};
}

CurvedRayParams curvedRayParamsFrom(const ParameterValues& values)
{
    CurvedRayParams params;
    params.hullOffset = values.at("hull_offset")[0];
    params.stepSize = values.at("step")[0];
    params.maxSteps = int(values.at("max_steps")[0]);
    return params;
}

ParameterValues curvedRayValues(const CurvedRayParams& params)
{
    return {{"hull_offset", {params.hullOffset}}, {"step", {params.stepSize}}, {"max_steps", {float(params.maxSteps)}}};
}

std::unique_ptr<IndirectMap> CurvedRayMethod::indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const
{
    return std::make_unique<CurvedRayMap>(scene, frame, *this);
}

PictureExtent CurvedRayMethod::pictureExtent(const RenderScene& scene, const core::Camera& camera) const
{
    return offsetMeshExtent(scene.vertices(), camera, mRay.hullOffset);
}

CurvedRayMap::CurvedRayMap(const RenderScene& scene, const core::CameraFrame& frame, const CurvedRayMethod& method)
    : mScene(scene),
      mFrame(frame),
      mMethod(method),
      mHullBox(hullBounds(scene.bounds(), method.rayParams().hullOffset, scene.distance().voxelSize())),
      mEpsilon(landingEpsilon(method.rayParams(), scene.distance()))
{
}

bool CurvedRayMap::seedFromRay(const core::CameraRay& ray, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    const glm::vec3 direction(ray.direction);
    const float hullOffset = mMethod.rayParams().hullOffset;
    const bool seeded =
        mMethod.seedRule() == SeedRule::ClosestApproach
            ? findClosestApproach(sampler, glm::vec3(ray.origin), direction, hullOffset, mHullBox, start.seed,
                                  start.seedDistance, &start.valleyBottom)
            : findHullExit(sampler, glm::vec3(ray.origin), direction, hullOffset, mHullBox, start.seed);
    return aimFromFoundSeed(glm::vec3(ray.origin), direction, seeded, sampler, start);
}

bool CurvedRayMap::aimedStartNear(double x, double y, float bottomGuess, float reach, DistanceField::Sampler& sampler,
                                  CurvedRayStart& start) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    const glm::vec3 origin(ray.origin), direction(ray.direction);
    return aimFromFoundSeed(
        origin, direction,
        findClosestApproachNear(sampler, origin, direction, mMethod.rayParams().hullOffset, mHullBox, bottomGuess,
                                reach, start.seed, start.seedDistance, &start.valleyBottom),
        sampler, start);
}

bool CurvedRayMap::aimedStartHinted(double x, double y, float bottomHint, float reach, DistanceField::Sampler& sampler,
                                    CurvedRayStart& start) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    const glm::vec3 origin(ray.origin), direction(ray.direction);
    return aimFromFoundSeed(
        origin, direction,
        findClosestApproachHinted(sampler, origin, direction, mMethod.rayParams().hullOffset, mHullBox, bottomHint,
                                  reach, start.seed, start.seedDistance, &start.valleyBottom),
        sampler, start);
}

bool CurvedRayMap::aimFromFoundSeed(const glm::vec3& origin, const glm::vec3& direction, bool seeded,
                                    DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    if (!seeded) {
        start.refusal = Refusal::NoSeed;
        return false;
    }
    start.rayParameter = glm::dot(start.seed - origin, direction);
    return aimFromSeed(direction, sampler, start);
}

float CurvedRayMap::pixelFootprint(const glm::vec3& p) const
{
    const double perUnit = 2.0 * mFrame.imagePlaneHalfHeight() / mFrame.height();
    const core::Camera& camera = mFrame.camera();
    return float(camera.orthographic ? perUnit : perUnit * glm::length(glm::dvec3(p) - camera.eye));
}

bool CurvedRayMap::aimFromSeed(const glm::vec3& direction, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    start.seedDistance = sampler.phiAndGradient(start.seed, start.gradient);
    start.tangent = initialVelocity(start.gradient, direction, 1.0f);
    const float length = glm::length(start.gradient);
    start.alignment = length > 0.0f ? glm::dot(direction, start.gradient) / length : 0.0f;
    return mMethod.aim(*this, start, sampler);
}

bool CurvedRayMap::aimedStart(double x, double y, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    return seedFromRay(mFrame.ray(x, y), sampler, start);
}

bool CurvedRayMap::hitsSurface(double x, double y) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    return mScene.bvh().intersect(glm::vec3(ray.origin), glm::vec3(ray.direction)).hit();
}

bool CurvedRayMap::start(double x, double y, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    return !hitsSurface(x, y) && aimedStart(x, y, sampler, start) && isStable(start, sampler);
}

void CurvedRayMap::startMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                             CurvedRayStart* starts, bool* drawn) const
{
    std::vector<CurvedRayStart*> aimed;
    std::vector<std::size_t> pixels;  // the position of each aimed start
    for (std::size_t i = 0; i < count; ++i) {
        drawn[i] = false;
        const glm::dvec2& p = positions[i];
        if (!hitsSurface(p.x, p.y) && aimedStart(p.x, p.y, sampler, starts[i])) {
            aimed.push_back(&starts[i]);
            pixels.push_back(i);
        }
    }
    std::unique_ptr<bool[]> stable(new bool[aimed.size()]);
    areStable(aimed.data(), aimed.size(), sampler, stable.get());
    for (std::size_t j = 0; j < aimed.size(); ++j) drawn[pixels[j]] = stable[j];
}

bool CurvedRayMap::isStable(CurvedRayStart& start, DistanceField::Sampler& sampler) const
{
    CurvedRayStart* one = &start;
    bool stable = false;
    areStable(&one, 1, sampler, &stable);
    return stable;
}

void CurvedRayMap::areStable(CurvedRayStart* const* starts, std::size_t count, DistanceField::Sampler& sampler,
                             bool* stable) const
{
    if (!mMethod.stabilityScale()) {  // no rule: every ray is drawn
        std::fill(stable, stable + count, true);
        return;
    }
    constexpr int kProbes = CurvedRayMethod::kMaxStabilityProbes;
    // The own rays not traced yet, then the probes of those that landed, all traced together.
    std::vector<CurvedRayStart> own;
    std::vector<std::size_t> owner;
    for (std::size_t i = 0; i < count; ++i)
        if (!starts[i]->traced) own.push_back(*starts[i]), owner.push_back(i);
    std::vector<CurvedRayTrace> ownTraces(own.size());
    traceMany(own.data(), own.size(), sampler, ownTraces.data());
    for (std::size_t k = 0; k < own.size(); ++k) starts[owner[k]]->traced = ownTraces[k].end;

    std::vector<CurvedRayStart> probes;
    std::vector<int> probeCount(count, 0);
    CurvedRayStart buffer[kProbes];
    for (std::size_t i = 0; i < count; ++i) {
        if (!starts[i]->traced->landed) continue;
        probeCount[i] = mMethod.stabilityProbes(*starts[i], buffer);
        probes.insert(probes.end(), buffer, buffer + probeCount[i]);
    }
    std::vector<CurvedRayTrace> probeTraces(probes.size());
    traceMany(probes.data(), probes.size(), sampler, probeTraces.data());
    std::size_t next = 0;
    for (std::size_t i = 0; i < count; ++i) {
        CurvedRayEnd ends[kProbes];
        for (int k = 0; k < probeCount[i]; ++k) ends[k] = probeTraces[next++].end;
        stable[i] = mMethod.isStable(*starts[i], *starts[i]->traced, ends);
    }
}

CurvedRayTrace CurvedRayMap::trace(const CurvedRayStart& start, DistanceField::Sampler& sampler) const
{
    CurvedRayTrace result;
    traceMany(&start, 1, sampler, &result);
    return result;
}

namespace {

/// CurvedRayMap::traceMany() of @a method's rays landing below @a epsilon, on tangent planes where
/// @a kPlanes.
template <bool kPlanes>
void traceInLanes(const CurvedRayMethod& method, float epsilon, const CurvedRayStart* starts, std::size_t count,
                  DistanceField::Sampler& sampler, CurvedRayTrace* traces)
{
    struct Lane {
        std::size_t ray;
        int launch;
        glm::vec3 launchVelocity;
        CurvedRayFlight flight;
    };
    const CurvedRayParams& params = method.rayParams();
    const float escape = escapeDistance(sampler.field());
    const TangentPlaneRule planes = tangentPlaneRule(sampler.field().voxelSize());
    auto launch = [&](Lane& lane, std::size_t ray, int launchIndex) {
        const glm::vec3 velocity = method.launchVelocity(starts[ray], launchIndex);
        lane = Lane{ray, launchIndex, velocity, CurvedRayFlight(starts[ray].seed, velocity)};
    };
    Lane lanes[CurvedRayMap::kLanes];
    int live = 0;
    std::size_t next = 0;
    // Moves next past the rays their method traced while aiming them, recording those as they are.
    auto moreToTrace = [&] {
        for (; next < count && starts[next].traced; ++next) traces[next] = {*starts[next].traced, 0};
        return next < count;
    };
    for (; live < CurvedRayMap::kLanes && moreToTrace(); ++live) launch(lanes[live], next++, 0);
    while (live > 0) {
        for (int k = 0; k < live;) {
            Lane& lane = lanes[k];
            if (lane.flight.end().steps < params.maxSteps &&
                lane.flight.template advance<kPlanes>(sampler, planes, params.stepSize, epsilon, escape)) {
                ++k;
                continue;
            }
            // This launch has ended: launch again while it did not land (as the method says), else
            // record it and take the next ray.
            const CurvedRayEnd& end = lane.flight.end();
            if (!end.landed && lane.launch != method.relaunches() && lane.launchVelocity != glm::vec3(0.0f)) {
                launch(lane, lane.ray, lane.launch + 1);
            } else {
                traces[lane.ray] = {end, lane.launch};
                if (moreToTrace()) {
                    launch(lane, next++, 0);
                } else {
                    lanes[k] = lanes[--live];  // slot k now holds the last lane: step it next
                    continue;
                }
            }
            ++k;
        }
    }
}

}  // namespace

void CurvedRayMap::traceMany(const CurvedRayStart* starts, std::size_t count, DistanceField::Sampler& sampler,
                             CurvedRayTrace* traces) const
{
    // Tangent planes pay only where a fine band of voxels finer than the far field's serves the
    // landings (docs/rendering.md, "Tangent planes near the landing").
    if (sampler.field().hasFineBand())
        traceInLanes<true>(mMethod, mEpsilon, starts, count, sampler, traces);
    else
        traceInLanes<false>(mMethod, mEpsilon, starts, count, sampler, traces);
}

void CurvedRayMap::mapMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                           PixelMapping* mappings) const
{
    std::vector<CurvedRayStart> starts;
    std::vector<std::size_t> pixels;  // the pixel of each start
    auto keep = [&](std::size_t i, bool aimed, const CurvedRayStart& start) {
        mappings[i] = {};
        if (!aimed) return;
        starts.push_back(start);
        pixels.push_back(i);
    };
    if (mMethod.seedRule() == SeedRule::HullExit) {
        // Seed the pixels' rays together (findHullExits clears neighbouring rays at once).
        std::vector<glm::vec3> origins(count), directions(count), seeds(count);
        std::unique_ptr<bool[]> found(new bool[count]);
        for (std::size_t i = 0; i < count; ++i) {
            const core::CameraRay ray = mFrame.ray(positions[i].x, positions[i].y);
            origins[i] = glm::vec3(ray.origin);
            directions[i] = glm::vec3(ray.direction);
        }
        findHullExits(sampler, origins.data(), directions.data(), count, mMethod.rayParams().hullOffset, mHullBox,
                      seeds.data(), found.get());
        for (std::size_t i = 0; i < count; ++i) {
            CurvedRayStart start;
            start.seed = seeds[i];
            start.rayParameter = glm::dot(seeds[i] - origins[i], directions[i]);
            keep(i, found[i] && aimFromSeed(directions[i], sampler, start), start);
        }
    } else {
        for (std::size_t i = 0; i < count; ++i) {
            CurvedRayStart start;
            keep(i, seedFromRay(mFrame.ray(positions[i].x, positions[i].y), sampler, start), start);
        }
    }
    // The stability rule on them all, then the landings of those it draws.
    std::vector<CurvedRayStart*> judged(starts.size());
    for (std::size_t j = 0; j < starts.size(); ++j) judged[j] = &starts[j];
    std::unique_ptr<bool[]> stable(new bool[starts.size()]);
    areStable(judged.data(), judged.size(), sampler, stable.get());
    std::size_t drawn = 0;
    for (std::size_t j = 0; j < starts.size(); ++j)
        if (stable[j]) starts[drawn] = starts[j], pixels[drawn++] = pixels[j];
    starts.resize(drawn);
    std::vector<PixelMapping> landings(drawn);
    landingMany(starts.data(), drawn, sampler, landings.data());
    for (std::size_t j = 0; j < drawn; ++j) mappings[pixels[j]] = landings[j];
}

void CurvedRayMap::landingMany(const CurvedRayStart* starts, std::size_t count, DistanceField::Sampler& sampler,
                               PixelMapping* mappings) const
{
    std::vector<CurvedRayTrace> traces(count);
    traceMany(starts, count, sampler, traces.data());
    for (std::size_t i = 0; i < count; ++i) {
        const CurvedRayEnd& end = traces[i].end;
        mappings[i] = end.landed ? landedAt(end, sampler) : launchedMiss(end.steps);
    }
}

PixelMapping CurvedRayMap::landedAt(const CurvedRayEnd& end, DistanceField::Sampler& sampler) const
{
    return render::landedAt(mScene, mFrame, end.position, end.velocity, end.steps, sampler);
}

PixelMapping CurvedRayMap::landing(const CurvedRayStart& start, DistanceField::Sampler& sampler) const
{
    const CurvedRayEnd end = trace(start, sampler).end;
    return end.landed ? landedAt(end, sampler) : launchedMiss(end.steps);
}

PixelMapping CurvedRayMap::map(double x, double y, DistanceField::Sampler& sampler) const
{
    CurvedRayStart start;
    if (!seedFromRay(mFrame.ray(x, y), sampler, start) || !isStable(start, sampler)) return {};
    return landing(start, sampler);
}

}  // namespace ivis::render
