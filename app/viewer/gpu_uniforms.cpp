#include "gpu_uniforms.h"

#include <ivis/render/curved_ray.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/shading.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

namespace ivis::app {
namespace {

constexpr int kMaxHullSteps = 4096;  // the CPU's backward hull search is unbounded; 4096 is never reached in practice

glm::vec3 toFloat(const glm::dvec3& v) { return glm::vec3(v); }

/// World -> clip for a camera, built from CameraFrame's own basis so rasterised and traced pixels agree.
glm::mat4 clipFromWorld(const core::CameraFrame& frame)
{
    const core::Camera& camera = frame.camera();
    const glm::dvec3 r = frame.right(), u = frame.upVector(), f = frame.forward(), eye = camera.eye;
    glm::dmat4 view(1.0);
    for (int i = 0; i < 3; ++i) {
        view[i][0] = r[i];
        view[i][1] = u[i];
        view[i][2] = -f[i];
    }
    view[3][0] = -glm::dot(r, eye);
    view[3][1] = -glm::dot(u, eye);
    view[3][2] = glm::dot(f, eye);
    // The mesh lies in [-1,1]^3: within sqrt(3) of the origin.
    const double centre = glm::dot(glm::dvec3(0.0) - eye, f), margin = 2.0;
    const double aspect = double(frame.width()) / double(frame.height());
    glm::dmat4 projection(0.0);
    // The image window is centred at windowCentre on the image plane (core::CameraFrame::ray).
    const glm::dvec2 shift = camera.windowCentre;
    if (camera.orthographic) {
        const double hh = camera.orthoHalfHeight, n = centre - margin, fa = centre + margin;
        projection[0][0] = 1.0 / (hh * aspect);
        projection[1][1] = 1.0 / hh;
        projection[3][0] = -shift.x / (hh * aspect);
        projection[3][1] = -shift.y / hh;
        projection[2][2] = -2.0 / (fa - n);
        projection[3][2] = -(fa + n) / (fa - n);
        projection[3][3] = 1.0;
    } else {
        const double hh = std::tan(0.5 * camera.fovYDeg * M_PI / 180.0);
        const double n = std::max(1e-3, centre - margin), fa = std::max(n + 1e-3, centre + margin);
        projection[0][0] = 1.0 / (hh * aspect);
        projection[1][1] = 1.0 / hh;
        projection[2][0] = shift.x / (hh * aspect);  // x_ndc = (x / -z - shift.x) / (hh aspect)
        projection[2][1] = shift.y / hh;
        projection[2][2] = -(fa + n) / (fa - n);
        projection[2][3] = -1.0;
        projection[3][2] = -2.0 * fa * n / (fa - n);
    }
    return glm::mat4(projection * view);
}

/// Sets @a v as the uniform of @a key: an int when @a integer, a vec2 or vec3 for two or three
/// components, else a float or a float array.
void setValueUniform(GlProgram& p, const std::string& key, const std::vector<float>& v, bool integer)
{
    const std::string name = parameterUniform(key);
    if (integer)
        p.set(name.c_str(), int(v[0]));
    else if (v.size() == 2)
        p.set(name.c_str(), glm::vec2(v[0], v[1]));
    else if (v.size() == 3)
        p.set(name.c_str(), glm::vec3(v[0], v[1], v[2]));
    else if (v.size() == 1)
        p.set(name.c_str(), v[0]);
    else
        p.setArray(name.c_str(), v.data(), int(v.size()));
}

/// Sets every parameter of @a method and every value it derives from the view as its uniform.
void setMethodUniforms(GlProgram& p, const render::Method& method, const core::CameraFrame& camera,
                       const core::TriangleMesh& mesh)
{
    const render::ParameterValues values = method.values();
    for (const render::ParameterSpec& spec : method.info().parameters)
        setValueUniform(p, spec.key, values.at(spec.key), spec.integer);
    const render::ParameterValues viewValues = method.viewValues(camera, mesh);
    for (const std::string& key : method.info().viewValueKeys) setValueUniform(p, key, viewValues.at(key), false);
}

/// The uniforms both passes read every frame: the look and the camera's position and heading.
void setSharedUniforms(GlProgram& program, const GpuFrame& frame, const core::CameraFrame& camera)
{
    const render::ShadingOptions& shading = frame.shading;
    program.set("uRange", glm::vec2(shading.scale.range.lo, shading.scale.range.hi));
    program.set("uLogScale", shading.scale.log);
    program.set("uInvertScale", shading.scale.invert);
    program.set("uNanColour", shading.nanColour);
    program.set("uNoDataColour", shading.noDataColour);
    program.set("uEye", toFloat(frame.camera.eye));
    program.set("uForward", toFloat(camera.forward()));
    program.set("uOrtho", frame.camera.orthographic);
    program.set("uToLight", toFloat(glm::normalize(render::kKeyLightRight * camera.right() +
                                                   render::kKeyLightUp * camera.upVector() +
                                                   render::kKeyLightForward * camera.forward())));
    program.set("uAmbient", shading.ambient);
    program.set("uShadows", shading.shadows);
}

}  // namespace

std::string parameterUniform(const std::string& key)
{
    std::string name = "u";
    bool upper = true;
    for (char c : key) {
        if (c == '_') {
            upper = true;
            continue;
        }
        name += upper ? char(std::toupper(static_cast<unsigned char>(c))) : c;
        upper = false;
    }
    return name;
}

void keepMeshUniforms(UniformSet& scene, const core::SurfaceField& field)
{
    scene.set("uHasScalar", field.hasScalar());
    scene.set("uCellScalar", field.valuesOn == core::Association::Cell);
    scene.set("uDataTriangles", int(std::min<std::size_t>(field.mesh.dataTriangleCount, 0x7fffffff)));
}

void keepVolumeUniforms(UniformSet& scene, const DenseSlices& slices, float interiorStep,
                        const core::Bounds3& surfaceBox)
{
    auto dims = [](const std::array<int, 3>& d) { return glm::ivec3(d[0], d[1], d[2]); };
    scene.set("uFarDims", dims(slices.far.dims));
    scene.set("uFarOrigin", slices.far.origin);
    scene.set("uFarInvVoxel", 1.0f / slices.farVoxelSize);
    scene.set("uOutside", slices.outside);
    scene.set("uHasFineBand", slices.hasFineBand);
    scene.set("uFineFrom", slices.fineFrom);
    scene.set("uFineUntil", slices.fineUntil);
    scene.set("uBandDims", dims(slices.band.dims));
    scene.set("uBandOrigin", slices.band.origin);
    scene.set("uTriangleDims", dims(slices.triangles.dims));
    scene.set("uTriangleOrigin", slices.triangles.origin);
    scene.set("uVoxel", slices.voxelSize);
    scene.set("uInvVoxel", 1.0f / slices.voxelSize);
    scene.set("uUnsigned", slices.unsignedDistance);
    scene.set("uInteriorStep", interiorStep);
    scene.set("uBoxHalf", float(vdb::kBoxHalfExtent));
    scene.set("uSurfaceLo", glm::vec3(surfaceBox.lo));
    scene.set("uSurfaceHi", glm::vec3(surfaceBox.hi));
    scene.set("uVolumeReady", true);
}

void setMeshPassUniforms(GlProgram& program, const GpuFrame& frame, const core::CameraFrame& camera)
{
    setSharedUniforms(program, frame, camera);
    program.set("uClipFromWorld", clipFromWorld(camera));
}

void setIndirectUniforms(GlProgram& p, const GpuFrame& frame, const core::CameraFrame& camera,
                         const core::SurfaceField& field, const core::Bounds3& meshBounds, const VolumeScale& volume)
{
    setSharedUniforms(p, frame, camera);
    p.set("uViewport", glm::vec2(float(frame.width), float(frame.height)));
    p.set("uHalfHeight", float(frame.camera.orthographic ? frame.camera.orthoHalfHeight
                                                         : std::tan(0.5 * frame.camera.fovYDeg * M_PI / 180.0)));
    p.set("uAspect", float(double(frame.width) / double(frame.height)));
    p.set("uWindowCentre", glm::vec2(frame.camera.windowCentre));
    p.set("uTargetDistance", float(glm::length(frame.camera.target - frame.camera.eye)));
    p.set("uRight", toFloat(camera.right()));
    p.set("uUp", toFloat(camera.upVector()));
    p.set("uIndirectBrightness", frame.shading.indirectBrightness);
    p.set("uShadeIndirect", frame.shading.shadeIndirect);
    p.set("uIndirectShadows", frame.method->indirectRaysArriveFromOutside());
    const render::Method& method = *frame.method;
    setMethodUniforms(p, method, camera, field.mesh);
    const render::CurvedRayMethod* curved = method.curved();
    // rays land within the method's landing threshold in voxels (render::landingEpsilon), the
    // wrap's own parameter `landing`
    p.set("uLanding", (curved ? curved->rayParams() : render::CurvedRayParams{}).landingVoxels);
    if (curved) {
        const float hullOffset = curved->rayParams().hullOffset;
        p.set("uMaxAlpha", render::kMaxAlpha);
        p.set("uRetries", curved->relaunches());
        p.set("uEscape", render::escapeDistance(volume.reach));
        p.set("uMaxHullSteps", kMaxHullSteps);
        const core::Bounds3 hull = render::hullBounds(meshBounds, hullOffset, volume.fineVoxelSize);
        p.set("uHullLo", glm::vec3(hull.lo));
        p.set("uHullHi", glm::vec3(hull.hi));
    }
}

}  // namespace ivis::app
