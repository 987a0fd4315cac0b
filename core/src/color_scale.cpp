#include <ivis/core/color_scale.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace ivis::core {
namespace {

std::vector<float> finiteValues(const std::vector<float>& values, bool positiveOnly)
{
    std::vector<float> kept;
    kept.reserve(values.size());
    for (const float v : values)
        if (std::isfinite(v) && (!positiveOnly || v > 0.0f)) kept.push_back(v);
    return kept;
}

std::string rangeText(double lo, double hi)
{
    std::ostringstream text;
    text << "[" << lo << ", " << hi << "]";
    return text.str();
}

}  // namespace

float ColorScale::position(float value) const
{
    if (std::isnan(value)) return value;
    float t = 0.5f;
    if (range.lo != range.hi) {
        if (log) {
            const double lo = std::log10(double(range.lo)), hi = std::log10(double(range.hi));
            t = value > 0.0f ? float(std::clamp((std::log10(double(value)) - lo) / (hi - lo), 0.0, 1.0)) : 0.0f;
        } else {
            t = range.normalized(value);
        }
    }
    return invert ? 1.0f - t : t;
}

double ColorScale::valueAt(double t) const
{
    if (invert) t = 1.0 - t;
    if (!log) return double(range.lo) + t * (double(range.hi) - double(range.lo));
    return std::pow(10.0, std::log10(double(range.lo)) + t * (std::log10(double(range.hi)) - std::log10(double(range.lo))));
}

void ColorScaleRequest::validate() const
{
    if (range && percentiles) throw ValueError("--range and --range-percentile exclude each other");
    if (log && symmetric) throw ValueError("--log and --symmetric exclude each other (a log scale has no 0)");
    if (percentiles) {
        const auto [lo, hi] = *percentiles;
        if (!(lo >= 0.0 && hi <= 100.0 && lo < hi))
            throw ValueError("--range-percentile " + rangeText(lo, hi) + ": expected 0 <= LO < HI <= 100");
    }
    if (log && range && !(range->lo > 0.0f))
        throw ValueError("--log needs a positive range; --range " + rangeText(range->lo, range->hi) + " is not");
}

ColorScale ColorScaleRequest::resolve(const std::vector<float>& values, const std::string& source) const
{
    validate();
    ColorScale scale;
    scale.log = log;
    scale.invert = invert;
    if (range) {
        scale.range = *range;
    } else {
        const std::vector<float> kept = finiteValues(values, log);
        if (log && kept.empty() && !values.empty())
            throw ValueError((source.empty() ? "" : source + ": ") +
                             "--log: the scalar has no positive value to put on a logarithmic scale");
        if (percentiles) {
            scale.range = {float(percentile(kept, percentiles->first)), float(percentile(kept, percentiles->second))};
            if (kept.empty()) scale.range = {0.0f, 0.0f};
        } else {
            scale.range = scalarRangeFromData(kept);
        }
    }
    if (symmetric) {
        const float m = std::max(std::abs(scale.range.lo), std::abs(scale.range.hi));
        scale.range = {-m, m};
    }
    if (log && scale.range.lo <= 0.0f) scale.range = {1.0f, 1.0f};  // no data: an empty positive range
    return scale;
}

double percentile(std::vector<float> values, double percent)
{
    values.erase(std::remove_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }), values.end());
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double rank = std::clamp(percent, 0.0, 100.0) / 100.0 * double(values.size() - 1);
    const std::size_t below = std::size_t(std::floor(rank));
    std::nth_element(values.begin(), values.begin() + below, values.end());
    const double lo = values[below];
    if (below + 1 >= values.size()) return lo;
    const double hi = *std::min_element(values.begin() + below + 1, values.end());
    return lo + (rank - double(below)) * (hi - lo);
}

}  // namespace ivis::core
