/// @file image_io.h
/// @brief Writes images as 8-bit sRGB PNG or multi-layer OpenEXR; reads them back for tests.
/// @note Writers go through writeAtomically (atomic_file.h): a temporary "<path>.tmp.<pid>.<n>" in
///       the same folder, renamed onto @a path, so a reader never sees a half-written file; on
///       failure the temporary is removed and an existing file at @a path is left untouched.
#pragma once

#include <ivis/core/image.h>
#include <ivis/core/similarity.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ivis::core {

/// @brief Writes @a image as an 8-bit PNG, encoded with the sRGB transfer function (sRGB chunk set).
/// @param transparentBackground true: RGBA with straight (un-premultiplied) colour and alpha;
///        false: RGB as stored, i.e. composited over black where alpha < 1
/// @throw ValueError for an empty image; InputError "<path>: cannot write (<reason>)" on any I/O
///        failure (missing folder, no permission, disk full)
void writePng(const Image& image, const std::string& path, bool transparentBackground);

/// @brief The bytes of writePng's file, in memory (a notebook shows them).
/// @throw ValueError for an empty image
std::vector<std::uint8_t> encodePng(const Image& image, bool transparentBackground);

/// @brief The 8-bit sRGB-encoded pixels writePng writes, row-major from the top row: RGBA with
///        straight alpha when @a transparentBackground, else RGB.
std::vector<std::uint8_t> srgbPixels(const Image& image, bool transparentBackground);

/// @brief Reads any PNG as 8-bit sRGB RGBA (libpng converts other layouts) into a linear,
///        premultiplied Image.
/// @throw InputError "<path>: cannot read (<reason>)"
Image readPng(const std::string& path);

/// @brief Writes a single-part scanline OpenEXR, ZIP-compressed: R, G, B, A as HALF (linear,
///        premultiplied) plus every channel of @a layers as FLOAT under its own name ("P.X" is
///        channel X of layer P), and the mesh's normalising transform @a meshUnits as header
///        attributes "ivis:meshCenter" (v3d) and "ivis:meshScale" (double): a position layer's
///        point P is P / meshScale + meshCenter in the mesh's own units.
/// @throw ValueError for an empty image or layers of another size; InputError
///        "<path>: cannot write (<reason>)" on any I/O failure
void writeExr(const Image& image, const ImageLayers& layers, const std::string& path, const Similarity& meshUnits = {});

/// @brief The normalising transform an EXR written by writeExr carries (identity when it has none).
/// @throw InputError "<path>: cannot read (<reason>)"
Similarity readExrMeshUnits(const std::string& path);

/// @brief Reads channel @a name of an EXR file as floats, row-major from the top row.
/// @throw InputError "<path>: cannot read (<reason>)", or when the channel is missing (the
///        message lists the channels present)
std::vector<float> readExrChannel(const std::string& path, const std::string& name);

}  // namespace ivis::core
