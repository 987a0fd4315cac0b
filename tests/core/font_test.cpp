#include <ivis/core/errors.h>
#include <ivis/core/font.h>

#include <gtest/gtest.h>

namespace ivis::core {
namespace {

TEST(Font, DecodesUtf8AndReplacesMalformedBytes)
{
    EXPECT_EQ(decodeUtf8("dyn/cm²"), std::u32string(U"dyn/cm\u00B2"));
    EXPECT_EQ(decodeUtf8("10⁻⁴"), std::u32string(U"10\u207B\u2074"));
    EXPECT_EQ(decodeUtf8("a\xFF" "b"), std::u32string(U"a\uFFFDb"));
    EXPECT_EQ(decodeUtf8("\xC3"), std::u32string(U"\uFFFD"));       // truncated
    EXPECT_EQ(decodeUtf8("\xC0\xAF"), std::u32string(U"\uFFFD\uFFFD"));  // overlong '/'
}

TEST(Font, MeasuresWiderTextWider)
{
    const Font& font = Font::standard();
    EXPECT_EQ(font.measure("", 20).width, 0);
    EXPECT_GT(font.measure("WWW", 20).width, font.measure("iii", 20).width);
    EXPECT_NEAR(font.measure("Pressure", 40).width, 2 * font.measure("Pressure", 20).width, 4);
    const TextExtent e = font.measure("x", 30);
    EXPECT_GT(e.ascent, 20);
    EXPECT_GT(e.descent, 3);
    EXPECT_THROW(font.measure("x", 0), ValueError);
}

TEST(Font, DrawsInkOnlyInsideTheTextBox)
{
    const Font& font = Font::standard();
    Image image(200, 80, glm::vec4(1.0f));
    const int x = 20, baseline = 50, size = 24;
    font.draw(image, x, baseline, "dyn/cm² Åg", glm::vec3(0.0f), size);
    const TextExtent e = font.measure("dyn/cm² Åg", size);
    int dark = 0;
    for (int py = 0; py < image.height(); ++py)
        for (int px = 0; px < image.width(); ++px) {
            if (image.at(px, py).r == 1.0f) continue;
            ASSERT_GE(px, x - 2);
            ASSERT_LE(px, x + e.width + 2);
            ASSERT_GE(py, baseline - e.ascent - 1);
            ASSERT_LE(py, baseline + e.descent + 1);
            if (image.at(px, py).r < 0.1f) ++dark;
        }
    EXPECT_GT(dark, 150);
}

TEST(Font, NamesAFileItCannotRead)
{
    try {
        Font font("/nonexistent/font.ttf");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/font.ttf"), std::string::npos);
    }
}

}  // namespace
}  // namespace ivis::core
