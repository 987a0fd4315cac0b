#include "vtk_xml_data_array.h"

#include "base64_stream.h"
#include "value_decoding.h"

#include <ivis/core/mesh_layout_check.h>
#include <ivis/core/number_text.h>

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <utility>

namespace ivis::core::detail {
namespace {

/// The bytes of one binary blob: a slice of raw appended data, or base64 text decoded on the way.
class BlobReader {
public:
    explicit BlobReader(std::string_view raw) : mRaw(raw) {}
    explicit BlobReader(Base64Stream base64) : mBase64(std::move(base64)), mIsBase64(true) {}

    bool read(std::size_t count, std::string& out)
    {
        if (count > available()) {
            mEndedEarly = true;
            return false;
        }
        if (mIsBase64) return mBase64.read(count, out);
        out.assign(mRaw.data() + mPos, count);
        mPos += count;
        return true;
    }
    std::size_t available() const { return mIsBase64 ? mBase64.available() : mRaw.size() - mPos; }
    std::string problem() const
    {
        if (mIsBase64 && !mEndedEarly) return mBase64.problem();
        return mIsBase64 ? "the base64 text ends early" : "the appended data ends early";
    }

private:
    std::string_view mRaw;
    std::size_t mPos = 0;
    Base64Stream mBase64{std::string_view()};
    bool mIsBase64 = false;
    bool mEndedEarly = false;
};

/// Reads and checks the blobs of one array; every failure names the file and the array.
class ArrayDecoder {
public:
    ArrayDecoder(const std::string& path, const std::string& what, const VtkXmlEncoding& encoding)
        : mPath(path), mWhat(what), mEncoding(encoding)
    {
    }

    [[noreturn]] void fail(const std::string& problem) const { failInput(mPath, mWhat + ": " + problem); }

    /// The uncompressed bytes of the blob, which must be @a expectedBytes long.
    std::string bytes(BlobReader& blob, std::size_t expectedBytes, std::size_t tupleBytes, const std::string& declared)
    {
        if (!mEncoding.zlib) {
            const std::uint64_t size = header(blob);
            checkSize(size, expectedBytes, tupleBytes, declared);
            std::string out;
            if (!blob.read(std::size_t(size), out)) fail(blob.problem());
            return out;
        }
        const std::uint64_t blocks = header(blob);
        const std::uint64_t blockSize = header(blob);
        const std::uint64_t lastSize = header(blob);
        if (blocks > blob.available() / mEncoding.headerBytes) fail("the compression header is longer than the data");
        if (blocks > 0 && blockSize == 0) fail("the compression header has a block size of 0");
        if (lastSize > blockSize || (blocks > 1 && blockSize > std::numeric_limits<std::uint64_t>::max() / blocks)) {
            fail("the compression header is corrupt");
        }
        const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * blockSize + (lastSize != 0 ? lastSize : blockSize);
        checkSize(total, expectedBytes, tupleBytes, declared);
        std::vector<std::uint64_t> compressed(blocks);
        std::uint64_t compressedTotal = 0;
        for (std::uint64_t& c : compressed) {
            c = header(blob);
            if (c > blob.available() - compressedTotal) fail("the compressed blocks run past the end of the data");
            compressedTotal += c;
        }
        std::string packed;
        if (!blob.read(std::size_t(compressedTotal), packed)) fail(blob.problem());
        std::string out(std::size_t(total), '\0');
        std::size_t in = 0;
        for (std::uint64_t b = 0; b < blocks; ++b) {
            const std::size_t want = std::size_t(b + 1 == blocks ? total - b * blockSize : blockSize);
            uLongf produced = uLongf(want);
            const int status = uncompress(reinterpret_cast<Bytef*>(out.data() + b * blockSize), &produced,
                                          reinterpret_cast<const Bytef*>(packed.data() + in), uLong(compressed[b]));
            if (status != Z_OK || produced != want) {
                fail("zlib block " + std::to_string(b) + " of " + std::to_string(blocks) + " is corrupt");
            }
            in += std::size_t(compressed[b]);
        }
        return out;
    }

private:
    /// One header word (UInt32 or UInt64, in the file's byte order).
    std::uint64_t header(BlobReader& blob)
    {
        if (!blob.read(mEncoding.headerBytes, mWord)) fail(blob.problem());
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < mEncoding.headerBytes; ++i) {
            const std::size_t k = mEncoding.bigEndian ? i : mEncoding.headerBytes - 1 - i;
            value = (value << 8) | static_cast<unsigned char>(mWord[k]);
        }
        return value;
    }

    void checkSize(std::uint64_t size, std::size_t expected, std::size_t tupleBytes, const std::string& declared) const
    {
        if (size == expected) return;
        if (size % tupleBytes != 0) {
            fail("the data holds " + std::to_string(size) + " bytes, not a whole number of " +
                 std::to_string(tupleBytes) + "-byte tuples");
        }
        fail("the data holds " + std::to_string(size / tupleBytes) + " tuples, but " + declared + " says " +
             std::to_string(expected / tupleBytes));
    }

