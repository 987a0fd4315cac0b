#include "base64_stream.h"

#include <array>
#include <cctype>

namespace ivis::core::detail {
namespace {

constexpr int kPad = 64;
constexpr int kInvalid = -1;

/// Value of each character: 0..63, kPad for '=', kInvalid otherwise.
constexpr std::array<int, 256> kValues = [] {
    std::array<int, 256> v{};
    for (int& x : v) x = kInvalid;
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i) v[static_cast<unsigned char>(alphabet[i])] = i;
    v['='] = kPad;
    return v;
}();

}  // namespace

bool Base64Stream::read(std::size_t count, std::string& out)
{
    out.resize(count);
    for (std::size_t i = 0; i < count;) {
        if (mGroupUsed == mGroupSize) {
            if (!nextGroup()) return false;
        }
        while (mGroupUsed < mGroupSize && i < count) out[i++] = char(mGroup[mGroupUsed++]);
    }
    return true;
}

bool Base64Stream::nextGroup()
{
    int values[4];
    for (int k = 0; k < 4; ++k) {
        while (mPos < mText.size() && std::isspace(static_cast<unsigned char>(mText[mPos]))) ++mPos;
        if (mPos == mText.size()) {
            mProblem = "the base64 text ends early";
            return false;
        }
        const char c = mText[mPos++];
        values[k] = kValues[static_cast<unsigned char>(c)];
        if (values[k] == kInvalid || (values[k] == kPad && k < 2)) {
            mProblem = "'" + std::string(1, c) + "' is not a base64 character here";
            return false;
        }
    }
    if (values[2] == kPad && values[3] != kPad) {
        mProblem = "'=' is not a base64 character here";
        return false;
    }
    mGroupSize = values[2] == kPad ? 1 : values[3] == kPad ? 2 : 3;
    const int v2 = values[2] == kPad ? 0 : values[2];
    const int v3 = values[3] == kPad ? 0 : values[3];
    const unsigned bits = unsigned(values[0]) << 18 | unsigned(values[1]) << 12 | unsigned(v2) << 6 | unsigned(v3);
    mGroup[0] = static_cast<unsigned char>(bits >> 16);
    mGroup[1] = static_cast<unsigned char>(bits >> 8);
    mGroup[2] = static_cast<unsigned char>(bits);
    mGroupUsed = 0;
    return true;
}

}  // namespace ivis::core::detail
