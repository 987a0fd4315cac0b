/// @file method.h
/// @brief A visualisation method as one object (as pbrt-v4's integrators): its description (name,
///        help, parameters with defaults and bounds, how the optimiser moves them) and, per view,
///        the map of the pixels that miss the surface onto the surface.
/// @note Methods are immutable and shared (std::shared_ptr<const Method>); they are created by
///       name from parameter values with makeMethod() (method_registry.h).
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/triangle_bvh.h>
#include <ivis/render/picture_extent.h>
#include <ivis/render/pixel_mapping.h>
#include <ivis/render/render_scene.h>

#include <glm/vec2.hpp>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ivis::render {

class CurvedRayMethod;
class Method;

/// @brief One named parameter of a method.
struct ParameterSpec {
    std::string key;              ///< JSON key; the command-line option is --key with '_' written '-'
    std::string help;             ///< one line for --help and the viewer's tooltip
    std::vector<float> defaults;  ///< one value per component
    float lo = 0.0f;              ///< lower bound of every component
    float hi = 0.0f;              ///< upper bound of every component
    bool optimised = false;       ///< moved by the parameter ascent
    bool integer = false;         ///< takes whole numbers only
    bool belowReach = false;      ///< a distance that must stay below the volume's reach (e.g. the hull offset)
    bool tracing = false;         ///< the tracer's accuracy (step, step cap, landing), not the picture's design

    /// @brief The command-line option: "--" and the key with '_' written '-'.
    std::string option() const;

    /// @brief This spec, its parameter moved by the parameter ascent (optimised).
    ParameterSpec& movedByTheAscent() { optimised = true; return *this; }
    /// @brief This spec, its parameter taking whole numbers only (integer).
    ParameterSpec& wholeNumbers() { integer = true; return *this; }
    /// @brief This spec, its parameter a distance below the volume's reach (belowReach).
    ParameterSpec& belowTheReach() { belowReach = true; return *this; }
    /// @brief This spec, its parameter the tracer's accuracy (tracing).
    ParameterSpec& ofTheTracer() { tracing = true; return *this; }
};

/// @brief Values of a method's parameters by key, one float per component.
using ParameterValues = std::map<std::string, std::vector<float>>;

/// @brief The line search of a method's parameter ascent.
struct LineSearch {
    bool unitDirection = false;  ///< search along the unit gradient instead of the gradient
    double maxStep = 0.25;       ///< interval [0, maxStep] of the step
    double tolerance = 0.01;     ///< final bracket length
};

/// @brief Makes a per-vertex array a method derives from its scene alone (the wrap's local
///        radii), one value per vertex of the scene's mesh: the viewer uploads it once per scene
///        and the method's shader reads it as a storage buffer (kMethodBuffer0, 1, ... in the order
///        of MethodInfo::vertexArrays: app/viewer/shaders.h).
using VertexArrayMaker = std::function<std::vector<float>(const RenderScene&)>;

/// @brief Everything the command line, the JSON writer, the optimiser and the viewer know of a method.
struct MethodInfo {
    std::string name;                     ///< command-line name, e.g. "inversevis"
    std::string help;                     ///< one line for --help
    std::vector<ParameterSpec> parameters;  ///< every parameter, in the order --help and JSON list them
    /// The scalar energy's gradient is analytic (tangent-linear curved rays); otherwise, and for
    /// the visibility energy always, the ascent uses forward differences.
    bool tangentLinearGradient = false;
    /// The method's own line search; none: the ascent's default (the paper's [0, 0.25], 0.01).
    std::optional<LineSearch> lineSearch;
    /// A one-component optimised parameter whose range the ascent may scan before it starts
    /// (AscentOptions::scanSamples); empty: none.
    std::string scannedParameter;
    /// A one-component parameter that trades completeness for coherence, larger values drawing
    /// more rays (the wrap's stable_shift): the optimisation's readable rule sets it to the
    /// loosest value whose picture stays coherent (optimize/readable_rule.h); empty: none.
    std::string readableRuleParameter;
    /// The keys of what Method::viewValues() derives from each view (the viewer's programs read
    /// each as a uniform, as the parameters); empty: none.
    std::vector<std::string> viewValueKeys;
    /// The per-vertex arrays its viewer shader reads; empty: none.
    std::vector<VertexArrayMaker> vertexArrays;
    /// Creates the method from complete, validated values.
    std::function<std::shared_ptr<const Method>(const ParameterValues&)> create;

    /// @brief The parameter named @a key, or null.
    const ParameterSpec* parameter(const std::string& key) const;
};

/// @brief The per-view part of a method: where the indirect ray of a pixel lands.
/// @warning It refers to the scene and to the method that made it: both must outlive it (ScreenMap
///          keeps the method alive). map() is const and thread-safe given one
///          DistanceField::Sampler per thread.
class IndirectMap {
public:
    virtual ~IndirectMap() = default;
    /// @brief What the indirect ray of continuous pixel position (x, y) shows (its view ray missed).
    virtual PixelMapping map(double x, double y, DistanceField::Sampler& sampler) const = 0;
    /// @brief map() of each of @a count pixel positions into @a mappings; a method may trace them
    ///        together (the curved rays do, for speed), with the same results.
    virtual void mapMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                         PixelMapping* mappings) const;
};

/// @brief A visualisation method with its parameter values.
class Method {
public:
    virtual ~Method() = default;
    /// @brief The method's description (shared by all its instances).
    virtual const MethodInfo& info() const = 0;
    /// @brief Every parameter's value, keyed as info().parameters.
    virtual ParameterValues values() const = 0;
    /// @brief What this method derives from the view @a frame of @a mesh (the ring map's layout),
    ///        keyed as info().viewValueKeys; empty by default.
    virtual ParameterValues viewValues(const core::CameraFrame& /*frame*/, const core::TriangleMesh& /*mesh*/) const
    {
        return {};
    }
    /// @brief Which faces the straight view rays see.
    virtual core::FaceFilter directFaces() const { return core::FaceFilter::Any; }
    /// @brief The map of the pixels that miss the surface for one view; null when they stay background.
    virtual std::unique_ptr<IndirectMap> indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const;
    /// @brief Whether indirectMap() maps the pixels that miss the surface (false: they stay background).
    virtual bool drawsIndirect() const { return false; }
    /// @brief How far this method's picture seen from @a camera reaches: the object and the region
    ///        where its indirect pixels can lie (render/framing.h fits the field of view to it).
    ///        By default the object's own extent.
    virtual PictureExtent pictureExtent(const RenderScene& scene, const core::Camera& camera) const;
    /// @brief Whether its indirect rays reach the surface from outside the object, so that the
    ///        points they show can be shadowed (the ring map's rays start inside it).
    virtual bool indirectRaysArriveFromOutside() const { return true; }
    /// @brief This method as a curved-ray method, or null when its indirect rays are not curved.
    virtual const CurvedRayMethod* curved() const { return nullptr; }
    /// @brief How far from the surface (normalised) the distance field must reach for this method's
    ///        rays; 0 when they need no exterior distance.
    virtual float reachNeeded() const { return 0.0f; }

    /// @brief The command-line name.
    const std::string& name() const { return info().name; }
    /// @brief True for the methods that trace curved rays from the hull.
    bool curvedRays() const { return curved() != nullptr; }
};

/// @brief Shared, immutable method.
using MethodPtr = std::shared_ptr<const Method>;

}  // namespace ivis::render
