/// @file mesh_reader_files.h
/// @brief Mesh files the reader tests write (PLY headers, a tetrahedron, a cube) and their checks
///        of the reader's one-line errors: what the mesh and VTK reader tests share.
#pragma once

#include <ivis/core/errors.h>
#include <ivis/core/mesh_reader.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <string>

namespace ivis::core {

using test::TempDir;
using test::writeFile;

/// The InputError message @a read throws, or a marker when it throws nothing or something else.
inline std::string inputError(const std::function<void()>& read)
{
    try {
        read();
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("<not an InputError: ") + e.what() + ">";
    }
    return "<no error>";
}

/// The problem readMesh reports for a file @a name in @a dir holding @a text: its error after
/// "<path>: " (expected to be one line starting so), or inputError's marker.
inline std::string readProblem(const TempDir& dir, const std::string& text, const std::string& name)
{
    const std::string path = dir.file(name);
    writeFile(path, text);
    const std::string message = inputError([&] { readMesh(path); });
    if (message.rfind("<", 0) == 0) return message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    if (message.rfind(path + ": ", 0) != 0) {
        ADD_FAILURE() << "the error does not start with the file: " << message;
        return message;
    }
    return message.substr(path.size() + 2);
}

/// Expects readMesh(@a path) to fail with one line "<path>: ...@a problem...".
inline void expectReadError(const std::string& path, const std::string& problem, const MeshReadOptions& options = {})
{
    const std::string message = inputError([&] { readMesh(path, options); });
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

/// Little- or big-endian bytes of binary PLY data.
class Bytes {
public:
    explicit Bytes(bool bigEndian = false) : mBigEndian(bigEndian) {}
    template <typename T>
    Bytes& put(T value)
    {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        if (mBigEndian) std::reverse(raw, raw + sizeof(T));
        mData.append(raw, sizeof(T));
        return *this;
    }
    /// Appends bytes as they are.
    Bytes& raw(const std::string& bytes)
    {
        mData += bytes;
        return *this;
    }
    /// A triangle as "list uchar int vertex_indices".
    Bytes& triangle(int a, int b, int c) { return put<std::uint8_t>(3).put(a).put(b).put(c); }
    const std::string& str() const { return mData; }

private:
    bool mBigEndian;
    std::string mData;
};

/// PLY header for @a vertices float x y z and @a faces "list uchar int vertex_indices".
inline std::string xyzPlyHeader(int vertices, int faces, const std::string& format = "ascii")
{
    return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

/// Header of a tetrahedron PLY with vertex x y z, float wss, double pressure; 4 triangles.
inline std::string tetraPlyHeader(const std::string& format)
{
    return "ply\nformat " + format +
           " 1.0\ncomment tetrahedron\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nproperty float wss\nproperty double pressure\nelement face 4\n"
           "property list uchar int vertex_indices\nend_header\n";
}

/// Tetrahedron: 0 origin, 1 on x, 2 on y, 3 on z (outward faces 0-2-1, 0-1-3, 0-3-2, 1-2-3).
const float kTetraXyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const int kTetraFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
const float kWss[4] = {0.5f, 1.25f, -3.0f, 1e-3f};
const double kPressure[4] = {101325.123456789, -0.000123456789, 7.0, 1e-300};

/// Byte offset of @a byte within vertex @a v of binaryTetraPly(false) (24 bytes per vertex).
inline std::size_t tetraVertexByte(int v, int byte)
{
    return tetraPlyHeader("binary_little_endian").size() + std::size_t(24 * v + byte);
}

inline std::string binaryTetraPly(bool bigEndian)
{
    Bytes body(bigEndian);
    for (int v = 0; v < 4; ++v) {
        body.put(kTetraXyz[v][0]).put(kTetraXyz[v][1]).put(kTetraXyz[v][2]).put(kWss[v]).put(kPressure[v]);
    }
    for (const auto& f : kTetraFaces) body.triangle(f[0], f[1], f[2]);
    return tetraPlyHeader(bigEndian ? "binary_big_endian" : "binary_little_endian") + body.str();
}

inline std::string asciiTetraPly()
{
    std::string text = tetraPlyHeader("ascii");
    char line[160];
    for (int v = 0; v < 4; ++v) {
        std::snprintf(line, sizeof line, "%g %g %g %.9g %.17g\n", kTetraXyz[v][0], kTetraXyz[v][1],
                      kTetraXyz[v][2], double(kWss[v]), kPressure[v]);
        text += line;
    }
    for (const auto& f : kTetraFaces) {
        text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    }
    return text;
}

/// Unit cube as an OBJ with six quads (1-based):
///     8 ---- 7        bottom 1 2 3 4 (z = 0), top 5 6 7 8 (z = 1)
///    /|     /|
///   5 ---- 6 |
///   | 4 ---|-3
///   |/     |/
///   1 ---- 2
inline const char* const kCubeObj =
    "# cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

inline std::string sharedMeshPath(const std::string& name)
{
    try {
        return test::sharedMesh(name);
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        return {};
    }
}

}  // namespace ivis::core
