// `inversevis-bench read`: reading a large mesh from a zlib-compressed binary .vtp (inline base64
// as VMTK writes it, and appended raw as ParaView writes it) against the same mesh and point
// array as binary PLY. The mesh is a shared mesh subdivided at edge midpoints until it is large;
// each read runs in its own forked child, the best of --repeat runs counts.
#include "benchmarks.h"
#include "child_measurement.h"
#include "vtk_files.h"

#include <ivis/core/mesh_reader.h>
#include <ivis/core/surface_source.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <unistd.h>
#include <unordered_map>

namespace ivis::bench {
namespace {

/// Splits every triangle into four at its edge midpoints (shared edges share their midpoint).
core::TriangleMesh subdivide(const core::TriangleMesh& mesh)
{
    core::TriangleMesh out;
    out.positions = mesh.positions;
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const std::uint64_t key = std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
        const auto [it, added] = midpoints.emplace(key, std::uint32_t(out.positions.size()));
        if (added) out.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
        return it->second;
    };
    for (const auto& t : mesh.triangles) {
        const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
        out.triangles.push_back({t[0], ab, ca});
        out.triangles.push_back({ab, t[1], bc});
        out.triangles.push_back({ca, bc, t[2]});
        out.triangles.push_back({ab, bc, ca});
    }
    out.dataTriangleCount = out.triangles.size();
    return out;
}

/// Binary little-endian PLY: float x y z height, faces as "list uchar int vertex_indices".
std::string plyBytes(const core::TriangleMesh& mesh, const std::vector<float>& height)
{
    std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(mesh.positions.size()) +
                      "\nproperty float x\nproperty float y\nproperty float z\nproperty float height\nelement face " +
                      std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    const auto put = [&out](const auto& value) { out.append(reinterpret_cast<const char*>(&value), sizeof value); };
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        put(mesh.positions[v]);
        put(height[v]);
    }
    for (const auto& t : mesh.triangles) {
        put(std::uint8_t(3));
        for (const std::uint32_t c : t) put(std::int32_t(c));
    }
    return out;
}

/// The same mesh and array as VTK XML PolyData, Float32 points, Int64 connectivity (VTK's own).
test::VtkDataSet vtkDataSet(const core::TriangleMesh& mesh, const std::vector<float>& height)
{
    test::VtkDataSet d;
    for (const glm::vec3& p : mesh.positions) d.points.insert(d.points.end(), {p.x, p.y, p.z});
    for (const auto& t : mesh.triangles) {
        d.polys.connectivity.insert(d.polys.connectivity.end(), t.begin(), t.end());
        d.polys.offsets.push_back(std::int64_t(d.polys.connectivity.size()));
    }
    d.pointData = {{"height", "Float32", 1, std::vector<double>(height.begin(), height.end())}};
    return d;
}

void writeBytes(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    if (!out.write(bytes.data(), std::streamsize(bytes.size()))) throw std::runtime_error(path + ": cannot write");
}

/// Best wall time of @a repeat reads of @a path, each in its own child; checks the triangles read.
Measurement bestRead(const std::string& path, std::size_t triangles, int repeat)
{
    Measurement best;
    for (int r = 0; r < repeat; ++r) {
        const Measurement m = measureInChild("reading " + path, [&] {
            return double(core::readMesh(path, {"height", ""}).mesh.triangles.size());
        });
        if (std::size_t(m.value) != triangles) throw std::runtime_error(path + ": read a different mesh");
        if (r == 0 || m.seconds < best.seconds) best = m;
    }
    return best;
}

}  // namespace

Benchmark addReadBenchmark(CLI::App& app)
{
    struct Options {
        std::string mesh = "../shared/meshes/neptune_30k.ply";
        int subdivisions = 3;
        int repeat = 3;
        std::string folder = std::filesystem::temp_directory_path().string();
        bool json = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("read", "Compressed binary .vtp vs binary PLY reading of one large mesh");
    command->add_option("mesh", options->mesh, "Mesh to subdivide")->capture_default_str();
    command->add_option("--subdivide", options->subdivisions, "Midpoint subdivisions (x4 triangles each)")
        ->check(CLI::Range(0, 5))
        ->capture_default_str();
    command->add_option("--repeat", options->repeat, "Reads per file; the best counts")
        ->check(CLI::Range(1, 20))
        ->capture_default_str();
    command->add_option("--dir", options->folder, "Folder for the temporary files")->capture_default_str();
    command->add_flag("--json", options->json, "Print one JSON object");

    return {command, [options] {
        core::TriangleMesh mesh = core::readMesh(options->mesh).mesh;
        for (int s = 0; s < options->subdivisions; ++s) mesh = subdivide(mesh);
        std::vector<float> height;
        for (const glm::vec3& p : mesh.positions) height.push_back(p.y);

        const std::filesystem::path folder(options->folder);
        const std::string stem = "inversevis-bench-read-" + std::to_string(::getpid());
        const std::string ply = (folder / (stem + ".ply")).string();
        const std::string inlineVtp = (folder / (stem + "-inline.vtp")).string();
        const std::string appendedVtp = (folder / (stem + "-appended.vtp")).string();
        test::VtkXmlLayout inlineLayout, appendedLayout;
        inlineLayout.zlib = appendedLayout.zlib = true;
        appendedLayout.format = test::VtkXmlLayout::AppendedRaw;
        const test::VtkDataSet data = vtkDataSet(mesh, height);
        writeBytes(ply, plyBytes(mesh, height));
        writeBytes(inlineVtp, test::vtpText(data, inlineLayout));
        writeBytes(appendedVtp, test::vtpText(data, appendedLayout));

        nlohmann::json out = {{"mesh", options->mesh},
                              {"subdivisions", options->subdivisions},
                              {"vertices", mesh.positions.size()},
                              {"triangles", mesh.triangles.size()}};
        try {
            const Measurement p = bestRead(ply, mesh.triangles.size(), options->repeat);
            const Measurement i = bestRead(inlineVtp, mesh.triangles.size(), options->repeat);
            const Measurement a = bestRead(appendedVtp, mesh.triangles.size(), options->repeat);
            out.update({{"ply_seconds", p.seconds},
                        {"vtp_inline_seconds", i.seconds},
                        {"vtp_appended_seconds", a.seconds},
                        {"ratio_inline", i.seconds / p.seconds},
                        {"ratio_appended", a.seconds / p.seconds},
                        {"ply_bytes", std::filesystem::file_size(ply)},
                        {"vtp_inline_bytes", std::filesystem::file_size(inlineVtp)},
                        {"vtp_appended_bytes", std::filesystem::file_size(appendedVtp)},
                        {"ply_peak_rss_bytes", p.peakRssBytes},
                        {"vtp_inline_peak_rss_bytes", i.peakRssBytes}});
        } catch (...) {
            for (const std::string& path : {ply, inlineVtp, appendedVtp}) std::filesystem::remove(path);
            throw;
        }
        for (const std::string& path : {ply, inlineVtp, appendedVtp}) std::filesystem::remove(path);
        if (options->json) {
            std::cout << out.dump() << "\n";
            return;
        }
        std::cout << out.at("triangles") << " triangles: PLY " << out.at("ply_seconds") << " s, .vtp inline "
                  << out.at("vtp_inline_seconds") << " s (ratio " << out.at("ratio_inline") << "), .vtp appended "
                  << out.at("vtp_appended_seconds") << " s (ratio " << out.at("ratio_appended") << ")\n";
    }};
}

}  // namespace ivis::bench
