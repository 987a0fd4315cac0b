#include <ivis/core/font.h>

#include <ivis/core/errors.h>

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>

namespace ivis::core {
namespace {

constexpr const char* kDefaultFontPaths[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",  // Debian / Ubuntu fonts-dejavu-core
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",           // Fedora, Arch
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
};

void checkPixelSize(int pixelSize)
{
    if (pixelSize < 1) throw ValueError("font pixel size must be >= 1, got " + std::to_string(pixelSize));
}

}  // namespace

struct Font::Face {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    std::mutex mutex;

    ~Face()
    {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }

    // Sets the em size; the caller holds the lock.
    void setSize(int pixelSize)
    {
        checkPixelSize(pixelSize);
        if (FT_Set_Pixel_Sizes(face, 0, FT_UInt(pixelSize)) != 0)
            throw ValueError("font cannot be scaled to " + std::to_string(pixelSize) + " pixels");
    }

    // Calls @a glyph(bitmap, left, top) for each rendered glyph of @a text at pen positions from
    // 0 (26.6 fixed point, kerned); returns the final pen position. The caller holds the lock.
    template <typename GlyphFn>
    FT_Pos layOut(const std::u32string& text, bool render, GlyphFn&& glyph)
    {
        FT_Pos pen = 0;
        FT_UInt previous = 0;
        for (const char32_t c : text) {
            const FT_UInt index = FT_Get_Char_Index(face, FT_ULong(c));
            if (previous && index && FT_HAS_KERNING(face)) {
                FT_Vector kern{};
                if (FT_Get_Kerning(face, previous, index, FT_KERNING_DEFAULT, &kern) == 0) pen += kern.x;
            }
            if (FT_Load_Glyph(face, index, render ? FT_LOAD_RENDER : FT_LOAD_DEFAULT) != 0) continue;
            if (render) glyph(face->glyph->bitmap, int((pen + 32) >> 6) + face->glyph->bitmap_left, face->glyph->bitmap_top);
            pen += face->glyph->advance.x;
            previous = index;
        }
        return pen;
    }
};

Font::Font(const std::string& path) : mPath(path), mFace(std::make_unique<Face>())
{
    if (FT_Init_FreeType(&mFace->library) != 0) throw InputError("FreeType failed to start");
    if (FT_New_Face(mFace->library, path.c_str(), 0, &mFace->face) != 0)
        throw InputError(path + ": not a font FreeType can read");
    if (!FT_IS_SCALABLE(mFace->face)) throw InputError(path + ": not a scalable font");
}

Font::~Font() = default;

const Font& Font::standard()
{
    static std::once_flag once;
    static std::unique_ptr<Font> font;
    static std::string failure;
    std::call_once(once, [] {
        std::vector<std::string> paths;
        if (const char* chosen = std::getenv("IVIS_FONT"); chosen && *chosen) paths.push_back(chosen);
        else paths.assign(std::begin(kDefaultFontPaths), std::end(kDefaultFontPaths));
        for (const std::string& path : paths) {
            try {
                font = std::make_unique<Font>(path);
                return;
            } catch (const InputError&) {
            }
        }
        failure = "no font for the colour bar: install fonts-dejavu-core or set IVIS_FONT to a .ttf file (looked at";
        for (const std::string& path : paths) failure += " " + path;
        failure += ")";
    });
    if (!font) throw InputError(failure);
    return *font;
}

TextExtent Font::measure(const std::string& utf8, int pixelSize) const
{
    std::lock_guard<std::mutex> lock(mFace->mutex);
    mFace->setSize(pixelSize);
    const FT_Pos pen = mFace->layOut(decodeUtf8(utf8), false, [](const FT_Bitmap&, int, int) {});
    const FT_Size_Metrics& metrics = mFace->face->size->metrics;
    return {int((pen + 63) >> 6), int((metrics.ascender + 63) >> 6), int((-metrics.descender + 63) >> 6)};
}

void Font::draw(Image& image, int x, int baseline, const std::string& utf8, const glm::vec3& color, int pixelSize) const
{
    std::lock_guard<std::mutex> lock(mFace->mutex);
    mFace->setSize(pixelSize);
    mFace->layOut(decodeUtf8(utf8), true, [&](const FT_Bitmap& bitmap, int left, int top) {
        for (unsigned row = 0; row < bitmap.rows; ++row)
            for (unsigned column = 0; column < bitmap.width; ++column) {
                const float coverage = bitmap.buffer[row * bitmap.pitch + column] / 255.0f;
                if (coverage <= 0.0f) continue;
                // Dark ink composited in sRGB space, as viewers expect text to look.
                const float opacity = 1.0f - std::pow(1.0f - coverage, 2.2f);
                const int px = x + left + int(column), py = baseline - top + int(row);
                if (px >= 0 && py >= 0 && px < image.width() && py < image.height())
                    image.blendOver(px, py, color, opacity);
            }
    });
}

std::u32string decodeUtf8(const std::string& utf8)
{
    constexpr char32_t kReplacement = 0xFFFD;
    std::u32string out;
    for (std::size_t i = 0; i < utf8.size();) {
        const unsigned char lead = static_cast<unsigned char>(utf8[i]);
        const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || i + length > utf8.size()) {
            out.push_back(kReplacement);
            ++i;
            continue;
        }
        char32_t c = length == 1 ? lead : lead & (0x7F >> length);
        bool valid = true;
        for (int k = 1; k < length; ++k) {
            const unsigned char next = static_cast<unsigned char>(utf8[i + k]);
            valid = valid && (next >> 6) == 0x2;
            c = (c << 6) | (next & 0x3F);
        }
        const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
        if (!valid || c < smallest[length] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
            out.push_back(kReplacement);
            ++i;
            continue;
        }
        out.push_back(c);
        i += std::size_t(length);
    }
    return out;
}

}  // namespace ivis::core
