#include <ivis/core/colormap.h>

#include "embedded_colormaps.h"

#include <ivis/core/errors.h>
#include <ivis/core/image.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace ivis::core {
namespace {

/// matplotlib's viridis (van der Walt and Smith, CC0), sRGB, resampled from its 256-entry table
/// at 65 even steps; linear interpolation stays within 0.5/255 of the original.
constexpr float kViridisSrgb[][3] = {
    {0.2670f, 0.0049f, 0.3294f}, {0.2726f, 0.0255f, 0.3530f}, {0.2770f, 0.0502f, 0.3755f},
    {0.2802f, 0.0732f, 0.3969f}, {0.2823f, 0.0946f, 0.4170f}, {0.2832f, 0.1153f, 0.4358f},
    {0.2829f, 0.1354f, 0.4530f}, {0.2815f, 0.1553f, 0.4688f}, {0.2789f, 0.1749f, 0.4830f},
    {0.2753f, 0.1942f, 0.4956f}, {0.2708f, 0.2133f, 0.5066f}, {0.2654f, 0.2321f, 0.5162f},
    {0.2593f, 0.2507f, 0.5244f}, {0.2525f, 0.2689f, 0.5313f}, {0.2454f, 0.2867f, 0.5370f},
    {0.2379f, 0.3042f, 0.5417f}, {0.2302f, 0.3213f, 0.5455f}, {0.2225f, 0.3381f, 0.5486f},
    {0.2148f, 0.3545f, 0.5510f}, {0.2073f, 0.3706f, 0.5530f}, {0.2000f, 0.3864f, 0.5545f},
    {0.1929f, 0.4019f, 0.5557f}, {0.1861f, 0.4173f, 0.5567f}, {0.1796f, 0.4324f, 0.5574f},
    {0.1733f, 0.4474f, 0.5579f}, {0.1672f, 0.4623f, 0.5581f}, {0.1613f, 0.4770f, 0.5581f},
    {0.1554f, 0.4918f, 0.5579f}, {0.1497f, 0.5064f, 0.5573f}, {0.1440f, 0.5211f, 0.5564f},
    {0.1384f, 0.5358f, 0.5551f}, {0.1331f, 0.5504f, 0.5533f}, {0.1281f, 0.5651f, 0.5509f},
    {0.1239f, 0.5798f, 0.5479f}, {0.1209f, 0.5945f, 0.5442f}, {0.1195f, 0.6091f, 0.5397f},
    {0.1203f, 0.6238f, 0.5343f}, {0.1240f, 0.6383f, 0.5280f}, {0.1310f, 0.6529f, 0.5208f},
    {0.1414f, 0.6673f, 0.5126f}, {0.1554f, 0.6815f, 0.5032f}, {0.1727f, 0.6956f, 0.4928f},
    {0.1930f, 0.7096f, 0.4812f}, {0.2160f, 0.7232f, 0.4685f}, {0.2415f, 0.7366f, 0.4545f},
    {0.2691f, 0.7497f, 0.4394f}, {0.2986f, 0.7624f, 0.4230f}, {0.3299f, 0.7748f, 0.4054f},
    {0.3629f, 0.7867f, 0.3866f}, {0.3972f, 0.7981f, 0.3665f}, {0.4330f, 0.8091f, 0.3453f},
    {0.4700f, 0.8194f, 0.3228f}, {0.5081f, 0.8292f, 0.2992f}, {0.5472f, 0.8384f, 0.2745f},
    {0.5873f, 0.8470f, 0.2489f}, {0.6280f, 0.8549f, 0.2224f}, {0.6694f, 0.8622f, 0.1954f},
    {0.7110f, 0.8689f, 0.1685f}, {0.7529f, 0.8751f, 0.1427f}, {0.7946f, 0.8808f, 0.1196f},
    {0.8359f, 0.8861f, 0.1025f}, {0.8766f, 0.8912f, 0.0953f}, {0.9166f, 0.8961f, 0.1008f},
    {0.9554f, 0.9011f, 0.1182f}, {0.9932f, 0.9062f, 0.1439f},
};

// Moreland, "Diverging Color Maps for Scientific Visualization" (2009): CIELAB with the D65
// white, its polar form Msh, and the cool-warm endpoints in sRGB.
constexpr double kPi = 3.14159265358979323846;
constexpr double kWhiteX = 0.95047, kWhiteZ = 1.08883;
const glm::vec3 kCoolSrgb(0.230f, 0.299f, 0.754f);
const glm::vec3 kWarmSrgb(0.706f, 0.016f, 0.150f);

double labF(double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; }
double labFInverse(double f) { return f * f * f > 0.008856 ? f * f * f : (f - 16.0 / 116.0) / 7.787; }

glm::dvec3 mshFromSrgb(const glm::vec3& srgb)
{
    const glm::dvec3 c(linearFromSrgb(srgb));
    const double x = glm::dot(c, glm::dvec3(0.4124564, 0.3575761, 0.1804375)) / kWhiteX;
    const double y = glm::dot(c, glm::dvec3(0.2126729, 0.7151522, 0.0721750));
    const double z = glm::dot(c, glm::dvec3(0.0193339, 0.1191920, 0.9503041)) / kWhiteZ;
    const glm::dvec3 lab(116.0 * labF(y) - 16.0, 500.0 * (labF(x) - labF(y)), 200.0 * (labF(y) - labF(z)));
    const double m = glm::length(lab);
    return {m, std::acos(lab.x / m), std::atan2(lab.z, lab.y)};
}

glm::vec3 srgbFromMsh(const glm::dvec3& msh)
{
    const double l = msh.x * std::cos(msh.y);
    const double fy = (l + 16.0) / 116.0;
    const double fx = fy + msh.x * std::sin(msh.y) * std::cos(msh.z) / 500.0;
    const double fz = fy - msh.x * std::sin(msh.y) * std::sin(msh.z) / 200.0;
    const glm::dvec3 xyz(kWhiteX * labFInverse(fx), labFInverse(fy), kWhiteZ * labFInverse(fz));
    const glm::dvec3 c(glm::dot(xyz, glm::dvec3(3.2404542, -1.5371385, -0.4985314)),
                       glm::dot(xyz, glm::dvec3(-0.9692660, 1.8760108, 0.0415560)),
                       glm::dot(xyz, glm::dvec3(0.0556434, -0.2040259, 1.0572252)));
    const glm::vec3 linear(glm::clamp(c, 0.0, 1.0));
    return {srgbFromLinear(linear.r), srgbFromLinear(linear.g), srgbFromLinear(linear.b)};
}

// Hue given to the white end when interpolating from the saturated colour @a saturated to an
// unsaturated one of magnitude @a whiteM, so the hue does not swing through unrelated colours.
double hueTowardWhite(const glm::dvec3& saturated, double whiteM)
{
    const double spin = saturated.y * std::sqrt(whiteM * whiteM - saturated.x * saturated.x) /
                        (saturated.x * std::sin(saturated.y));
    return saturated.z > -kPi / 3.0 ? saturated.z + spin : saturated.z - spin;
}

// Moreland's map at t in [0,1]: cool -> white (M = max(M_cool, M_warm, 88)) -> warm.
glm::vec3 coolWarmSrgb(double t)
{
    const glm::dvec3 cool = mshFromSrgb(kCoolSrgb), warm = mshFromSrgb(kWarmSrgb);
    const double whiteM = std::max({cool.x, warm.x, 88.0});
    if (t < 0.5) {
        const glm::dvec3 white(whiteM, 0.0, hueTowardWhite(cool, whiteM));
        return srgbFromMsh(glm::mix(cool, white, 2.0 * t));
    }
    const glm::dvec3 white(whiteM, 0.0, hueTowardWhite(warm, whiteM));
    return srgbFromMsh(glm::mix(white, warm, 2.0 * t - 1.0));
}

/// The colour map of an embedded table "<name>.txt": one sRGB "r g b" line per knot, "#" lines skipped.
Colormap tableColormap(const detail::EmbeddedFile& file)
{
    std::string name = file.name;
    name = name.substr(0, name.rfind('.'));
    std::vector<glm::vec3> knots;
    std::istringstream lines(file.text);
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream values(line);
        glm::vec3 c;
        if (!(values >> c.r >> c.g >> c.b)) throw ValueError("colour map table " + std::string(file.name) + ": bad line '" + line + "'");
        knots.push_back(c);
    }
    return Colormap(name, std::move(knots));
}

