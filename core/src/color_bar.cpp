#include <ivis/core/color_bar.h>

#include <ivis/core/errors.h>
#include <ivis/core/text_raster.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace ivis::core {
namespace {

const glm::vec3 kInk = linearFromSrgb(glm::vec3(0.17f));       // text, frame and ticks
const glm::vec3 kBacking = linearFromSrgb(glm::vec3(0.97f));   // the legend's background
const glm::vec3 kEdge = linearFromSrgb(glm::vec3(0.72f));      // the backing's outline

std::string formatValue(double value, int digits)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, value == 0.0 ? 0.0 : value);  // no "-0"
    return text;
}

PixelRect clipped(const PixelRect& r, const Image& image)
{
    return {std::max(r.x0, 0), std::max(r.y0, 0), std::min(r.x1, image.width()), std::min(r.y1, image.height())};
}

void fill(Image& image, const PixelRect& rect, const glm::vec3& color)
{
    const PixelRect r = clipped(rect, image);
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) image.at(x, y) = glm::vec4(color, 1.0f);
}

// Puts the image over an opaque backing colour, then veils it with that colour at @a opacity.
void drawBacking(Image& image, const PixelRect& rect, float opacity)
{
    const PixelRect r = clipped(rect, image);
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            glm::vec4& pixel = image.at(x, y);
            const glm::vec3 over = glm::vec3(pixel) + kBacking * (1.0f - glm::clamp(pixel.a, 0.0f, 1.0f));
            pixel = glm::vec4(glm::mix(over, kBacking, opacity), 1.0f);
        }
}

void validate(const ColorBarOptions& options)
{
    if (!(options.heightFraction >= 0.05f && options.heightFraction <= 0.8f))
        throw ValueError("colour bar height fraction " + std::to_string(options.heightFraction) +
                         " is outside [0.05, 0.8]");
    if (options.textScale < 0) throw ValueError("colour bar text scale must be >= 0 (0 = automatic)");
    if (!(options.backingOpacity >= 0.0f && options.backingOpacity <= 1.0f))
        throw ValueError("colour bar backing opacity " + std::to_string(options.backingOpacity) +
                         " is outside [0, 1]");
}

// Title lines: "title [units]", split in two when both parts exist and together they are more
// than 1.5 times @a width (the width of the bar and its labels).
std::vector<std::string> titleLines(const std::string& title, const std::string& units, int width, int scale)
{
    const std::string bracketed = units.empty() ? "" : "[" + units + "]";
    if (!title.empty() && !bracketed.empty()) {
        const std::string joined = title + " " + bracketed;
        if (2 * textWidth(joined, scale) <= 3 * width) return {joined};
        return {title, bracketed};
    }
    if (title.empty() && bracketed.empty()) return {};
    return {title + bracketed};
}

}  // namespace

std::vector<std::string> colorBarLabels(const ScalarRange& range)
{
    if (range.lo == range.hi) return {formatValue(range.lo, 6)};
    const double span = double(range.hi) - double(range.lo);
    double middle = 0.5 * (double(range.lo) + double(range.hi));
    if (std::abs(middle) < 1e-6 * std::abs(span)) middle = 0.0;
    std::vector<std::string> labels;
    for (int digits = 3; digits <= 9; ++digits) {
        labels = {formatValue(range.lo, digits), formatValue(middle, digits), formatValue(range.hi, digits)};
        if (labels[0] != labels[1] && labels[1] != labels[2]) break;
    }
    return labels;
}

ColorBarLayout drawColorBar(Image& image, const Colormap& map, const ScalarRange& range, const std::string& title,
                            const std::string& units, const ColorBarOptions& options)
{
    validate(options);
    const int side = std::min(image.width(), image.height());
    const int scale = options.textScale > 0 ? options.textScale : std::max(1, side / 500);
    const int pad = 4 * scale + 2;
    const int margin = std::max(2, side / 40);
    const int stroke = std::max(1, scale / 2);
    const int capHalf = (kCapHeight * scale + 1) / 2;
    const int tickLength = 2 * scale + 1;
    const int labelGap = 2 * scale;

    // Horizontal: [frame + gradient][tick][gap][labels]; the title lines above, left-aligned.
    const int frameHeight = std::max(8, static_cast<int>(std::lround(options.heightFraction * float(image.height()))));
    const int frameWidth = std::max(3 * kCapHeight * scale / 2, frameHeight / 12);
    const std::vector<std::string> labels = colorBarLabels(range);
    int labelWidth = 0;
    for (const std::string& label : labels) labelWidth = std::max(labelWidth, textWidth(label, scale));
    const int barBlockWidth = frameWidth + tickLength + labelGap + labelWidth;
    const std::vector<std::string> lines = titleLines(title, units, barBlockWidth, scale);
    int contentWidth = barBlockWidth;
    for (const std::string& line : lines) contentWidth = std::max(contentWidth, textWidth(line, scale));
    const int lineHeight = textHeight(scale) + scale;
    const int titleHeight = lines.empty() ? 0 : static_cast<int>(lines.size()) * lineHeight + scale;

    const int backingHeight = 2 * pad + titleHeight + 2 * capHalf + frameHeight;
    const int backingTop = std::max(0, image.height() - margin - backingHeight);  // lower right corner
    const int backingRight = image.width() - margin;
    const PixelRect backing{backingRight - (contentWidth + 2 * pad), backingTop, backingRight,
                            backingTop + backingHeight};
    drawBacking(image, backing, options.backingOpacity);
    fill(image, {backing.x0, backing.y0, backing.x1, backing.y0 + stroke}, kEdge);
    fill(image, {backing.x0, backing.y1 - stroke, backing.x1, backing.y1}, kEdge);
    fill(image, {backing.x0, backing.y0, backing.x0 + stroke, backing.y1}, kEdge);
    fill(image, {backing.x1 - stroke, backing.y0, backing.x1, backing.y1}, kEdge);

    const int left = backing.x0 + pad;
    for (std::size_t i = 0; i < lines.size(); ++i)
        drawText(image, left, backing.y0 + pad + static_cast<int>(i) * lineHeight, lines[i], kInk, scale);

    const int frameTop = backing.y0 + pad + titleHeight + capHalf;
    const PixelRect frame{left, frameTop, left + frameWidth, frameTop + frameHeight};
    const PixelRect gradient{frame.x0 + stroke, frame.y0 + stroke, frame.x1 - stroke, frame.y1 - stroke};
    fill(image, frame, kInk);
    const int gradientHeight = gradient.y1 - gradient.y0;
    for (int y = gradient.y0; y < gradient.y1; ++y) {
        const float t = 1.0f - (float(y - gradient.y0) + 0.5f) / float(gradientHeight);
        fill(image, {gradient.x0, y, gradient.x1, y + 1}, map.at(t));
    }

    for (std::size_t i = 0; i < labels.size(); ++i) {
        const float t = labels.size() == 1 ? 0.5f : float(i) / float(labels.size() - 1);
        const int y = gradient.y0 + static_cast<int>(std::lround((1.0f - t) * float(gradientHeight - 1)));
        fill(image, {frame.x1, y - stroke / 2, frame.x1 + tickLength, y - stroke / 2 + stroke}, kInk);
        drawText(image, frame.x1 + tickLength + labelGap, y - kCapHeight * scale / 2, labels[i], kInk, scale);
    }
    return {clipped(backing, image), clipped(gradient, image)};
}

}  // namespace ivis::core
