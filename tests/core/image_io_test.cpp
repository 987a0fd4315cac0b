#include <ivis/core/errors.h>
#include <ivis/core/image.h>
#include <ivis/core/image_io.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <limits>
#include <string>
#include <vector>

namespace ivis::core {
namespace {
namespace fs = std::filesystem;

float linearFromByte(int code) { return linearFromSrgb(code / 255.0f); }
int byteFromLinear(float v) { return static_cast<int>(std::lround(srgbFromLinear(v) * 255.0f)); }

std::vector<std::string> folderEntries(const std::string& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    return names;
}

// Expects InputError "<path>: cannot write (...)" from @a write.
template <typename Write>
void expectWriteError(const std::string& path, const Write& write)
{
    try {
        write();
        FAIL() << "expected InputError for " << path;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": cannot write (", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(ImageIo, PngEncodesHalfLinearAsSrgb188)
{
    test::TempDir dir;
    writePng(Image(1, 1, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)), dir.file("half.png"), false);
    const Image read = readPng(dir.file("half.png"));
    ASSERT_EQ(read.width(), 1);
    EXPECT_EQ(read.at(0, 0), glm::vec4(glm::vec3(linearFromByte(188)), 1.0f));
}

/// The 8-bit sRGB level by its formula, clamped, NaN at 0.
int levelByFormula(float linear)
{
    const float encoded = srgbFromLinear(linear);
    return static_cast<int>(std::lround((encoded > 0.0f ? std::min(encoded, 1.0f) : 0.0f) * 255.0f));
}

TEST(SrgbByte, IsTheFormulasLevelOnBothSidesOfEveryStepAndAtRandomValues)
{
    for (int level = 1; level < 256; ++level) {  // the step's least float, by bisection on the formula
        float below = 0.0f, at = 1.0f;
        while (std::nextafter(below, 1.0f) < at) {
            const float middle = below + (at - below) / 2.0f;
            if (middle == below || middle == at) break;
            (levelByFormula(middle) >= level ? at : below) = middle;
        }
        while (levelByFormula(std::nextafter(at, 0.0f)) >= level) at = std::nextafter(at, 0.0f);
        ASSERT_EQ(srgbByteFromLinear(at), levelByFormula(at)) << level;
        ASSERT_EQ(srgbByteFromLinear(std::nextafter(at, 0.0f)), levelByFormula(std::nextafter(at, 0.0f))) << level;
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(-0.1f, 1.1f);
    for (int i = 0; i < 1000000; ++i) {
        const float v = value(random);
        ASSERT_EQ(srgbByteFromLinear(v), levelByFormula(v)) << v;
    }
    const float inf = std::numeric_limits<float>::infinity();
    for (const float v : {0.0f, -0.0f, 1e-40f, 1.0f, std::nextafter(1.0f, 0.0f), 2.0f, inf, -inf})
        EXPECT_EQ(srgbByteFromLinear(v), levelByFormula(v)) << v;
    EXPECT_EQ(srgbByteFromLinear(std::numeric_limits<float>::quiet_NaN()), 0);
}

TEST(ImageIo, EncodedPngIsTheWrittenFile)
{
    test::TempDir dir;
    Image image(300, 200);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) image.at(x, y) = glm::vec4(x / 300.0f, y / 200.0f, 0.5f, 1.0f);
    writePng(image, dir.file("picture.png"), false);
    std::ifstream file(dir.file("picture.png"), std::ios::binary);
    const std::vector<std::uint8_t> written((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_EQ(encodePng(image, false), written);
    const Image read = readPng(dir.file("picture.png"));
    for (std::size_t i = 0; i < image.pixels().size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(levelByFormula(read.pixels()[i][c]), levelByFormula(image.pixels()[i][c])) << i;
}

TEST(ImageIo, PngRoundTripKeepsEveryRgbByte)
{
    test::TempDir dir;
    Image image(64, 12);  // 768 pixels: every code in each channel, rows from the top
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const int i = y * image.width() + x;
            image.at(x, y) = glm::vec4(linearFromByte(i % 256), linearFromByte((i * 7) % 256),
                                       linearFromByte((i * 13 + y) % 256), 1.0f);
        }
    writePng(image, dir.file("codes.png"), false);
    const Image read = readPng(dir.file("codes.png"));
    ASSERT_EQ(read.width(), image.width());
    ASSERT_EQ(read.height(), image.height());
    for (std::size_t i = 0; i < image.pixels().size(); ++i) ASSERT_EQ(read.pixels()[i], image.pixels()[i]) << i;
}

TEST(ImageIo, TransparentPngKeepsAlphaAndStraightColour)
{
    test::TempDir dir;
    Image image(256, 1);
    for (int x = 0; x < 256; ++x) {
        const float alpha = std::max(x, 1) / 255.0f;
        image.at(x, 0) = glm::vec4(glm::vec3(linearFromByte(x), linearFromByte(255 - x), linearFromByte(77)) * alpha,
                                   alpha);
    }
    writePng(image, dir.file("alpha.png"), true);
    const Image read = readPng(dir.file("alpha.png"));
    for (int x = 0; x < 256; ++x) {
        const glm::vec4 p = read.at(x, 0);
        ASSERT_EQ(static_cast<int>(std::lround(p.a * 255.0f)), std::max(x, 1));
        EXPECT_EQ(byteFromLinear(p.r / p.a), x);
        EXPECT_EQ(byteFromLinear(p.g / p.a), 255 - x);
        EXPECT_EQ(byteFromLinear(p.b / p.a), 77);
    }
}

TEST(ImageIo, OpaquePngDropsAlpha)
{
    test::TempDir dir;
    writePng(Image(2, 2, glm::vec4(0.0f)), dir.file("clear.png"), false);
    EXPECT_EQ(readPng(dir.file("clear.png")).at(1, 1), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
}

TEST(ImageIo, ExrRoundTripsLayersExactlyAndColourAsHalf)
{
    test::TempDir dir;
    Image image(5, 3, glm::vec4(0.25f, 0.5f, 2.0f, 1.0f));
    image.at(4, 0) = glm::vec4(0.1f, 0.0f, 0.0f, 0.5f);
    ImageLayers layers(5, 3);
    core::Channel& depth = layers.add("depth", std::numeric_limits<float>::infinity());
    core::Channel& px = layers.add("P.X");
    for (std::size_t i = 0; i < depth.size(); ++i) {
        depth[i] = i == 7 ? std::numeric_limits<float>::quiet_NaN() : 1.0f / 3.0f + float(i) * 1e5f;
        px[i] = -float(i) * 0.123456789f;
    }
    writeExr(image, layers, dir.file("layers.exr"));

    const std::vector<float> readDepth = readExrChannel(dir.file("layers.exr"), "depth");
    ASSERT_EQ(readDepth.size(), depth.size());
    EXPECT_EQ(std::memcmp(readDepth.data(), depth.data(), depth.size() * sizeof(float)), 0);
    EXPECT_EQ(readExrChannel(dir.file("layers.exr"), "P.X"), std::vector<float>(px.begin(), px.end()));
    const std::vector<float> red = readExrChannel(dir.file("layers.exr"), "R");
    EXPECT_EQ(red[0], 0.25f);
    EXPECT_NEAR(red[4], 0.1f, 1e-4f);  // top-right pixel, stored as half
    EXPECT_EQ(readExrChannel(dir.file("layers.exr"), "A")[4], 0.5f);
    EXPECT_EQ(readExrChannel(dir.file("layers.exr"), "B")[14], 2.0f);
}

TEST(ImageIo, ExrMissingChannelListsThePresentOnes)
{
    test::TempDir dir;
    ImageLayers layers(2, 2);
    layers.add("scalar");
    writeExr(Image(2, 2), layers, dir.file("a.exr"));
    try {
        readExrChannel(dir.file("a.exr"), "depth");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir.file("a.exr") + ": no channel 'depth' (channels: A, B, G, R, scalar)");
    }
    EXPECT_THROW(readExrChannel(dir.file("none.exr"), "R"), InputError);
    EXPECT_THROW(readPng(dir.file("a.exr")), InputError);
}

TEST(ImageIo, WritingIntoAMissingFolderNamesThePathAndLeavesNothing)
{
    test::TempDir dir;
    const std::string png = dir.file("missing/x.png");
    const std::string exr = dir.file("missing/x.exr");
    expectWriteError(png, [&] { writePng(Image(4, 4), png, true); });
    expectWriteError(exr, [&] { writeExr(Image(4, 4), ImageLayers(4, 4), exr); });
    try {
        writePng(Image(4, 4), png, false);
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), png + ": cannot write (No such file or directory)");
    }
    EXPECT_TRUE(folderEntries(dir.path()).empty());
}

TEST(ImageIo, FailedRenameRemovesTheTemporary)
{
    test::TempDir dir;
    const std::string occupied = dir.file("occupied");  // a folder where the image should go
    fs::create_directory(occupied);
    fs::create_directory(occupied + "/keep");
    expectWriteError(occupied, [&] { writePng(Image(4, 4), occupied, false); });
    expectWriteError(occupied, [&] { writeExr(Image(4, 4), ImageLayers(4, 4), occupied); });
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"occupied"});
}

TEST(ImageIo, SuccessfulWriteReplacesTheFileAndLeavesNoTemporary)
{
    test::TempDir dir;
    writePng(Image(3, 3, glm::vec4(1.0f)), dir.file("out.png"), false);
    writePng(Image(7, 2, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)), dir.file("out.png"), false);
    EXPECT_EQ(readPng(dir.file("out.png")).width(), 7);
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"out.png"});
}

TEST(ImageIo, RejectsEmptyImagesAndMismatchedLayers)
{
    test::TempDir dir;
    EXPECT_THROW(writePng(Image(), dir.file("e.png"), false), ValueError);
    EXPECT_THROW(writeExr(Image(4, 4), ImageLayers(4, 5), dir.file("e.exr")), ValueError);
    EXPECT_TRUE(folderEntries(dir.path()).empty());
}

TEST(ImageLayers, ValidatesNames)
{
    ImageLayers layers(3, 2);
    EXPECT_EQ(layers.add("region", -1.0f), core::Channel(6, -1.0f));
    EXPECT_THROW(layers.add("region"), ValueError);
    EXPECT_THROW(layers.add("A"), ValueError);
    EXPECT_THROW(layers.add(""), ValueError);
    EXPECT_THROW(layers.channel("steps"), ValueError);
    layers.channel("region")[5] = 4.0f;
    EXPECT_EQ(layers.channels().at("region")[5], 4.0f);
    EXPECT_THROW(Image(-1, 2), ValueError);
}

}  // namespace
}  // namespace ivis::core
