/// @file font.h
/// @brief Anti-aliased text from a TrueType/OpenType font (FreeType), UTF-8 in, drawn into an
///        Image; DejaVu Sans (Debian's fonts-dejavu-core) by default.
/// @note Thread-safe: one FreeType face per Font, used under a lock.
#pragma once

#include <ivis/core/image.h>

#include <glm/vec3.hpp>

#include <memory>
#include <string>

namespace ivis::core {

/// @brief Size of a line of text at a pixel size: the advance width and the font's line metrics.
struct TextExtent {
    int width = 0;    ///< pen advance from the start to the end of the text, rounded up
    int ascent = 0;   ///< font ascender above the baseline (pixels)
    int descent = 0;  ///< font descender below the baseline (pixels, >= 0)
};

/// @brief A scalable font face.
class Font {
public:
    /// @brief Loads the font file at @a path.
    /// @throw InputError naming the file when FreeType cannot open it
    explicit Font(const std::string& path);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    /// @brief The font of every picture: the file named by $IVIS_FONT, else DejaVu Sans.
    /// @throw InputError naming the paths looked at when none loads
    static const Font& standard();

    /// @brief The file this font was loaded from.
    const std::string& path() const { return mPath; }
    /// @brief Extent of @a utf8 at @a pixelSize (the em size in pixels, >= 1).
    /// @throw ValueError for pixelSize < 1
    TextExtent measure(const std::string& utf8, int pixelSize) const;
    /// @brief Draws @a utf8 starting at pen position @a x on baseline @a baseline in opaque linear
    ///        @a color (meant for dark ink: coverage is blended as sRGB-space compositing would);
    ///        pixels outside the image are skipped. Invalid UTF-8 bytes are drawn as U+FFFD.
    /// @throw ValueError for pixelSize < 1
    void draw(Image& image, int x, int baseline, const std::string& utf8, const glm::vec3& color, int pixelSize) const;

private:
    struct Face;
    std::string mPath;
    std::unique_ptr<Face> mFace;
};

/// @brief Code points of @a utf8; malformed sequences become U+FFFD.
std::u32string decodeUtf8(const std::string& utf8);

}  // namespace ivis::core
