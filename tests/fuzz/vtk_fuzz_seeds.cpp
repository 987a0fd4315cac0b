// Writes the seed corpora of the VTK fuzz targets: `vtk_fuzz_seeds FOLDER` fills FOLDER/vtk_xml
// with a small cube in every XML layout and two tetrahedra as UnstructuredGrid, FOLDER/vtk_legacy
// with legacy files (ASCII and binary, classic and offset cell lists, a bit array, a grid) and FOLDER/pvd with a
// collection of two steps.
#include "vtk_files.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using ivis::test::VtkXmlLayout;

void write(const fs::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

/// A unit cube of six quads with a vertex and a line cell, a point array and a cell array.
ivis::test::VtkDataSet cube()
{
    ivis::test::VtkDataSet d;
    d.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    d.verts = {{0}, {1}, {}};
    d.lines = {{0, 6}, {2}, {}};
    d.polys = {{0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7}, {4, 8, 12, 16, 20, 24}, {}};
    d.strips = {{0, 1, 3, 2}, {4}, {}};
    d.pointData = {{"p", "Float64", 1, {0, 1, 2, 3, 4, 5, 6, 7}}, {"v", "Float32", 3, d.points}};
    d.cellData = {{"c", "Int32", 1, {0, 1, 2, 3, 4, 5, 6, 7, 8}}};
    return d;
}

/// Big-endian bytes of @a values as @a type, for the binary legacy seeds.
std::string be(const std::vector<double>& values, const std::string& type)
{
    return ivis::test::vtkBytes(values, type, true) + "\n";
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: vtk_fuzz_seeds FOLDER\n";
        return 2;
    }
    const fs::path xml = fs::path(argv[1]) / "vtk_xml", legacy = fs::path(argv[1]) / "vtk_legacy",
                   pvd = fs::path(argv[1]) / "pvd";
    fs::create_directories(xml);
    fs::create_directories(legacy);
    fs::create_directories(pvd);
    write(pvd / "series.pvd",
          "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
          "<DataSet timestep=\"0.5\" part=\"0\" file=\"b.vtp\"/>\n<DataSet timestep=\"0\" file=\"a.vtp\"/>\n"
          "</Collection>\n</VTKFile>\n");

    int n = 0;
    for (int format = 0; format < 4; ++format)
        for (const bool zlib : {false, true})
            for (const bool header64 : {false, true}) {
                if (format == VtkXmlLayout::Ascii && (zlib || header64)) continue;
                VtkXmlLayout layout;
                layout.format = VtkXmlLayout::Format(format);
                layout.zlib = zlib;
                layout.header64 = header64;
                layout.bigEndian = header64;
                layout.blockSize = 40;
                write(xml / ("cube" + std::to_string(n++) + ".vtp"), ivis::test::vtpText(cube(), layout));
            }
    ivis::test::VtkDataSet tets;
    tets.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 2, 0, 0};
    tets.cells = {{0, 1, 2, 3, 1, 3, 2, 4, 1, 5, 2}, {4, 8, 11}, {10, 10, 5}};
    tets.cellData = {{"c", "Int32", 1, {0, 1, 2}}};
    write(xml / "tets.vtu", ivis::test::vtuText(tets, {}));

    const std::string points = "0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1\n";
    write(legacy / "classic.vtk",
          "# vtk DataFile Version 3.0\ncube\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n" + points +
              "POLYGONS 2 10\n4 0 3 2 1\n4 4 5 6 7\nVERTICES 1 2\n1 0\nTRIANGLE_STRIPS 1 5\n4 0 1 3 2\n"
              "POINT_DATA 8\nSCALARS p float 1\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7\nVECTORS v double\n" +
              points + "CELL_DATA 4\nFIELD f 1\nc 1 4 int\n0 1 2 3\n");
    write(legacy / "offsets.vtk",
          "# vtk DataFile Version 5.1\ncube\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n" + points +
              "POLYGONS 3 8\nOFFSETS vtktypeint64\n0 4 8\nCONNECTIVITY vtktypeint64\n0 3 2 1 4 5 6 7\n"
              "POINT_DATA 8\nNORMALS n float\n" + points + "METADATA\nINFORMATION 0\n\n");
    write(legacy / "binary.vtk",
          "# vtk DataFile Version 5.1\ncube\nBINARY\nDATASET POLYDATA\nPOINTS 8 float\n" +
              be({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1}, "Float32") +
              "POLYGONS 3 8\nOFFSETS vtktypeint64\n" + be({0, 4, 8}, "Int64") + "CONNECTIVITY vtktypeint64\n" +
              be({0, 3, 2, 1, 4, 5, 6, 7}, "Int64") + "CELL_DATA 2\nSCALARS c int\nLOOKUP_TABLE default\n" +
              be({5, 6}, "Int32") + "SCALARS flags bit 3\nLOOKUP_TABLE default\n\xb4");
    write(legacy / "grid.vtk",
          "# vtk DataFile Version 3.0\ntets\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 float\n"
          "0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\nCELLS 3 14\n4 0 1 2 3\n4 1 3 2 4\n3 1 2 4\nCELL_TYPES 3\n10\n10\n5\n"
          "CELL_DATA 3\nTENSORS t float\n1 0 0 0 1 0 0 0 1\n1 0 0 0 1 0 0 0 1\n1 0 0 0 1 0 0 0 1\n");
    return 0;
}