    const std::string& mPath;
    const std::string& mWhat;
    const VtkXmlEncoding& mEncoding;
    std::string mWord;
};

/// Whitespace-separated numbers ("nan" and "inf" allowed).
std::vector<double> parseAscii(const ArrayDecoder& decoder, std::string_view text, std::size_t expected)
{
    std::vector<double> values;
    values.reserve(std::min(expected, text.size() / 2 + 1));
    const char* p = text.data();
    const char* end = p + text.size();
    while (true) {
        while (p != end && std::isspace(static_cast<unsigned char>(*p))) ++p;
        if (p == end) break;
        const char* start = p;
        while (p != end && !std::isspace(static_cast<unsigned char>(*p))) ++p;
        double v = 0.0;
        if (!parseNumber(std::string_view(start, std::size_t(p - start)), v)) {
            decoder.fail("'" + std::string(start, std::size_t(std::min<std::ptrdiff_t>(p - start, 40))) +
                         "' is not a number");
        }
        values.push_back(v);
    }
    return values;
}

std::size_t countAttribute(const ArrayDecoder& decoder, const pugi::xml_node& node, const char* name,
                           std::size_t fallback)
{
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) return fallback;
    const std::string_view text = attribute.value();
    std::size_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) {
        decoder.fail(std::string(name) + " '" + std::string(text) + "' is not a count");
    }
    return value;
}

}  // namespace

std::optional<ValueType> vtkXmlValueType(std::string_view name)
{
    for (int t = 0; t <= int(ValueType::Float64); ++t) {
        if (name == valueTypeName(ValueType(t))) return ValueType(t);
    }
    return std::nullopt;
}

DataArray readVtkXmlDataArray(const std::string& path, const std::string& what, const pugi::xml_node& node,
                              const VtkXmlEncoding& encoding, std::size_t expectedTuples, const std::string& declaredBy)
{
    ArrayDecoder decoder(path, what, encoding);
    DataArray array;
    array.name = node.attribute("Name").value();
    const std::string typeName = node.attribute("type").value();
    const std::optional<ValueType> type = vtkXmlValueType(typeName);
    if (!type) decoder.fail("type '" + typeName + "' is not a numeric type");
    array.type = *type;
    const std::size_t components = countAttribute(decoder, node, "NumberOfComponents", 1);
    if (components < 1 || components > 1024)
        decoder.fail("NumberOfComponents " + std::to_string(components) + " is out of range");
    array.components = int(components);
    const std::size_t tupleBytes = components * valueTypeSize(array.type);
    if (expectedTuples > std::numeric_limits<std::size_t>::max() / tupleBytes)
        decoder.fail(declaredBy + " is too large");

    const std::string format = node.attribute("format").as_string("ascii");
    if (format == "ascii") {
        array.values = parseAscii(decoder, node.child_value(), expectedTuples * components);
        if (array.values.size() != expectedTuples * components) {
            if (array.values.size() % components != 0) {
                decoder.fail("the data holds " + std::to_string(array.values.size()) +
                             " values, not a whole number of " + std::to_string(components) + "-component tuples");
            }
            decoder.fail("the data holds " + std::to_string(array.values.size() / components) + " tuples, but " +
                         declaredBy + " says " + std::to_string(expectedTuples));
        }
        return array;
    }
    std::string bytes;
    if (format == "binary") {
        BlobReader blob{Base64Stream(node.child_value())};
        bytes = decoder.bytes(blob, expectedTuples * tupleBytes, tupleBytes, declaredBy);
    } else if (format == "appended") {
        if (encoding.appended.data() == nullptr) decoder.fail("format is appended, but the file has no AppendedData");
        const std::size_t offset = countAttribute(decoder, node, "offset", std::size_t(-1));
        if (offset == std::size_t(-1)) decoder.fail("format is appended, but the array has no offset");
        if (offset > encoding.appended.size()) {
            decoder.fail("offset " + std::to_string(offset) + " lies past the end of the appended data (" +
                         std::to_string(encoding.appended.size()) +
                         (encoding.appendedBase64 ? " characters)" : " bytes)"));
        }
        const std::string_view start = encoding.appended.substr(offset);
        BlobReader blob = encoding.appendedBase64 ? BlobReader(Base64Stream(start)) : BlobReader(start);
        bytes = decoder.bytes(blob, expectedTuples * tupleBytes, tupleBytes, declaredBy);
    } else {
        decoder.fail("format '" + format + "' is not ascii, binary or appended");
    }
    array.values =
        valuesFromBytes(bytes.data(), bytes.size() / valueTypeSize(array.type), array.type, encoding.bigEndian);
    return array;
}

std::vector<std::int64_t> toIndices(const std::string& path, const std::string& what, const std::vector<double>& values)
{
    std::vector<std::int64_t> indices(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double v = values[i];
        if (!(v >= -9.2e18 && v <= 9.2e18) || v != std::floor(v)) {
            failInput(path, what + ": value " + shortNumber(v) + " at position " + std::to_string(i) + " is not an index");
        }
        indices[i] = std::int64_t(v);
    }
    return indices;
}

}  // namespace ivis::core::detail