std::vector<Colormap> makeBuiltins()
{
    std::vector<glm::vec3> viridis;
    for (const auto& c : kViridisSrgb) viridis.emplace_back(c[0], c[1], c[2]);
    constexpr int kCoolWarmSteps = 256;
    std::vector<glm::vec3> coolWarm;
    for (int i = 0; i <= kCoolWarmSteps; ++i) coolWarm.push_back(coolWarmSrgb(double(i) / kCoolWarmSteps));
    std::vector<Colormap> maps = {Colormap("viridis", std::move(viridis)), Colormap("coolwarm", std::move(coolWarm)),
                                  Colormap("grey", {glm::vec3(0.0f), glm::vec3(1.0f)})};
    for (const detail::EmbeddedFile& file : detail::embeddedFiles()) maps.push_back(tableColormap(file));
    return maps;
}

const std::vector<Colormap>& builtins()
{
    static const std::vector<Colormap> maps = makeBuiltins();
    return maps;
}

}  // namespace

Colormap::Colormap(std::string name, std::vector<glm::vec3> srgbKnots)
    : mName(std::move(name)), mSrgbKnots(std::move(srgbKnots))
{
    if (mSrgbKnots.size() < 2) throw ValueError("colour map '" + mName + "' needs at least two knots");
}

glm::vec3 Colormap::at(float t) const
{
    const float x = (t > 0.0f ? std::min(t, 1.0f) : 0.0f) * float(mSrgbKnots.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), mSrgbKnots.size() - 2);
    return linearFromSrgb(glm::mix(mSrgbKnots[i], mSrgbKnots[i + 1], x - float(i)));
}

