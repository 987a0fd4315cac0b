/// @file curved_ray_method.h
/// @brief What the curved-ray methods share (docs/method.md, "InverseVis, I-"): a seed on the hull
///        {phi = phi0} where the view ray leaves it, a launch velocity that each method chooses,
///        and the symplectic integration onto the surface.
#pragma once

#include <ivis/render/curved_ray.h>
#include <ivis/render/method.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace ivis::render {

/// @brief Why a pixel whose view ray misses the surface gets no curved ray.
enum class Refusal : std::uint8_t {
    None,                ///< a ray is drawn
    NoSeed,              ///< the view ray does not come within the hull (no seed)
    NoSurfaceNearSeed,   ///< the method finds no surface near the seed
    BeyondRing,          ///< the seed lies beyond its ring (the wrap's rings)
    DoesNotLand,         ///< the ray does not land
    NeighbourDoesNotLand,  ///< a neighbouring pixel's ray does not land (the stability rule)
    Unstable             ///< the landing is unstable (the stability rule)
};

/// @brief The refusal in words, as a probe tells it ("beyond its ring"); null for None.
const char* describe(Refusal refusal);

/// @brief Where across its ring a seed lies, for a method whose rays start in rings (the wrap).
struct RingPosition {
    float coordinate = 0.0f;  ///< 0 at the silhouette, 1 at the ring's outer edge
    float width = 0.0f;       ///< the ring's width (normalised units): the seed's distance is coordinate * width
};

/// @brief Start of one pixel's curved ray: where it starts (CurvedRayMap), then how the method
///        launches it (CurvedRayMethod::aim) and whether it draws it (CurvedRayMethod::isStable).
struct CurvedRayStart {
    glm::vec3 seed{};           ///< where the ray starts on its view ray (SeedRule)
    float rayParameter = 0.0f;  ///< the seed's parameter t on its view ray origin + t direction
    float valleyBottom = 0.0f;  ///< closest-approach seeds: the parameter t of the least phi on the view ray
    glm::vec3 gradient{};       ///< grad phi at the seed
    float seedDistance = 0.0f;  ///< phi at the seed
    glm::vec3 tangent{};        ///< g x (r x g), g = gradient / |gradient|: the view direction's part tangential to the hull
    float alignment = 0.0f;     ///< c = r . g
    glm::vec3 launchDirection{};  ///< unit launch direction, where the method aims each ray itself (the wrap)
    float alpha = 0.0f;         ///< launch speed, where the method aims each ray itself (the wrap)
    std::optional<RingPosition> ring;  ///< where across its ring the seed lies, for a method with rings
    float bend = 0.0f;          ///< how far the landing strays from a smooth function of the launch, where
                                ///< the method measures it (the wrap's stability rule); rays bending more
                                ///< than the readable rule's parameter are not drawn (MethodInfo::readableRuleParameter)
    /// The end of the first launch's ray where it was traced already (the wrap's stability rule
    /// traces it), set only where that end is final: CurvedRayMap::traceMany() takes it as it is.
    std::optional<CurvedRayEnd> traced;
    Refusal refusal = Refusal::None;  ///< why the pixel gets no ray, where it gets none
};

/// @brief Where on its view ray a curved ray starts.
enum class SeedRule {
    HullExit,        ///< the farthest crossing with the hull (the paper)
    ClosestApproach  ///< the point of the view ray closest to the surface, within the hull (findClosestApproach)
};

/// @brief The scale of a method's stability rule: a ray is drawn when the landings of the rays
///        seeded @a probeStep further in and out bend from a straight line by at most @a largestBend.
struct StabilityScale {
    float largestBend = 0.0f;  ///< normalised units (the wrap's stable_shift)
    float probeStep = 0.0f;    ///< normalised units between the probes' seeds
};

/// @brief How a launch velocity moves with the optimised parameters: along one direction,
///        dv0 / dparameter_k = perParameter[k] * direction.
struct LaunchSensitivity {
    glm::vec3 direction{0.0f};         ///< the direction in velocity space the launch moves along
    std::vector<double> perParameter;  ///< one entry per optimised component (optimisedParameters order)
};

/// @brief Where a curved ray ended and which launch it was (0: the first).
struct CurvedRayTrace {
    CurvedRayEnd end;
    int launch = 0;
};

/// @brief The descriptions of hull_offset, step and max_steps, shared by the curved-ray methods,
///        with a method's own @a defaults (the wrap's hull is wider than the paper's).
std::vector<ParameterSpec> curvedRaySpecs(const CurvedRayParams& defaults = {});
/// @brief Ray parameters from values keyed as curvedRaySpecs().
CurvedRayParams curvedRayParamsFrom(const ParameterValues& values);
/// @brief Values of the ray parameters, keyed as curvedRaySpecs().
ParameterValues curvedRayValues(const CurvedRayParams& params);

