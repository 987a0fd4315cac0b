#include <ivis/core/errors.h>
#include <ivis/core/image.h>
#include <ivis/core/text_raster.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace ivis::core {
namespace {

const glm::vec4 kPaper(1.0f, 1.0f, 1.0f, 1.0f);
const glm::vec3 kRed(1.0f, 0.0f, 0.0f);

// Bounding box [x0, x1) x [y0, y1) of the pixels that are no longer paper; x0 == x1 when none.
struct Box {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int count = 0;
};

Box inkBox(const Image& image)
{
    Box box{image.width(), image.height(), 0, 0, 0};
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (image.at(x, y) == kPaper) continue;
            box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x + 1), std::max(box.y1, y + 1),
                   box.count + 1};
        }
    if (box.count == 0) box = {};
    return box;
}

Box drawn(const std::string& text, int scale, int x = 4, int y = 4)
{
    Image image(120, 60, kPaper);
    drawText(image, x, y, text, kRed, scale);
    return inkBox(image);
}

TEST(TextRaster, LetterDrawsPixelsAndSpaceDrawsNone)
{
    EXPECT_GT(drawn("A", 1).count, 10);
    EXPECT_EQ(drawn(" ", 1).count, 0);
    EXPECT_EQ(drawn("", 1).count, 0);
}

TEST(TextRaster, DrawsOpaqueColour)
{
    Image image(10, 12, glm::vec4(0.0f));
    drawText(image, 0, 0, "I", kRed);
    EXPECT_EQ(image.at(2, 3), glm::vec4(kRed, 1.0f));  // the stem of the I
    EXPECT_EQ(image.at(0, 3), glm::vec4(0.0f));
}

TEST(TextRaster, WidthMeasurementMatchesTheDrawnExtent)
{
    EXPECT_EQ(textWidth("", 2), 0);
    EXPECT_EQ(textWidth("A"), kGlyphWidth);
    EXPECT_EQ(textWidth("1.2e+03", 2), 2 * (7 * kGlyphAdvance - 1));
    EXPECT_EQ(textHeight(3), 3 * kGlyphHeight);
    for (int scale : {1, 2, 3}) {
        const Box box = drawn("MW", scale, 5, 3);  // both glyphs fill all five columns
        EXPECT_EQ(box.x0, 5);
        EXPECT_EQ(box.x1 - box.x0, textWidth("MW", scale));
        const Box tall = drawn("Hg", scale, 5, 3);  // cap top to descender bottom
        EXPECT_EQ(tall.y0, 3);
        EXPECT_EQ(tall.y1 - tall.y0, textHeight(scale));
        EXPECT_EQ(drawn("H", scale, 5, 3).y1 - 3, kCapHeight * scale);  // baseline
    }
}

TEST(TextRaster, EveryPrintableGlyphIsDistinctAndVisible)
{
    std::set<std::vector<bool>> seen;
    for (char c = '!'; c <= '~'; ++c) {
        std::vector<bool> bits;
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int column = 0; column < kGlyphWidth; ++column) bits.push_back(glyphPixel(c, column, row));
        EXPECT_NE(std::count(bits.begin(), bits.end(), true), 0) << c;
        EXPECT_TRUE(seen.insert(bits).second) << "glyph '" << c << "' repeats another";
    }
    EXPECT_FALSE(glyphPixel('A', kGlyphWidth, 0));
    EXPECT_FALSE(glyphPixel('A', 0, -1));
}

TEST(TextRaster, CharactersOutsideAsciiDrawAsQuestionMark)
{
    const Box question = drawn("?", 1);
    const Box other = drawn("\xC2", 1);  // first byte of a UTF-8 sequence
    EXPECT_EQ(other.count, question.count);
    EXPECT_EQ(other.x0, question.x0);
    EXPECT_EQ(drawn("\x07", 1).count, question.count);
}

TEST(TextRaster, ClipsAtTheImageBorder)
{
    Image image(8, 8, kPaper);
    drawText(image, -7, -5, "W8g", kRed, 2);
    drawText(image, 5, 6, "W8g", kRed, 2);
    EXPECT_GT(inkBox(image).count, 0);
    EXPECT_THROW(drawText(image, 0, 0, "x", kRed, 0), ValueError);
    EXPECT_THROW(textWidth("x", 0), ValueError);
}

}  // namespace
}  // namespace ivis::core
