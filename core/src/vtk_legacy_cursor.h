/// @file vtk_legacy_cursor.h
/// @brief Reads a VTK legacy file line by line and its data as ASCII tokens or big-endian binary.
/// @note Internal to the legacy reader. Every failure is an InputError "<path>: <problem>".
#pragma once

#include <ivis/core/data_array.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ivis::core::detail {

/// A position in the bytes of one legacy file.
class VtkLegacyCursor {
public:
    /// @a data must outlive the cursor.
    VtkLegacyCursor(const std::string& path, const std::string& data) : mPath(path), mData(data) {}

    /// Chooses how values are stored after the header: ASCII tokens or big-endian binary.
    void setBinary(bool binary) { mBinary = binary; }
    /// The next line that is not blank, split into its words (empty at the end of the file);
    /// the cursor moves past its newline, where binary data starts.
    std::vector<std::string> words();
    /// The next word in lower case without moving (at most 32 characters: binary data may follow).
    std::string peekWord() const;
    /// The next line as it is, without its newline.
    std::string_view line();
    /// True when only whitespace is left.
    bool atEnd() const;

    /// Reads @a count values of @a type; @a what names them in messages ("POINTS").
    std::vector<double> values(std::size_t count, ValueType type, const std::string& what);
    /// Reads @a count values of a `bit` array as 0 and 1: ASCII numbers (any but 0 is 1, as VTK
    /// reads them) or, in binary, bits packed eight to a byte, the first in the highest bit.
    std::vector<double> bits(std::size_t count, const std::string& what);

private:
    const std::string& mPath;
    const std::string& mData;
    std::size_t mPos = 0;
    bool mBinary = false;
};

}  // namespace ivis::core::detail
