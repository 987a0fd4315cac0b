/// @file mesh_layout_check.h
/// @brief Walks the bytes of a PLY, OFF, OBJ or STL file the way OpenMesh 9.0 will read them and
///        rejects layouts it would misread, loop on or crash on.
/// @note Internal to readMesh: every failure is an InputError with the one-line message
///       "<path>: <problem>"; vertex and face numbers count from 0, OBJ ones from 1.
#pragma once

#include <ivis/core/data_array.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ivis::core::detail {

/// Mesh file formats OpenMesh reads for readMesh.
enum class MeshFormat { Obj, Off, Ply, Stl };

/// Facts about a checked file that its OpenMesh import needs.
struct MeshLayout {
    /// An ASCII PLY property of an 8-bit type, declared 16-bit to OpenMesh (whose ASCII reader
    /// reads an 8-bit value as one character): its array takes the file's type back.
    struct BytePlyProperty {
        Association association = Association::Point;  ///< vertex: Point, face: Cell
        std::string name;
        ValueType type = ValueType::UInt8;
    };
    std::size_t facesInFile = 0;  ///< faces (STL facets) the file declares or contains
    bool binaryStl = false;       ///< STL whose size matches its binary triangle count
    std::vector<BytePlyProperty> asciiPlyBytes;
    /// The points as the file holds them, in double, where it holds more than single precision (OBJ,
    /// OFF and ASCII PLY text, binary PLY with double coordinates); else empty.
    std::vector<glm::dvec3> filePoints;
    /// An ASCII STL's facet corners in double, three a facet (its mesh is built from them, since
    /// OpenMesh would merge corners by their single-precision values); else empty.
    std::vector<glm::dvec3> stlCorners;
};

/// Throws the one-line InputError "<path>: <problem>"; control bytes of @a problem (quoted from
/// the file) are written as \xNN.
[[noreturn]] void failInput(const std::string& path, const std::string& problem);

/// Lower-case name of @a format: "obj", "off", "ply" or "stl".
const char* formatName(MeshFormat format);

/// Checks the whole file in @a data and may rewrite a binary PLY header into the form OpenMesh expects.
MeshLayout checkMeshLayout(const std::string& path, MeshFormat format, std::string& data);

/// Whitespace-separated tokens and lines of text held in memory, split as an istream splits them.
class TextCursor {
public:
    /// Starts at byte @a pos of @a text, which must outlive the cursor.
    explicit TextCursor(const std::string& text, std::size_t pos = 0) : mText(text), mPos(pos) {}

    /// Next token, or "" at the end of the text.
    std::string_view token()
    {
        while (mPos < mText.size() && std::isspace(static_cast<unsigned char>(mText[mPos]))) ++mPos;
        const std::size_t begin = mPos;
        while (mPos < mText.size() && !std::isspace(static_cast<unsigned char>(mText[mPos]))) ++mPos;
        return std::string_view(mText).substr(begin, mPos - begin);
    }
    /// Rest of the current line without its newline; moves past the newline.
    std::string_view line()
    {
        const std::size_t begin = mPos;
        const std::size_t end = std::min(mText.find('\n', mPos), mText.size());
        mPos = std::min(end + 1, mText.size());
        return std::string_view(mText).substr(begin, end - begin);
    }
    /// True when every byte has been consumed.
    bool atEnd() const { return mPos >= mText.size(); }
    /// Offset of the next unread byte.
    std::size_t pos() const { return mPos; }

private:
    const std::string& mText;
    std::size_t mPos;
};

/// A number token as a stream reads it into a float.
struct FloatToken {
    enum Kind { Finite, NonFinite, NotANumber } kind;
    double value;
};

/// Classifies @a token: decimals Finite; nan/inf spellings and float overflow NonFinite; else NotANumber.
FloatToken parseFloatToken(std::string_view token);

}  // namespace ivis::core::detail
