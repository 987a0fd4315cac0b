#include "vtk_legacy_cursor.h"

#include "value_decoding.h"

#include <ivis/core/mesh_layout_check.h>

#include <algorithm>
#include <cctype>

namespace ivis::core::detail {
namespace {

bool isSpace(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

}  // namespace

std::string_view VtkLegacyCursor::line()
{
    const std::size_t begin = mPos;
    const std::size_t end = std::min(mData.find('\n', mPos), mData.size());
    mPos = std::min(end + 1, mData.size());
    std::string_view text = std::string_view(mData).substr(begin, end - begin);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
}

std::vector<std::string> VtkLegacyCursor::words()
{
    std::vector<std::string> out;
    while (out.empty() && mPos < mData.size()) {
        const std::string_view text = line();
        for (std::size_t i = 0; i < text.size();) {
            while (i < text.size() && isSpace(text[i])) ++i;
            const std::size_t start = i;
            while (i < text.size() && !isSpace(text[i])) ++i;
            if (i > start) out.emplace_back(text.substr(start, i - start));
        }
    }
    return out;
}

std::string VtkLegacyCursor::peekWord() const
{
    std::size_t i = mPos;
    while (i < mData.size() && isSpace(mData[i])) ++i;
    std::string word;
    for (; i < mData.size() && !isSpace(mData[i]) && word.size() < 32; ++i) {
        word += char(std::tolower(static_cast<unsigned char>(mData[i])));
    }
    return word;
}

bool VtkLegacyCursor::atEnd() const
{
    return std::all_of(mData.begin() + std::ptrdiff_t(mPos), mData.end(), isSpace);
}

std::vector<double> VtkLegacyCursor::values(std::size_t count, ValueType type, const std::string& what)
{
    if (mBinary) {
        const std::size_t size = valueTypeSize(type);
        if (count > (mData.size() - mPos) / size) {
            failInput(mPath, what + ": the file ends within its " + std::to_string(count) + " binary values");
        }
        std::vector<double> out = valuesFromBytes(mData.data() + mPos, count, type, true);
        mPos += count * size;
        return out;
    }
    std::vector<double> out;
    out.reserve(std::min(count, (mData.size() - mPos) / 2 + 1));
    for (std::size_t i = 0; i < count; ++i) {
        while (mPos < mData.size() && isSpace(mData[mPos])) ++mPos;
        const std::size_t start = mPos;
        while (mPos < mData.size() && !isSpace(mData[mPos])) ++mPos;
        if (start == mPos) {
            failInput(mPath, what + ": the file ends after " + std::to_string(i) + " of its " + std::to_string(count) +
                                 " values");
        }
        const std::string_view token = std::string_view(mData).substr(start, mPos - start);
        double v = 0.0;
        if (!parseNumber(token, v)) {
            failInput(mPath, what + ": value " + std::to_string(i) + " '" + std::string(token.substr(0, 40)) +
                                 "' is not a number");
        }
        out.push_back(v);
    }
    return out;
}

std::vector<double> VtkLegacyCursor::bits(std::size_t count, const std::string& what)
{
    if (!mBinary) {
        std::vector<double> out = values(count, ValueType::Float64, what);
        for (double& v : out) v = v != 0.0 ? 1.0 : 0.0;
        return out;
    }
    const std::size_t bytes = count / 8 + (count % 8 != 0 ? 1 : 0);
    if (bytes > mData.size() - mPos)
        failInput(mPath, what + ": the file ends within its " + std::to_string(count) + " binary bits");
    std::vector<double> out(count);
    for (std::size_t i = 0; i < count; ++i)
        out[i] = (static_cast<unsigned char>(mData[mPos + i / 8]) >> (7 - i % 8)) & 1u;
    mPos += bytes;
    return out;
}

}  // namespace ivis::core::detail