class CurvedRayMap;

/// @brief A method whose indirect rays are curved rays from the hull.
class CurvedRayMethod : public Method {
public:
    /// @brief A curved-ray method whose rays integrate with @a params.
    explicit CurvedRayMethod(const CurvedRayParams& params) : mRay(params) {}
    /// @brief Step size, hull offset, step cap and landing threshold of the rays.
    const CurvedRayParams& rayParams() const { return mRay; }
    /// @brief Initial velocity of launch @a launch (0 first) of the ray from @a start.
    virtual glm::vec3 launchVelocity(const CurvedRayStart& start, int launch) const = 0;
    /// @brief Where the rays start (the paper: the hull exit).
    virtual SeedRule seedRule() const { return SeedRule::HullExit; }
    /// @brief Chooses this ray's own launch once it is seeded (the wrap: start.alpha,
    ///        start.launchDirection, start.ring); the default: nothing.
    /// @return false (start.refusal set) when the pixel gets no ray after all (it shows the background)
    virtual bool aim(const CurvedRayMap& /*rays*/, CurvedRayStart& /*start*/, DistanceField::Sampler& /*sampler*/) const
    {
        return true;
    }
    /// @brief Most probes stabilityProbes() gives.
    static constexpr int kMaxStabilityProbes = 2;
    /// @brief The starts of the rays the stability rule compares an aimed start's ray with (the
    ///        wrap: the seeds of the neighbouring pixels further in and out across its ring), at most
    ///        kMaxStabilityProbes into @a probes; none by default (every ray that lands is drawn).
    /// @return how many
    virtual int stabilityProbes(const CurvedRayStart& /*start*/, CurvedRayStart* /*probes*/) const { return 0; }
    /// @brief The stability rule's verdict on an aimed start from the end of its own ray and of its
    ///        probes' rays (as stabilityProbes() lists them; not traced where its own did not land):
    ///        sets start.bend and, when false, start.refusal.
    /// @return whether its ray is drawn
    virtual bool isStable(CurvedRayStart& /*start*/, const CurvedRayEnd& /*own*/, const CurvedRayEnd* /*probes*/) const
    {
        return true;
    }
    /// @brief The scale of the stability rule, for a method with one (isStable then refuses rays);
    ///        none by default.
    virtual std::optional<StabilityScale> stabilityScale() const { return std::nullopt; }
    /// @brief How often a ray that does not land is launched again.
    virtual int relaunches() const { return 0; }
    /// @brief The sensitivity of launch @a launch's velocity to the optimised parameters; the
    ///        default: none (a method without optimised launch parameters).
    /// @return false where the launch does not move with them (e.g. a clamped alpha)
    virtual bool launchSensitivity(const CurvedRayStart& /*start*/, int /*launch*/,
                                   LaunchSensitivity& /*sensitivity*/) const
    {
        return false;
    }

    /// @brief A CurvedRayMap: each pixel's curved ray traced to where it lands.
    std::unique_ptr<IndirectMap> indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const override;
    bool drawsIndirect() const override { return true; }
    /// @brief The hull {phi = hull_offset}: the mesh grown by the hull offset (offsetMeshExtent).
    PictureExtent pictureExtent(const RenderScene& scene, const core::Camera& camera) const override;
    const CurvedRayMethod* curved() const override { return this; }
    /// @brief The hull offset and 0.6 beyond it (the paper's hull 0.4: 1.0, inversevis-wrap's reach):
    ///        one volume then serves every method at its defaults (docs/volume.md).
    float reachNeeded() const override { return mRay.hullOffset + 0.6f; }

private:
    CurvedRayParams mRay;
};

/// @brief The curved rays of one view: seeds, launches and landings.
/// @warning Thread-safe given one DistanceField::Sampler per thread.
class CurvedRayMap final : public IndirectMap {
public:
    /// @brief The curved rays of @a method seen through @a frame (scene and method must outlive it).
    CurvedRayMap(const RenderScene& scene, const core::CameraFrame& frame, const CurvedRayMethod& method);

