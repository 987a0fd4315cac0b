#include <ivis/core/pvd_reader.h>

#include "value_decoding.h"

#include <ivis/core/file_bytes.h>
#include <ivis/core/file_extension.h>
#include <ivis/core/mesh_formats.h>
#include <ivis/core/mesh_layout_check.h>

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace ivis::core {

std::vector<TimeStep> readPvd(const std::string& path) { return detail::parsePvd(path, detail::readFileBytes(path)); }

std::vector<TimeStep> detail::parsePvd(const std::string& path, std::string text)
{
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_buffer_inplace(text.data(), text.size());
    if (!parsed) {
        failInput(path, std::string("not valid XML (") + parsed.description() + " at byte " +
                            std::to_string(parsed.offset) + ")");
    }
    const pugi::xml_node collection = document.child("VTKFile").child("Collection");
    if (!collection || std::string(document.child("VTKFile").attribute("type").value()) != "Collection") {
        failInput(path, "not a ParaView collection (no <VTKFile type=\"Collection\"> with a <Collection>)");
    }
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::vector<TimeStep> steps;
    for (const pugi::xml_node& dataset : collection.children("DataSet")) {
        const std::string where = "DataSet " + std::to_string(steps.size());
        const std::string file = dataset.attribute("file").value();
        if (file.empty()) failInput(path, where + " has no file");
        TimeStep step;
        const std::string time = dataset.attribute("timestep").value();
        if (!time.empty() && !(detail::parseNumber(time, step.time) && std::isfinite(step.time))) {
            failInput(path, where + " has the timestep '" + time + "', which is not a finite number");
        }
        step.timed = !dataset.attribute("timestep").empty();
        if (!steps.empty() && step.timed != steps.front().timed)
            failInput(path, "DataSet " + std::to_string(step.timed ? 0 : steps.size()) + " has no timestep, and DataSet " +
                                std::to_string(step.timed ? steps.size() : 0) +
                                " has one: give every DataSet its time, or none (the steps in the file's order)");
        if (!step.timed) step.time = double(steps.size());
        const std::string part = dataset.attribute("part").as_string("0");
        if (part != "0") failInput(path, where + " is part " + part + " of its time step; one part per step is read");
        step.path = (folder / file).string();
        std::error_code ec;
        if (std::filesystem::is_directory(step.path, ec))
            failInput(path, where + " names '" + file + "', which is a folder");
        if (!std::filesystem::is_regular_file(step.path, ec)) {
            failInput(path, where + " names '" + file + "', which does not exist");
        }
        if (!detail::findMeshFileFormat(step.path)) {
            const std::string extension = lowerCaseExtension(step.path);
            failInput(path, where + " names '" + file + "', which is not a mesh file (" +
                                (extension.empty() ? std::string("no extension") : "'" + extension + "'") + ")");
        }
        steps.push_back(step);
    }
    if (steps.empty()) failInput(path, "the collection lists no DataSet");
    std::stable_sort(steps.begin(), steps.end(), [](const TimeStep& a, const TimeStep& b) { return a.time < b.time; });
    return steps;
}

}  // namespace ivis::core