std::vector<std::string> colormapNames()
{
    std::vector<std::string> names;
    for (const Colormap& map : builtins()) names.push_back(map.name());
    return names;
}

const Colormap& colormap(const std::string& name)
{
    for (const Colormap& map : builtins())
        if (map.name() == name) return map;
    std::ostringstream known;
    for (const std::string& n : colormapNames()) known << (known.tellp() > 0 ? ", " : "") << n;
    throw InputError("unknown colour map '" + name + "' (known: " + known.str() + ")");
}

float ScalarRange::normalized(float value) const
{
    if (std::isnan(value)) return value;
    if (lo == hi) return 0.5f;
    const double t = (double(value) - lo) / (double(hi) - lo);
    return float(std::clamp(t, 0.0, 1.0));
}

ScalarRange scalarRangeFromData(const std::vector<float>& values)
{
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float v : values) {
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (lo > hi) return {0.0f, 0.0f};
    return {lo, hi};
}

ScalarRange scalarRangeFromUser(double lo, double hi)
{
    const double biggest = std::numeric_limits<float>::max();
    auto valid = [&](double v) { return std::isfinite(v) && std::abs(v) <= biggest; };
    std::ostringstream text;
    text << std::setprecision(15) << "invalid range [" << lo << ", " << hi << "]: ";
    if (!valid(lo) || !valid(hi))
        throw ValueError(text.str() + "both ends must be finite numbers of magnitude at most 3.4e38 (single precision)");
    if (!(lo < hi)) throw ValueError(text.str() + "lo must be less than hi");
    if (!(float(lo) < float(hi)))
        throw ValueError(text.str() + "lo and hi are one number in single precision, which the colours are mapped in");
    return {float(lo), float(hi)};
}

}  // namespace ivis::core
