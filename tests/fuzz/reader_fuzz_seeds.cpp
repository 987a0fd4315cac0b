// Writes the seed corpora of the mesh, scalar-file and volume-cache fuzz targets:
// `reader_fuzz_seeds FOLDER` fills FOLDER/obj, off, ply, stl (a tetrahedron in each format's ASCII
// and, where it has one, binary layout; a PLY with vertex and face properties), FOLDER/scalar_file
// (four values, nan included), FOLDER/volume_cache (the volume of a small icosphere) and
// FOLDER/camera_json (a camera file with every key), FOLDER/view_file (a view file) and
// FOLDER/evaluation_json (an evaluate --json file with every table's fields), FOLDER/png and
// FOLDER/exr (a small picture and its layers).
#include <ivis/core/image_io.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/vdb/volume_cache.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& bytes)
{
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

template <typename T>
void append(std::string& bytes, T value)
{
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.append(raw, sizeof(T));
}

constexpr float kTetra[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
constexpr int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::string binaryStl()
{
    std::string bytes(80, ' ');
    append<std::uint32_t>(bytes, 4);
    for (const auto& f : kFaces) {
        for (int k = 0; k < 3; ++k) append<float>(bytes, 0.0f);  // normal
        for (const int v : f)
            for (const float c : kTetra[v]) append<float>(bytes, c);
        append<std::uint16_t>(bytes, 0);
    }
    return bytes;
}

std::string plyHeader(const char* format)
{
    return std::string("ply\nformat ") + format +
           " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty float pressure\n"
           "element face 4\nproperty list uchar int vertex_indices\nproperty float wss\nend_header\n";
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: reader_fuzz_seeds FOLDER\n";
        return 2;
    }
    const fs::path root(argv[1]);
    std::string obj = "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvt 0 0\n";
    std::string off = "OFF\n4 4 6\n";
    std::string asciiStl = "solid t\n";
    std::string asciiPly = plyHeader("ascii"), binaryPly = plyHeader("binary_little_endian");
    for (int v = 0; v < 4; ++v) {
        const std::string xyz = std::to_string(kTetra[v][0]) + " " + std::to_string(kTetra[v][1]) + " " +
                                std::to_string(kTetra[v][2]);
        off += xyz + "\n";
        asciiPly += xyz + " " + std::to_string(v * 0.5) + "\n";
        for (const float c : kTetra[v]) append<float>(binaryPly, c);
        append<float>(binaryPly, float(v) * 0.5f);
    }
    for (const auto& f : kFaces) {
        obj += "f " + std::to_string(f[0] + 1) + "//1 " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
        off += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
        asciiPly += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " 1.5\n";
        append<std::uint8_t>(binaryPly, 3);
        for (const int v : f) append<std::int32_t>(binaryPly, v);
        append<float>(binaryPly, 1.5f);
        asciiStl += "facet normal 0 0 0\nouter loop\n";
        for (const int v : f)
            asciiStl += "vertex " + std::to_string(kTetra[v][0]) + " " + std::to_string(kTetra[v][1]) + " " +
                        std::to_string(kTetra[v][2]) + "\n";
        asciiStl += "endloop\nendfacet\n";
    }
    asciiStl += "endsolid t\n";
    write(root / "obj" / "tetra.obj", obj);
    write(root / "obj" / "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf -1 -2 -3\n");
    write(root / "off" / "tetra.off", off);
    write(root / "ply" / "ascii.ply", asciiPly);
    write(root / "ply" / "binary.ply", binaryPly);
    std::string doublePly = "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\n"
                            "property double y\nproperty double z\nelement face 4\n"
                            "property list uchar int vertex_indices\nend_header\n";  // read in double
    const auto bigEndian = [&](auto value) {
        std::string bytes;
        append(bytes, value);
        doublePly.append(bytes.rbegin(), bytes.rend());
    };
    for (const auto& v : kTetra)
        for (const float c : v) bigEndian(double(c) + 1e9);
    for (const auto& f : kFaces) {
        bigEndian(std::uint8_t(3));
        for (const int v : f) bigEndian(std::int32_t(v));
    }
    write(root / "ply" / "double.ply", doublePly);
    write(root / "ply" / "bytes.ply",  // 8-bit properties in ASCII, which OpenMesh is given as 16-bit
          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
          "property uchar flag\nelement face 1\nproperty list uchar int vertex_indices\nproperty char tag\n"
          "end_header\n0 0 0 200\n1 0 0 7\n0 1 0 255\n3 0 1 2 -5\n");
    write(root / "stl" / "ascii.stl", asciiStl);
    write(root / "stl" / "binary.stl", binaryStl());
    write(root / "scalar_file" / "values.txt", "0.5 1e3\n-2\tnan\n");
    write(root / "camera_json" / "camera.json",
          "{\"eye\": [0, 1.25, 2.165], \"target\": [0, 0, 0], \"up\": [0, 1, 0], \"fov_y_deg\": 60, "
          "\"orthographic\": false, \"ortho_half_height\": 1, \"window_centre\": [0.1, -0.2]}");
    write(root / "view_file" / "wrap.view.json",
          R"({"camera":{"eye":[0,1.25,2.165],"fov_y_deg":49.3,"ortho_half_height":1.6,"orthographic":false,)"
          R"("target":[0,0,0],"up":[0,1,0],"window_centre":[0,0]},"colormap":"viridis","hotspots":2,)"
          R"("inversevis_view":1,"legend":"right","method":{"method":"inversevis-wrap","wrap_speed":2.5,)"
          R"("stable_shift":0.1},"outline":true,"scalar":"","scalar_file":"","scale":{"invert":false,"log":false,)"
          R"("range":[0.0,1.0]},"shade_indirect":true,"shadows":true,"size":[32,32],"units":"mm"})");
    write(root / "evaluation_json" / "evaluation.json",
          R"({"sphere":{"front":{"coherence":1.0,"display_res":32,"front_visibility":0.3,"paper_literal":0.2,)"
          R"("reveal":{"direct":0.5,"per_region":[0.0,1.0],"shapes":[{"largest_share":0.9,"outline_ratio":1.3}],)"
          R"("total":0.5},"seconds":{"16":0.1},"settings":{"--opt-res":[16],"mesh hash":"0123456789abcdef"},)"
          R"("visibility":0.3,"voxel_visibility":0.28},"inversevis-wrap":{"coherence":0.99,"front_visibility":0.4,)"
          R"("paper_literal":0.6,"reveal":null,"seconds":{"16":2.5,"100":3.0},"several_views":{"union":)"
          R"({"visibility":0.99},"views":[{"coherence":0.99,"visibility":0.95}]},"visibility":0.95,)"
          R"("voxel_visibility":0.9}}})");
    ivis::core::Image picture(4, 3, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
    picture.at(1, 1) = glm::vec4(0.0f);
    fs::create_directories(root / "png");
    fs::create_directories(root / "exr");
    ivis::core::writePng(picture, (root / "png" / "picture.png").string(), true);
    ivis::core::ImageLayers layers(4, 3);
    layers.add("region");
    ivis::core::writeExr(picture, layers, (root / "exr" / "picture.exr").string(), {{1.0, 2.0, 3.0}, 0.5});
    ivis::vdb::VolumeOptions options;
    options.resolution = 16;
    ivis::vdb::writeVolume(ivis::vdb::buildSurfaceVolume(ivis::core::makeSphere(1).mesh, options),
                           (root / "volume_cache" / "sphere.vdb").string());
    return 0;
}
