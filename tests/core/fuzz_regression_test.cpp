// Every input a fuzz target found a problem with (tests/fuzz/regressions/<reader>/) is read again
// by its reader: it must return or throw one single-line InputError, never crash or abort.
#include "app/evaluation_report.h"

#include <ivis/core/camera.h>
#include <ivis/core/errors.h>
#include <ivis/core/file_bytes.h>
#include <ivis/core/mesh_formats.h>
#include <ivis/core/mesh_reader.h>
#include <ivis/core/pvd_reader.h>
#include <ivis/core/raw_mesh_import.h>
#include <ivis/vdb/volume_cache.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <string>

namespace ivis::core {
namespace {

namespace fs = std::filesystem;

/// The reader each regressions folder holds inputs of, on a file's path and bytes.
const std::map<std::string, std::function<void(const std::string&, std::string)>>& readers()
{
    using detail::MeshFormat;
    static const std::map<std::string, std::function<void(const std::string&, std::string)>> table = {
        {"obj", [](const std::string& p, std::string b) { detail::readOpenMeshFile(p, MeshFormat::Obj, std::move(b)); }},
        {"off", [](const std::string& p, std::string b) { detail::readOpenMeshFile(p, MeshFormat::Off, std::move(b)); }},
        {"ply", [](const std::string& p, std::string b) { detail::readOpenMeshFile(p, MeshFormat::Ply, std::move(b)); }},
        {"stl", [](const std::string& p, std::string b) { detail::readOpenMeshFile(p, MeshFormat::Stl, std::move(b)); }},
        {"scalar_file", [](const std::string& p, std::string b) { detail::parseScalarFile(p, b, 4); }},
        {"vtk_xml", [](const std::string& p, std::string b) { detail::readVtkXml(p, std::move(b)); }},
        {"vtk_legacy", [](const std::string& p, std::string b) { detail::readVtkLegacy(p, std::move(b)); }},
        {"pvd", [](const std::string& p, std::string b) { detail::parsePvd(p, std::move(b)); }},
        {"volume_cache", [](const std::string& p, std::string) { vdb::readVolume(p); }},
        {"camera_json", [](const std::string& p, std::string b) { detail::parseCameraJson(p, b); }},
        {"evaluation_json", [](const std::string& p, std::string b) { app::detail::parseEvaluationJson(p, b); }},
    };
    return table;
}

TEST(FuzzRegression, EveryFoundInputGivesOneLineOrAMesh)
{
    const fs::path root = fs::path(IVIS_SOURCE_DIR) / "tests" / "fuzz" / "regressions";
    int inputs = 0;
    for (const fs::directory_entry& folder : fs::directory_iterator(root)) {
        const std::string reader = folder.path().filename().string();
        ASSERT_TRUE(readers().count(reader)) << "no reader for the regressions of " << reader;
        for (const fs::directory_entry& file : fs::directory_iterator(folder.path())) {
            SCOPED_TRACE(file.path().string());
            const std::string path = file.path().string();
            try {
                readers().at(reader)(path, detail::readFileBytes(path));
            } catch (const InputError& e) {
                EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
            }
            ++inputs;
        }
    }
    EXPECT_GE(inputs, 1);
}

}  // namespace
}  // namespace ivis::core
