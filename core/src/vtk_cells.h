/// @file vtk_cells.h
/// @brief Turns VTK cells into the faces of a surface: polygons as they are, triangle strips as
///        triangles, the boundary faces of volume cells (tetrahedra, hexahedra, wedges, pyramids,
///        voxels); vertex and line cells are counted and left out.
/// @note Internal to the VTK readers (legacy and XML). Every failure is an InputError
///       "<path>: <problem>" naming the cell.
#pragma once

#include <ivis/core/raw_mesh.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ivis::core::detail {

/// Cells as VTK stores them: cell c has the corners connectivity[offsets[c] .. offsets[c + 1]).
struct VtkCellArray {
    std::vector<std::int64_t> connectivity;
    std::vector<std::int64_t> offsets{0};  ///< one more than the cells, starting at 0
    std::vector<std::uint8_t> types;       ///< VTK cell type of each cell (vtkCellType.h)

    /// Number of cells.
    std::size_t size() const { return offsets.size() - 1; }
};

/// @a values as VTK cell types (whole numbers 0..255).
/// @throw InputError "<path>: cell <c> has the cell type <v>, which VTK does not define"
std::vector<std::uint8_t> toCellTypes(const std::string& path, const std::vector<double>& values);

/// Collects the surface of the cells of one file, cell block after cell block.
class VtkCellSurface {
public:
    /// @param path the file, for messages
    /// @param pointCount points in the file: every corner index must be below it
    VtkCellSurface(std::string path, std::size_t pointCount);

    /// Adds @a cells as the file's cells [firstCell, firstCell + cells.size()); @a what names the
    /// block in messages ("Polys", "CELLS"). Checks the offsets, indices and cell types.
    void add(const VtkCellArray& cells, std::size_t firstCell, const std::string& what);

    /// Moves the faces into @a out (polygons and strips in cell order, then the boundary faces of
    /// the volume cells), sets its cellCount and adds notes on the cells left out.
    void finish(RawMesh& out, std::size_t cellCount);

private:
    /// One face of a volume cell: its corners (3 or 4) and the cell.
    struct CellFace {
        std::array<std::uint32_t, 4> corners;
        std::array<std::uint32_t, 4> key;  ///< corners sorted (a triangle's 4th is UINT32_MAX): shared faces match
        std::uint32_t size;
        std::uint32_t cell;
    };

    std::string mPath;
    std::size_t mPointCount;
    RawMesh mFaces;
    std::vector<CellFace> mVolumeFaces;
    std::size_t mVertexCells = 0;
    std::size_t mLineCells = 0;
    std::size_t mVolumeCells = 0;
};

}  // namespace ivis::core::detail
