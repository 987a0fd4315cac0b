#include "vtk_cells.h"

#include <ivis/core/errors.h>
#include <ivis/core/mesh_layout_check.h>
#include <ivis/core/number_text.h>

#include <algorithm>
#include <numeric>

namespace ivis::core::detail {
namespace {

// vtkCellType.h
enum VtkCellType : int {
    kEmptyCell = 0,
    kVertex = 1,
    kPolyVertex = 2,
    kLine = 3,
    kPolyLine = 4,
    kTriangle = 5,
    kTriangleStrip = 6,
    kPolygon = 7,
    kPixel = 8,
    kQuad = 9,
    kTetra = 10,
    kVoxel = 11,
    kHexahedron = 12,
    kWedge = 13,
    kPyramid = 14,
};

/// Corner lists of the faces of a volume cell, each seen from outside counter-clockwise (as
/// vtkTetra, vtkVoxel, vtkHexahedron, vtkWedge and vtkPyramid list them).
using FaceTable = std::vector<std::vector<int>>;
const FaceTable kTetraFaces = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 1}};
const FaceTable kVoxelFaces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
const FaceTable kHexahedronFaces = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
const FaceTable kWedgeFaces = {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
const FaceTable kPyramidFaces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

/// Faces of volume cell @a type, or nullptr when it is not one we take the boundary of.
const FaceTable* volumeFaces(int type)
{
    switch (type) {
    case kTetra: return &kTetraFaces;
    case kVoxel: return &kVoxelFaces;
    case kHexahedron: return &kHexahedronFaces;
    case kWedge: return &kWedgeFaces;
    case kPyramid: return &kPyramidFaces;
    default: return nullptr;
    }
}

/// Corners a cell of @a type must have; 0 when any number is allowed.
std::size_t fixedCornerCount(int type)
{
    switch (type) {
    case kVertex: return 1;
    case kLine: return 2;
    case kTriangle: return 3;
    case kPixel:
    case kQuad:
    case kTetra: return 4;
    case kPyramid: return 5;
    case kWedge: return 6;
    case kVoxel:
    case kHexahedron: return 8;
    default: return 0;
    }
}

/// VTK's name of cell type @a type and its number ("VTK_HEXAHEDRON (12)"), or the number alone.
std::string cellTypeName(int type)
{
    static const char* const kNames[] = {"VTK_EMPTY_CELL",
                                         "VTK_VERTEX",
                                         "VTK_POLY_VERTEX",
                                         "VTK_LINE",
                                         "VTK_POLY_LINE",
                                         "VTK_TRIANGLE",
                                         "VTK_TRIANGLE_STRIP",
                                         "VTK_POLYGON",
                                         "VTK_PIXEL",
                                         "VTK_QUAD",
                                         "VTK_TETRA",
                                         "VTK_VOXEL",
                                         "VTK_HEXAHEDRON",
                                         "VTK_WEDGE",
                                         "VTK_PYRAMID",
                                         "VTK_PENTAGONAL_PRISM",
                                         "VTK_HEXAGONAL_PRISM",
                                         nullptr,
                                         nullptr,
                                         nullptr,
                                         nullptr,
                                         "VTK_QUADRATIC_EDGE",
                                         "VTK_QUADRATIC_TRIANGLE",
                                         "VTK_QUADRATIC_QUAD",
                                         "VTK_QUADRATIC_TETRA",
                                         "VTK_QUADRATIC_HEXAHEDRON",
                                         "VTK_QUADRATIC_WEDGE",
                                         "VTK_QUADRATIC_PYRAMID",
                                         "VTK_BIQUADRATIC_QUAD",
                                         "VTK_TRIQUADRATIC_HEXAHEDRON",
                                         "VTK_QUADRATIC_LINEAR_QUAD",
                                         "VTK_QUADRATIC_LINEAR_WEDGE",
                                         "VTK_BIQUADRATIC_QUADRATIC_WEDGE",
                                         "VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON",
                                         "VTK_BIQUADRATIC_TRIANGLE",
                                         "VTK_CUBIC_LINE",
                                         "VTK_QUADRATIC_POLYGON",
                                         nullptr,
                                         nullptr,
                                         nullptr,
                                         nullptr,
                                         "VTK_CONVEX_POINT_SET",
                                         "VTK_POLYHEDRON"};
    const int count = int(sizeof(kNames) / sizeof(kNames[0]));
    if (type >= 0 && type < count && kNames[type] != nullptr)
        return std::string(kNames[type]) + " (" + std::to_string(type) + ")";
    return std::to_string(type);
}

bool isLeftOut(int type)
{
    return type == kEmptyCell || type == kVertex || type == kPolyVertex || type == kLine || type == kPolyLine;
}

}  // namespace

std::vector<std::uint8_t> toCellTypes(const std::string& path, const std::vector<double>& values)
{
    std::vector<std::uint8_t> types(values.size());
    for (std::size_t c = 0; c < values.size(); ++c) {
        const double t = values[c];
        if (!(t >= 0.0 && t <= 255.0) || t != double(int(t))) {
            failInput(path, "cell " + std::to_string(c) + " has the cell type " + shortNumber(t) +
                                ", which VTK does not define");
        }
        types[c] = std::uint8_t(t);
    }
    return types;
}

