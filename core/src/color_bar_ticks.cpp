#include <ivis/core/color_bar.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ivis::core {
namespace {

// Magnitudes written plainly; outside, labels use a power of ten.
constexpr double kPlainBelow = 1e5;
constexpr double kPlainFrom = 1e-3;

std::string superscript(int exponent)
{
    static const char* const kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string text = exponent < 0 ? "⁻" : "";
    const std::string digits = std::to_string(std::abs(exponent));
    for (const char d : digits) text += kDigits[d - '0'];
    return text;
}

std::string printed(const char* format, double value, int precision)
{
    char text[48];
    std::snprintf(text, sizeof text, format, precision, value == 0.0 ? 0.0 : value);  // no "-0"
    return text[0] == '-' ? "−" + std::string(text + 1) : std::string(text);  // a real minus sign
}

// "1.5×10⁴" (its own power of ten, at most @a decimals in the mantissa, trailing zeros dropped),
// "10⁴" for an exact power of ten, "0" for zero.
std::string powerOfTen(double value, int decimals)
{
    if (value == 0.0) return "0";
    int exponent = int(std::floor(std::log10(std::abs(value)) + 1e-9));
    std::string m = printed("%.*f", value / std::pow(10.0, exponent), std::max(0, decimals));
    if (m == "10" || m == "−10") {  // rounded up to the next power
        ++exponent;
        m = printed("%.*f", value / std::pow(10.0, exponent), std::max(0, decimals));
    }
    if (m.find('.') != std::string::npos) {
        while (m.back() == '0') m.pop_back();
        if (m.back() == '.') m.pop_back();
    }
    if (m == "1") return "10" + superscript(exponent);
    if (m == "−1") return "−10" + superscript(exponent);
    return m + "×" + "10" + superscript(exponent);
}

bool plain(double magnitude) { return magnitude == 0.0 || (magnitude >= kPlainFrom && magnitude < kPlainBelow); }

// A range end with up to four significant digits (trailing zeros dropped).
std::string endLabel(double value)
{
    return plain(std::abs(value)) ? printed("%.*g", value, 4) : powerOfTen(value, 3);
}

// Values closer than this are the same tick (the scale's ends are floats).
double sameTickTolerance(double lo, double hi) { return 1e-6 * std::max({std::abs(lo), std::abs(hi), hi - lo}); }

std::vector<ColorBarTick> linearTicks(const ColorScale& scale)
{
    const double lo = scale.range.lo, hi = scale.range.hi, span = hi - lo;
    double step = std::pow(10.0, std::floor(std::log10(span / 4.0)) + 1.0);
    // Multiples k of a step s in [lo, hi] (the float ends may sit a rounding error off a multiple).
    auto first = [&](double s) { return std::ceil(lo / s - 1e-6); };
    auto last = [&](double s) { return std::floor(hi / s + 1e-6); };
    auto count = [&](double s) { return last(s) - first(s) + 1.0; };
    for (int i = 0; count(step) < 5.0; ++i) step *= (i % 3 == 1) ? 0.4 : 0.5;  // 10 -> 5 -> 2 -> 1 -> 0.5 ...
    const int stepExponent = int(std::floor(std::log10(step) + 1e-9));
    const bool usePlain = plain(std::max(std::abs(lo), std::abs(hi)));

    std::vector<ColorBarTick> ticks;
    const double tolerance = sameTickTolerance(lo, hi);
    for (double k = first(step); k <= last(step); ++k) {
        const double value = k * step;
        ColorBarTick tick{value, scale.position(float(value)), "", false};
        const int valueExponent = value == 0.0 ? 0 : int(std::floor(std::log10(std::abs(value)) + 1e-9));
        tick.label = usePlain ? printed("%.*f", value, std::max(0, -stepExponent))
                              : powerOfTen(value, valueExponent - stepExponent);
        tick.rangeEnd = std::abs(value - lo) <= tolerance || std::abs(value - hi) <= tolerance;
        ticks.push_back(tick);
    }
    for (const double end : {lo, hi}) {
        const bool present = std::any_of(ticks.begin(), ticks.end(), [&](const ColorBarTick& t) {
            return std::abs(t.value - end) <= tolerance;
        });
        if (!present) ticks.push_back({end, scale.position(float(end)), endLabel(end), true});
    }
    return ticks;
}

std::vector<ColorBarTick> logTicks(const ColorScale& scale)
{
    const double lo = scale.range.lo, hi = scale.range.hi;
    IVIS_CHECK(lo > 0.0 && lo <= hi && std::isfinite(hi));  // a log scale resolved (a negative end made 2^31 decades)
    std::vector<ColorBarTick> ticks;
    for (const std::vector<int>& multiples : {std::vector<int>{1}, {1, 2, 5}, {1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
        ticks.clear();
        for (int e = int(std::floor(std::log10(lo))); e <= int(std::ceil(std::log10(hi))); ++e)
            for (const int m : multiples) {
                const double value = m * std::pow(10.0, e);
                if (value < lo - sameTickTolerance(lo, lo) || value > hi + sameTickTolerance(hi, hi)) continue;
                const std::string label = plain(value) ? printed("%.*g", value, 6) : powerOfTen(value, 0);
                ticks.push_back({value, scale.position(float(value)), label, false});
            }
        if (ticks.size() >= 5) break;
    }
    for (const double end : {lo, hi}) {
        auto same = std::find_if(ticks.begin(), ticks.end(), [&](const ColorBarTick& t) {
            return std::abs(t.value - end) <= sameTickTolerance(end, end);
        });
        if (same != ticks.end()) same->rangeEnd = true;
        else ticks.push_back({end, scale.position(float(end)), endLabel(end), true});
    }
    return ticks;
}

}  // namespace

std::vector<ColorBarTick> colorBarTicks(const ColorScale& scale)
{
    if (!(scale.range.lo < scale.range.hi))
        return {{scale.range.lo, scale.position(scale.range.lo), endLabel(scale.range.lo), true}};
    std::vector<ColorBarTick> ticks = scale.log ? logTicks(scale) : linearTicks(scale);
    std::sort(ticks.begin(), ticks.end(), [](const ColorBarTick& a, const ColorBarTick& b) { return a.value < b.value; });
    return ticks;
}

}  // namespace ivis::core
