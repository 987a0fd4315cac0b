/// @file base64_stream.h
/// @brief Decodes base64 text a few bytes at a time, as VTK's vtkBase64InputStream reads it.
/// @note Padding may end a group in the middle of the text: VTK encodes a binary header and the
///       data behind it as two separate base64 runs ("AAAAAA==BBBB..."), other writers as one.
///       Whitespace between characters is skipped.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ivis::core::detail {

/// Sequential base64 decoder over text that outlives it.
class Base64Stream {
public:
    explicit Base64Stream(std::string_view text) : mText(text) {}

    /// Decodes the next @a count bytes into @a out (resized to @a count); false with problem() set
    /// when the text ends first or holds a character that is not base64.
    bool read(std::size_t count, std::string& out);
    /// An upper bound on the bytes still to come (for sanity checks before allocating).
    std::size_t available() const { return (mText.size() - mPos) / 4 * 3 + 3; }
    /// Why the last read failed ("the base64 text ends early", "'%' is not a base64 character").
    const std::string& problem() const { return mProblem; }

private:
    /// Decodes the next group of four characters into mGroup; false at the end or on a bad one.
    bool nextGroup();

    std::string_view mText;
    std::size_t mPos = 0;
    unsigned char mGroup[3] = {};
    int mGroupSize = 0;  ///< decoded bytes in mGroup (1 to 3)
    int mGroupUsed = 0;  ///< of which already handed out
    std::string mProblem;
};

}  // namespace ivis::core::detail