VtkCellSurface::VtkCellSurface(std::string path, std::size_t pointCount)
    : mPath(std::move(path)), mPointCount(pointCount)
{
}

void VtkCellSurface::add(const VtkCellArray& cells, std::size_t firstCell, const std::string& what)
{
    IVIS_CHECK(cells.types.size() == cells.size());
    const auto where = [&](std::size_t c) { return "cell " + std::to_string(firstCell + c); };
    if (cells.offsets.front() != 0) failInput(mPath, what + ": the offsets do not start at 0");
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells.offsets[c + 1] < cells.offsets[c]) failInput(mPath, what + ": the offsets decrease at " + where(c));
    }
    if (std::uint64_t(cells.offsets.back()) != cells.connectivity.size()) {
        failInput(mPath, what + ": the offsets end at " + std::to_string(cells.offsets.back()) +
                             " but the connectivity has " + std::to_string(cells.connectivity.size()) + " values");
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const std::int64_t* begin = cells.connectivity.data() + cells.offsets[c];
        const std::int64_t* end = cells.connectivity.data() + cells.offsets[c + 1];
        for (const std::int64_t* v = begin; v != end; ++v) {
            if (*v < 0 || std::uint64_t(*v) >= mPointCount) {
                failInput(mPath, where(c) + " references point " + std::to_string(*v) + ", but the file has " +
                                     std::to_string(mPointCount) + " points");
            }
        }
        const int type = cells.types[c];
        const std::size_t size = std::size_t(end - begin);
        const std::size_t fixed = fixedCornerCount(type);
        if (fixed != 0 && size != fixed) {
            failInput(mPath, where(c) + " (" + cellTypeName(type) + ") has " + std::to_string(size) +
                                 " points, expected " + std::to_string(fixed));
        }
        const auto cell = std::uint32_t(firstCell + c);
        if (isLeftOut(type)) {
            ++(type == kEmptyCell || type == kVertex || type == kPolyVertex ? mVertexCells : mLineCells);
        } else if (type == kTriangle || type == kPolygon || type == kQuad) {
            mFaces.addFace(begin, end, cell);
        } else if (type == kPixel) {
            const std::int64_t quad[4] = {begin[0], begin[1], begin[3], begin[2]};
            mFaces.addFace(quad, quad + 4, cell);
        } else if (type == kTriangleStrip) {
            for (std::size_t i = 0; i + 2 < size; ++i) {
                const std::int64_t t[3] = {begin[i + (i & 1)], begin[i + 1 - (i & 1)], begin[i + 2]};
                mFaces.addFace(t, t + 3, cell);
            }
        } else if (const FaceTable* faces = volumeFaces(type)) {
            ++mVolumeCells;
            for (const auto& face : *faces) {
                CellFace f{{}, {}, std::uint32_t(face.size()), cell};
                std::size_t k = 0;
                for (const int corner : face) f.corners[k++] = std::uint32_t(begin[corner]);
                f.key = f.corners;
                if (f.size == 3) f.key[3] = UINT32_MAX;  // no point has this index
                std::sort(f.key.begin(), f.key.end());
                mVolumeFaces.push_back(f);
            }
        } else {
            failInput(mPath, where(c) + " has type " + cellTypeName(type) +
                                 ", which is not read (surface cells, triangle strips and linear volume cells are)");
        }
    }
}

void VtkCellSurface::finish(RawMesh& out, std::size_t cellCount)
{
    // A face of the boundary belongs to exactly one volume cell.
    std::vector<std::size_t> order(mVolumeFaces.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return mVolumeFaces[a].key < mVolumeFaces[b].key; });
    std::vector<bool> boundary(mVolumeFaces.size(), false);
    const auto same = [&](std::size_t a, std::size_t b) { return mVolumeFaces[a].key == mVolumeFaces[b].key; };
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i + 1;
        while (j < order.size() && same(order[i], order[j])) ++j;
        if (j == i + 1) boundary[order[i]] = true;
        i = j;
    }
    std::size_t boundaryFaces = 0;
    for (std::size_t f = 0; f < mVolumeFaces.size(); ++f) {
        if (!boundary[f]) continue;
        const CellFace& face = mVolumeFaces[f];
        mFaces.addFace(face.corners.begin(), face.corners.begin() + face.size, face.cell);
        ++boundaryFaces;
    }

    out.corners = std::move(mFaces.corners);
    out.faceEnds = std::move(mFaces.faceEnds);
    out.faceCells = std::move(mFaces.faceCells);
    out.cellCount = cellCount;
    if (mVolumeCells > 0) {
        out.notes.push_back("showing the boundary of " + std::to_string(mVolumeCells) + " volume cells (" +
                            std::to_string(boundaryFaces) + " faces)");
    }
    const auto count = [](std::size_t n, const char* what) {
        return n == 0 ? std::string() : std::to_string(n) + " " + what + " cell" + (n == 1 ? "" : "s");
    };
    const std::string vertices = count(mVertexCells, "vertex"), lines = count(mLineCells, "line");
    if (!vertices.empty() || !lines.empty()) {
        out.notes.push_back("left out " + vertices + (vertices.empty() || lines.empty() ? "" : " and ") + lines +
                            ": only surfaces are shown");
    }
}

}  // namespace ivis::core::detail
