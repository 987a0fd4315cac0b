// `inversevis info MESH`: what a mesh file carries.
#include "commands.h"

#include <ivis/core/mesh_reader.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace ivis::app {

Command addInfoCommand(CLI::App& app)
{
    struct Options {
        std::string path;
        bool json = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("info", "List what a mesh carries: counts, boundary, bounds, scalars");
    command->add_option("mesh", options->path, "Mesh file (.obj .off .ply .stl)")->required();
    command->add_flag("--json", options->json, "Print one JSON object");

    return {command, [options] {
        const core::MeshInfo info = core::describeMesh(options->path);
        if (options->json) {
            nlohmann::json scalars = nlohmann::json::array();
            for (const auto& s : info.scalars)
                scalars.push_back({{"name", s.name}, {"min", s.min}, {"max", s.max}, {"nan_count", s.nanCount}});
            const nlohmann::json out = {
                {"path", info.path},
                {"format", info.format},
                {"vertices", info.vertices},
                {"triangles", info.triangles},
                {"degenerate_dropped", info.degenerateDropped},
                {"boundary_edges", info.boundaryEdges},
                {"open_mesh", info.boundaryEdges > 0},
                {"components", info.components},
                {"bbox_min", {info.bounds.lo.x, info.bounds.lo.y, info.bounds.lo.z}},
                {"bbox_max", {info.bounds.hi.x, info.bounds.hi.y, info.bounds.hi.z}},
                {"scalars", scalars}};
            std::cout << out.dump(2) << "\n";
            return;
        }
        std::cout << info.path << " (" << info.format << ")\n"
                  << "  vertices        " << info.vertices << "\n"
                  << "  triangles       " << info.triangles;
        if (info.degenerateDropped > 0) std::cout << " (" << info.degenerateDropped << " degenerate dropped)";
        std::cout << "\n  boundary edges  " << info.boundaryEdges << (info.boundaryEdges > 0 ? " (open)" : " (closed)")
                  << "\n  components      " << info.components << "\n  bounding box    [" << info.bounds.lo.x
                  << ", " << info.bounds.lo.y << ", " << info.bounds.lo.z << "] .. [" << info.bounds.hi.x << ", "
                  << info.bounds.hi.y << ", " << info.bounds.hi.z << "]\n  scalars         ";
        if (info.scalars.empty()) std::cout << "none";
        std::cout << "\n";
        for (const auto& s : info.scalars) {
            std::cout << "    " << s.name << "  min " << s.min << "  max " << s.max;
            if (s.nanCount > 0) std::cout << "  (" << s.nanCount << " NaN)";
            std::cout << "\n";
        }
    }};
}

}  // namespace ivis::app
