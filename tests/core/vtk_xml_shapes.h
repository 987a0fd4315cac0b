/// @file vtk_xml_shapes.h
/// @brief The data sets and layouts the VTK XML reader tests write: a cube with vertex, line and
///        quad cells, every binary layout, two tetrahedra and a triangle.
#pragma once

#include "vtk_files.h"

#include <string>
#include <vector>

namespace ivis::core {

using test::VtkDataSet;
using test::VtkXmlLayout;

/// Unit cube with a vertex cell and a line cell before its six quads:
///       7 ------ 6         points 0..3 at z = 0, 4..7 at z = 1
///      /|       /|         cell 0: vertex {0}; cell 1: line {0, 6}
///     4 ------ 5 |         cells 2..7: quads 0-3-2-1, 4-5-6-7, 0-1-5-4, 1-2-6-5, 2-3-7-6, 3-0-4-7
///     | 3 -----|-2         point arrays: "typed" (0..7, of the type under test), "velocity" (x, y, z)
///     |/       |/          cell array: "cell_id" (0..7, Int32)
///     0 ------ 1
inline VtkDataSet cube(const std::string& typedType = "Float64")
{
    VtkDataSet d;
    d.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    d.verts = {{0}, {1}, {}};
    d.lines = {{0, 6}, {2}, {}};
    d.polys = {{0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7}, {4, 8, 12, 16, 20, 24}, {}};
    d.pointData = {{"typed", typedType, 1, {0, 1, 2, 3, 4, 5, 6, 7}}, {"velocity", "Float32", 3, d.points}};
    d.cellData = {{"cell_id", "Int32", 1, {0, 1, 2, 3, 4, 5, 6, 7}}};
    return d;
}

inline std::string describe(const VtkXmlLayout& l)
{
    static const char* const kFormats[] = {"ascii", "binary", "appended raw", "appended base64"};
    return std::string(kFormats[l.format]) + (l.zlib ? " zlib/" + std::to_string(l.blockSize) : "") +
           (l.header64 ? " UInt64" : " UInt32") + (l.bigEndian ? " big-endian" : "") +
           (l.oneBase64Run ? " one base64 run" : "");
}

/// Every layout: 4 formats x zlib (blocks of 20 bytes: a partial last block; of 32: none) x
/// header width x byte order x one or two base64 runs.
inline std::vector<VtkXmlLayout> everyLayout()
{
    std::vector<VtkXmlLayout> layouts;
    for (int format = 0; format < 4; ++format)
        for (int zlib = 0; zlib < 3; ++zlib)
            for (bool header64 : {false, true})
                for (bool bigEndian : {false, true})
                    for (bool oneRun : {false, true}) {
                        if (format == VtkXmlLayout::Ascii && (zlib > 0 || header64 || bigEndian || oneRun)) continue;
                        if (format == VtkXmlLayout::AppendedRaw && oneRun) continue;
                        VtkXmlLayout l;
                        l.format = VtkXmlLayout::Format(format);
                        l.zlib = zlib > 0;
                        l.blockSize = zlib == 1 ? 20 : 32;
                        l.header64 = header64;
                        l.bigEndian = bigEndian;
                        l.oneBase64Run = oneRun;
                        layouts.push_back(l);
                    }
    return layouts;
}

/// Two tetrahedra sharing the face 1-2-3, and a triangle cell beside them:
///   points 0 (0,0,0) 1 (1,0,0) 2 (0,1,0) 3 (0,0,1) 4 (1,1,1) 5 (2,0,0)
///   cell 0: tetra 0 1 2 3; cell 1: tetra 1 2 3 4 (the mirror through 1-2-3); cell 2: triangle 1 5 2
inline VtkDataSet twoTetrahedra()
{
    VtkDataSet d;
    d.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 2, 0, 0};
    d.cells = {{0, 1, 2, 3, 1, 3, 2, 4, 1, 5, 2}, {4, 8, 11}, {10, 10, 5}};
    d.cellData = {{"cell", "Int32", 1, {0, 1, 2}}};
    return d;
}

}  // namespace ivis::core