    PixelMapping map(double x, double y, DistanceField::Sampler& sampler) const override;
    /// @brief map() of many pixels: seeds them, then traces their rays kLanes at a time in lockstep
    ///        (traceMany), then finds where they landed.
    void mapMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                 PixelMapping* mappings) const override;

    /// @brief Start of the curved ray of pixel position (x, y): seeded, aimed and judged by the
    ///        method's stability rule.
    /// @return false when the view ray hits the surface or the pixel gets no ray (start.refusal says why)
    bool start(double x, double y, DistanceField::Sampler& sampler, CurvedRayStart& start) const;
    /// @brief start() of each of @a count pixel positions into @a starts and @a drawn, the stability
    ///        rule's rays traced together (areStable).
    void startMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                   CurvedRayStart* starts, bool* drawn) const;
    /// @brief Whether the view ray of pixel position (x, y) hits the surface (any face).
    bool hitsSurface(double x, double y) const;
    /// @brief The start of a pixel whose view ray misses the surface, without the stability rule:
    ///        the ray as the method aims it, which isStable() then judges (adaptive image sampling
    ///        judges only the rays it must).
    /// @return false when the pixel gets no ray (start.refusal says why)
    bool aimedStart(double x, double y, DistanceField::Sampler& sampler, CurvedRayStart& start) const;
    /// @brief aimedStart() of a pixel whose valley bottom is sought only within @a reach of
    ///        @a bottomGuess (one interpolated from its neighbours' bottoms:
    ///        findClosestApproachNear), for the closest-approach seed rule.
    /// @return false when the pixel gets no ray (start.refusal says why)
    bool aimedStartNear(double x, double y, float bottomGuess, float reach, DistanceField::Sampler& sampler,
                        CurvedRayStart& start) const;
    /// @brief aimedStart() of a pixel whose seed search starts from a neighbouring bottom
    ///        @a bottomHint (findClosestApproachHinted, within @a reach of it), for the
    ///        closest-approach seed rule.
    /// @return false when the pixel gets no ray (start.refusal says why)
    bool aimedStartHinted(double x, double y, float bottomHint, float reach, DistanceField::Sampler& sampler,
                          CurvedRayStart& start) const;
    /// @brief The distance (normalised) between the view rays of neighbouring pixels at point @a p.
    float pixelFootprint(const glm::vec3& p) const;
    /// @brief The method's stability rule on an aimed start: its own ray traced (unless
    ///        start.traced holds it already; then kept there) and, where it lands, its probes.
    bool isStable(CurvedRayStart& start, DistanceField::Sampler& sampler) const;
    /// @brief isStable() of each of @a count aimed starts into @a stable, every probe traced
    ///        together (traceMany).
    void areStable(CurvedRayStart* const* starts, std::size_t count, DistanceField::Sampler& sampler, bool* stable) const;
    /// @brief Traces the ray of @a start, launching it again while it does not land (as the method says).
    CurvedRayTrace trace(const CurvedRayStart& start, DistanceField::Sampler& sampler) const;
    /// @brief trace() of each of @a count starts into @a traces: kLanes rays step in turn, a lane
    ///        taking the next ray when its own ends, so that the samples of different rays overlap
    ///        in memory latency (about 1.4 times the steps per second of one ray after another);
    ///        a start that carries its traced end (CurvedRayStart::traced) is not traced again.
    void traceMany(const CurvedRayStart* starts, std::size_t count, DistanceField::Sampler& sampler,
                   CurvedRayTrace* traces) const;
    /// @brief Rays traceMany() steps together.
    static constexpr int kLanes = 4;
    /// @brief The surface point the curved ray from @a start lands on (a launched miss if none).
    PixelMapping landing(const CurvedRayStart& start, DistanceField::Sampler& sampler) const;
    /// @brief landing() of each of @a count starts into @a mappings, their rays traced by traceMany().
    void landingMany(const CurvedRayStart* starts, std::size_t count, DistanceField::Sampler& sampler,
                     PixelMapping* mappings) const;
    /// @brief landedAt() for this view.
    PixelMapping landedAt(const CurvedRayEnd& end, DistanceField::Sampler& sampler) const;

    /// @brief The scene the rays fall onto.
    const RenderScene& scene() const { return mScene; }
    /// @brief The method whose rays these are.
    const CurvedRayMethod& method() const { return mMethod; }
    /// @brief The landing threshold used.
    float epsilon() const { return mEpsilon; }

private:
    /// The seed of the view ray and the method's aim (not its stability rule).
    bool seedFromRay(const core::CameraRay& ray, DistanceField::Sampler& sampler, CurvedRayStart& start) const;
    /// The rest of a start whose seed is set: gradient, tangent, alignment, the method's aim.
    bool aimFromSeed(const glm::vec3& direction, DistanceField::Sampler& sampler, CurvedRayStart& start) const;
    /// aimFromSeed() of the view ray origin + t direction when its seed search @a seeded it (its
    /// parameter along the ray set first); else the refusal NoSeed.
    bool aimFromFoundSeed(const glm::vec3& origin, const glm::vec3& direction, bool seeded,
                          DistanceField::Sampler& sampler, CurvedRayStart& start) const;

    const RenderScene& mScene;
    core::CameraFrame mFrame;
    const CurvedRayMethod& mMethod;
    core::Bounds3 mHullBox;
    float mEpsilon;
};

}  // namespace ivis::render
