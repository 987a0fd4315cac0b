#include <ivis/core/color_bar.h>

#include <ivis/core/errors.h>
#include <ivis/core/font.h>
#include <ivis/core/utf8.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace ivis::core {
namespace {

const glm::vec3 kInk = linearFromSrgb(glm::vec3(0.13f));  // text, frame and ticks
constexpr int kSvgStops = 64;                             // gradient stops of the SVG ramp

constexpr int kMaxLinesPerPart = 2;         // lines for the title, and for the units, before an ellipsis
constexpr const char* kEllipsis = "\xE2\x80\xA6";  // U+2026

std::string titleText(const ColorBarContent& content)
{
    const std::string bracketed = content.units.empty() ? "" : "[" + content.units + "]";
    if (content.title.empty() || bracketed.empty()) return content.title + bracketed;
    return content.title + " " + bracketed;
}

// The characters of @a text as byte counts (a byte that starts no UTF-8 character counts as one).
std::vector<std::size_t> characterEnds(const std::string& text)
{
    std::vector<std::size_t> ends;
    for (std::size_t i = 0; i < text.size();) ends.push_back(i += std::max<std::size_t>(1, utf8Length(text, i)));
    return ends;
}

// The longest start of @a text (whole characters) no wider than @a width after @a suffix is added.
std::string fittingStart(const std::string& text, const std::string& suffix, int width, int fontPixels)
{
    std::string kept;
    for (const std::size_t end : characterEnds(text)) {
        if (Font::standard().measure(text.substr(0, end) + suffix, fontPixels).width > width) break;
        kept = text.substr(0, end);
    }
    return kept;
}

// @a text in lines no wider than @a width: broken between words, within a word where one word is
// wider, and at most kMaxLinesPerPart lines, the last ending in an ellipsis where text is left.
std::vector<std::string> wrappedLines(const std::string& text, int width, int fontPixels)
{
    const Font& font = Font::standard();
    std::vector<std::string> lines;
    std::string rest = text;
    while (!rest.empty()) {
        if (font.measure(rest, fontPixels).width <= width) {
            lines.push_back(rest);
            break;
        }
        if (int(lines.size()) + 1 == kMaxLinesPerPart) {
            lines.push_back(fittingStart(rest, kEllipsis, width, fontPixels) + kEllipsis);
            break;
        }
        std::string line = fittingStart(rest, "", width, fontPixels);
        const std::size_t space = rest[line.size()] == ' ' ? std::string::npos : line.rfind(' ');
        if (space != std::string::npos && space > 0) line.resize(space);  // the word cut goes to the next line
        if (line.empty()) line = rest.substr(0, characterEnds(rest).front());  // one character wider than the bar
        lines.push_back(line);
        rest.erase(0, std::min(rest.size(), rest.find_first_not_of(' ', line.size())));
    }
    return lines;
}

// Title lines: one line, or title and units on lines of their own when one line is wider than
// @a width, each wrapped to it.
std::vector<std::string> titleLines(const ColorBarContent& content, int width, int fontPixels)
{
    const std::string joined = titleText(content);
    if (joined.empty()) return {};
    if (content.title.empty() || content.units.empty()) return wrappedLines(joined, width, fontPixels);
    if (Font::standard().measure(joined, fontPixels).width <= width) return {joined};
    std::vector<std::string> lines = wrappedLines(content.title, width, fontPixels);
    for (const std::string& l : wrappedLines("[" + content.units + "]", width, fontPixels)) lines.push_back(l);
    return lines;
}

// The ticks whose labels do not collide: range ends first, then the others in order, each kept
// when its label's extent along the bar (@a extent) stays @a gap from every kept one.
template <typename ExtentFn>
std::vector<ColorBarTick> legibleTicks(const std::vector<ColorBarTick>& ticks, ExtentFn extent, int gap)
{
    std::vector<std::pair<int, int>> taken;
    std::vector<char> keep(ticks.size(), 0);
    for (const bool ends : {true, false})
        for (std::size_t i = 0; i < ticks.size(); ++i) {
            if (ticks[i].rangeEnd != ends) continue;
            const std::pair<int, int> span = extent(ticks[i]);
            const bool free = std::none_of(taken.begin(), taken.end(), [&](const std::pair<int, int>& t) {
                return span.first < t.second + gap && t.first < span.second + gap;
            });
            if (!free && !ends) continue;
            keep[i] = 1;
            taken.push_back(span);
        }
    std::vector<ColorBarTick> kept;
    for (std::size_t i = 0; i < ticks.size(); ++i)
        if (keep[i]) kept.push_back(ticks[i]);
    return kept;
}

std::string hexColour(const glm::vec3& linear)
{
    char text[8];
    auto byte = [](float c) { return int(std::lround(std::clamp(srgbFromLinear(c), 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(linear.r), byte(linear.g), byte(linear.b));
    return text;
}

/// @a text as XML character data: markup escaped, and each byte that does not start a UTF-8
/// character (a Latin-1 name or --units) or is a control character XML forbids as U+FFFD.
std::string xmlEscaped(const std::string& text)
{
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t length = utf8Length(text, i);
        if (length == 0 || (c < 0x20 && c != '\t' && c != '\n' && c != '\r')) {
            out += "\xEF\xBF\xBD";
            ++i;
            continue;
        }
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out.append(text, i, length);
        }
        i += length;
    }
    return out;
}

}  // namespace

LegendSide legendSideFromName(const std::string& name)
{
    if (name == "right") return LegendSide::Right;
    if (name == "left") return LegendSide::Left;
    if (name == "bottom") return LegendSide::Bottom;
    throw InputError("unknown colour-bar side '" + name + "' (known: right, left, bottom)");
}

ColorBarDrawing layOutColorBar(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side)
{
    if (pictureWidth < 1 || pictureHeight < 1) throw ValueError("colour bar for an empty picture");
    const Font& font = Font::standard();
    ColorBarDrawing d;
    d.vertical = side != LegendSide::Bottom;
    const int along = d.vertical ? pictureHeight : pictureWidth;  // the picture's side the bar runs along
    d.fontPixels = std::max(12, int(std::lround(along / 45.0)));
    const int em = d.fontPixels;
    const TextExtent line = font.measure("0", em);
    const int lineHeight = line.ascent + line.descent;
    const int pad = em;
    const int thickness = std::max(10, em);
    const int stroke = std::max(1, em / 12);
    const int tickLength = std::max(3, em / 3);
    const int gap = std::max(2, em / 4);
    const int length = std::max(2 * lineHeight, int(std::lround(0.6 * along)));
    const std::vector<ColorBarTick> all = colorBarTicks(content.scale);

    // Pixel offset along the bar of colour-map position t (vertical: from the top).
    auto offset = [&](float t) {
        return int(std::lround((d.vertical ? 1.0f - t : t) * float(length - 1)));
    };
    if (d.vertical) {
        d.ticks = legibleTicks(all, [&](const ColorBarTick& t) {
            const int y = offset(t.position);
            return std::pair{y - line.ascent / 2 - 1, y + line.ascent / 2 + line.descent};
        }, gap);
        int labelWidth = 0;
        for (const ColorBarTick& t : d.ticks) labelWidth = std::max(labelWidth, font.measure(t.label, em).width);
        const int blockWidth = thickness + tickLength + gap + labelWidth;
        const std::vector<std::string> lines = titleLines(content, std::max(blockWidth, pictureWidth / 4), em);
        int contentWidth = blockWidth;
        for (const std::string& l : lines) contentWidth = std::max(contentWidth, font.measure(l, em).width);
        // Below the title, room for the top tick's label, which stands half a line above the bar.
        const int titleHeight = int(lines.size()) * lineHeight + (lines.empty() ? 0 : gap + line.ascent / 2 + 1);
        d.width = 2 * pad + contentWidth;
        d.height = std::max(pictureHeight, 2 * pad + titleHeight + length + lineHeight);
        const int top = (d.height - (titleHeight + length)) / 2;  // title and bar centred as one group
        for (std::size_t i = 0; i < lines.size(); ++i)
            d.labels.push_back({pad, top + int(i) * lineHeight + line.ascent, lines[i], false});
        d.gradient = {pad, top + titleHeight, pad + thickness, top + titleHeight + length};
        for (const ColorBarTick& t : d.ticks) {
            const int y = d.gradient.y0 + offset(t.position);
            d.ink.push_back({d.gradient.x1, y - stroke / 2, d.gradient.x1 + tickLength, y - stroke / 2 + stroke});
            d.labels.push_back({d.gradient.x1 + tickLength + gap, y + line.ascent / 2, t.label, false});
        }
    } else {
        d.ticks = legibleTicks(all, [&](const ColorBarTick& t) {
            const int x = offset(t.position), w = font.measure(t.label, em).width;
            return std::pair{x - w / 2, x + w - w / 2};
        }, 2 * gap);
        const std::vector<std::string> lines = titleLines(content, length, em);
        const int titleHeight = int(lines.size()) * lineHeight + (lines.empty() ? 0 : gap);
        d.width = pictureWidth;
        d.height = 2 * pad + titleHeight + thickness + tickLength + gap + lineHeight;
        const int left = (d.width - length) / 2;
        for (std::size_t i = 0; i < lines.size(); ++i)
            d.labels.push_back({d.width / 2, pad + int(i) * lineHeight + line.ascent, lines[i], true});
        d.gradient = {left, pad + titleHeight, left + length, pad + titleHeight + thickness};
        for (const ColorBarTick& t : d.ticks) {
            const int x = d.gradient.x0 + offset(t.position);
            d.ink.push_back({x - stroke / 2, d.gradient.y1, x - stroke / 2 + stroke, d.gradient.y1 + tickLength});
            d.labels.push_back({x, d.gradient.y1 + tickLength + gap + line.ascent, t.label, true});
        }
    }
    const PixelRect& g = d.gradient;  // the frame, drawn around the ramp
    d.ink.push_back({g.x0 - stroke, g.y0 - stroke, g.x1 + stroke, g.y0});
    d.ink.push_back({g.x0 - stroke, g.y1, g.x1 + stroke, g.y1 + stroke});
    d.ink.push_back({g.x0 - stroke, g.y0, g.x0, g.y1});
    d.ink.push_back({g.x1, g.y0, g.x1 + stroke, g.y1});
    return d;
}

void paintColorBar(Image& image, int x, int y, const ColorBarDrawing& drawing, const ColorBarContent& content)
{
    const Colormap& map = colormap(content.colormap);
    auto fill = [&](const PixelRect& r, auto colourAt) {
        for (int py = std::max(0, y + r.y0); py < std::min(image.height(), y + r.y1); ++py)
            for (int px = std::max(0, x + r.x0); px < std::min(image.width(), x + r.x1); ++px)
                image.at(px, py) = glm::vec4(colourAt(px - x, py - y), 1.0f);
    };
    const PixelRect& g = drawing.gradient;
    fill(g, [&](int px, int py) {
        const float t = drawing.vertical ? 1.0f - (float(py - g.y0) + 0.5f) / float(g.y1 - g.y0)
                                         : (float(px - g.x0) + 0.5f) / float(g.x1 - g.x0);
        return map.at(t);
    });
    for (const PixelRect& r : drawing.ink) fill(r, [](int, int) { return kInk; });
    const Font& font = Font::standard();
    for (const ColorBarDrawing::Text& t : drawing.labels) {
        const int start = t.centred ? t.x - font.measure(t.text, drawing.fontPixels).width / 2 : t.x;
        font.draw(image, x + start, y + t.baseline, t.text, kInk, drawing.fontPixels);
    }
}

int colorBarMargin(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side)
{
    const ColorBarDrawing d = layOutColorBar(content, pictureWidth, pictureHeight, side);
    return side == LegendSide::Bottom ? d.height : d.width;
}

Image withColorBar(const Image& picture, const ColorBarContent& content, LegendSide side, const glm::vec4& background,
                   int minimumMargin)
{
    const ColorBarDrawing d = layOutColorBar(content, picture.width(), picture.height(), side);
    const bool bottom = side == LegendSide::Bottom;
    const int margin = std::max(minimumMargin, bottom ? d.height : d.width);
    Image canvas(picture.width() + (bottom ? 0 : margin), bottom ? picture.height() + margin : std::max(picture.height(), d.height),
                 background);
    const int pictureX = side == LegendSide::Left ? margin : 0;
    const int pictureY = bottom ? 0 : (canvas.height() - picture.height()) / 2;
    for (int y = 0; y < picture.height(); ++y)
        for (int x = 0; x < picture.width(); ++x) canvas.at(pictureX + x, pictureY + y) = picture.at(x, y);
    const int barX = side == LegendSide::Right ? picture.width() : side == LegendSide::Left ? margin - d.width : 0;
    const int barY = bottom ? picture.height() : 0;
    paintColorBar(canvas, barX, barY, d, content);
    return canvas;
}

Image colorBarImage(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side,
                    const glm::vec4& background)
{
    const ColorBarDrawing d = layOutColorBar(content, pictureWidth, pictureHeight, side);
    Image image(d.width, d.height, background);
    paintColorBar(image, 0, 0, d, content);
    return image;
}

std::string colorBarSvg(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side)
{
    const ColorBarDrawing d = layOutColorBar(content, pictureWidth, pictureHeight, side);
    const Colormap& map = colormap(content.colormap);
    const PixelRect& g = d.gradient;
    std::ostringstream svg;
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << d.width << "\" height=\"" << d.height
        << "\" viewBox=\"0 0 " << d.width << ' ' << d.height << "\">\n"
        << "<defs><linearGradient id=\"ramp\" x1=\"0\" y1=\"" << (d.vertical ? 1 : 0) << "\" x2=\""
        << (d.vertical ? 0 : 1) << "\" y2=\"0\">\n";
    for (int i = 0; i <= kSvgStops; ++i) {
        const float t = float(i) / kSvgStops;
        svg << "<stop offset=\"" << t << "\" stop-color=\"" << hexColour(map.at(t)) << "\"/>\n";
    }
    svg << "</linearGradient></defs>\n"
        << "<rect x=\"" << g.x0 << "\" y=\"" << g.y0 << "\" width=\"" << g.x1 - g.x0 << "\" height=\"" << g.y1 - g.y0
        << "\" fill=\"url(#ramp)\"/>\n";
    const std::string ink = hexColour(kInk);
    for (const PixelRect& r : d.ink)
        svg << "<rect x=\"" << r.x0 << "\" y=\"" << r.y0 << "\" width=\"" << r.x1 - r.x0 << "\" height=\""
            << r.y1 - r.y0 << "\" fill=\"" << ink << "\"/>\n";
    svg << "<g font-family=\"DejaVu Sans, Verdana, sans-serif\" font-size=\"" << d.fontPixels << "\" fill=\"" << ink
        << "\">\n";
    for (const ColorBarDrawing::Text& t : d.labels)
        svg << "<text x=\"" << t.x << "\" y=\"" << t.baseline << '"' << (t.centred ? " text-anchor=\"middle\"" : "")
            << '>' << xmlEscaped(t.text) << "</text>\n";
    svg << "</g>\n</svg>\n";
    return svg.str();
}

}  // namespace ivis::core
