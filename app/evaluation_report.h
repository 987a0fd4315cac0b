/// @file evaluation_report.h
/// @brief The Markdown tables of `inversevis evaluate`, made from its results JSON, so that a run
///        resumed from a partial JSON writes the same tables as an uninterrupted one.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ivis::app {

/// @brief What the tables show and in which order.
struct ReportLayout {
    std::vector<std::string> stems;    ///< mesh rows, in the order of the command line
    std::vector<std::string> methods;  ///< method columns
    std::vector<int> optResolutions;   ///< Table 2's resolutions per method
    int displayResolution = 1000;      ///< where the measures were taken
};

/// @brief Table 1 (surface visibility with its front-only part), the paper-literal visibility,
///        the mapping coherence, the hot-spot reveal (when some mesh has it) and Table 2 (seconds),
///        with a row per mesh of @a layout that @a results holds (results[stem][method] as
///        evaluate writes it); a method the row lacks (a partial job's) shows "-".
std::string evaluationMarkdown(const nlohmann::json& results, const ReportLayout& layout);

/// @brief How the settings @a a differ from @a b (an evaluation entry's "settings": options keyed
///        by their flags, each entry those its method uses): "" when every flag both hold is the
///        same, else the first that differs with both values, as "--steps 10 against 20", or
///        "settings against none (...)" when one side has none (a file of an older version).
/// @param sameMesh false for the entries of two meshes, which differ in the mesh (its "mesh hash")
///        and may differ in what each shows and how it is read (--scalar, --scalar-file,
///        --cell-to-point, --hotspots, --cap-holes, --distance), as docs/results.md's runs show the
///        artery's pressure and hot spots elsewhere
std::string settingsDifference(const nlohmann::json& a, const nlohmann::json& b, bool sameMesh);

/// @brief The results of an evaluate --json file (results[stem][method]), every entry checked as
///        evaluate writes it and its tables made once, so that anything amiss is found on reading.
/// @throw InputError naming @a path (and the entry) when it is a folder, missing, unreadable, or
///        not an evaluation's JSON
nlohmann::json readEvaluationJson(const std::string& path);

namespace detail {
/// @brief readEvaluationJson of the file's bytes @a text (the fuzz target's entry point).
nlohmann::json parseEvaluationJson(const std::string& path, const std::string& text);
}  // namespace detail

}  // namespace ivis::app
