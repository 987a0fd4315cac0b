// Evaluation jobs run apart (evaluate --only MESH:METHOD) and joined by `inversevis merge` give
// the results and tables of one evaluation of them all.
#include "cli_fixture.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ivis::app {
namespace {

/// @a results without the timings (which differ from run to run).
nlohmann::json withoutSeconds(nlohmann::json results)
{
    for (auto& [stem, methods] : results.items())
        for (auto& [method, entry] : methods.items()) entry.erase("seconds");
    return results;
}

TEST_F(Cli, MergedJobsGiveTheEvaluationOfThemAll)
{
    const std::string common = "evaluate scene:sphere scene:torus --volume-res 48 --methods front,inversevis --opt-res 16 "
                               "--steps 1 --display-res 32 --cache-dir " + quoted(output(""));
    const test::CliResult full = test::runCli(common + " --json " + quoted(output("all.json")) + " --markdown " +
                                              quoted(output("all.md")));
    ASSERT_EQ(full.status, 0) << full.err;
    const test::CliResult first =
        test::runCli(common + " --only sphere:front --only torus:inversevis --json " + quoted(output("p1.json")));
    ASSERT_EQ(first.status, 0) << first.err;
    const test::CliResult second =
        test::runCli(common + " --only sphere:inversevis --only torus:front --json " + quoted(output("p2.json")));
    ASSERT_EQ(second.status, 0) << second.err;
    const nlohmann::json part = nlohmann::json::parse(std::ifstream(output("p1.json")));
    EXPECT_EQ(part.at("sphere").size(), 1u);  // only what --only asked for
    EXPECT_TRUE(part.at("sphere").contains("front"));

    const test::CliResult merged = test::runCli("merge " + quoted(output("p2.json")) + " " + quoted(output("p1.json")) +
                                                " --json " + quoted(output("m.json")) + " --markdown " + quoted(output("m.md")));
    ASSERT_EQ(merged.status, 0) << merged.err;
    const nlohmann::json all = nlohmann::json::parse(std::ifstream(output("all.json")));
    EXPECT_EQ(withoutSeconds(nlohmann::json::parse(std::ifstream(output("m.json")))), withoutSeconds(all));
    const std::string tables = test::readFile(output("all.md")), joined = test::readFile(output("m.md"));
    EXPECT_EQ(joined.substr(0, joined.find("## Viewpoint")), tables.substr(0, tables.find("## Viewpoint")))
        << "the same tables (the seconds may differ)";

    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " " + quoted(output("p1.json"))),
                   {"sphere:front is in", "p1.json too"});
    // Parts of other evaluations: other options, or none recorded (they used to be joined).
    nlohmann::json other = nlohmann::json::parse(std::ifstream(output("p2.json")));
    other.at("torus").at("front").at("settings")["--steps"] = 2;
    test::writeFile(output("other.json"), other.dump());
    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " " + quoted(output("other.json"))),
                   {"other.json: torus:front was evaluated with --steps 2 against 1 in", "p1.json (sphere:front); merge "
                                                                                         "parts of one evaluation"});
    // --views is recorded only above 1: a part of one view against one of two (they were joined).
    other = nlohmann::json::parse(std::ifstream(output("p2.json")));
    other.at("torus").at("front").at("settings")["--views"] = 2;
    test::writeFile(output("other.json"), other.dump());
    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " " + quoted(output("other.json"))),
                   {"other.json: torus:front was evaluated with --views 2 against 1 in"});
    // Two meshes of one file name (patient01/surface.vtp, patient02/surface.vtp) are not one row.
    other = nlohmann::json::parse(std::ifstream(output("p2.json")));
    other.at("torus").at("front").at("settings")["mesh hash"] = "0123456789abcdef";
    test::writeFile(output("other.json"), other.dump());
    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " " + quoted(output("other.json"))),
                   {"torus:front was evaluated with mesh hash \"0123456789abcdef\" against"});
    // The meshes of one evaluation may show other scalars (docs/results.md: the artery's pressure,
    // hot spots elsewhere), each mesh one for all its methods.
    other = nlohmann::json::parse(std::ifstream(output("p2.json")));
    nlohmann::json hot = nlohmann::json::parse(std::ifstream(output("p1.json")));
    other.at("torus").at("front").at("settings")["--hotspots"] = 2;
    test::writeFile(output("other.json"), other.dump());
    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " " + quoted(output("other.json"))),
                   {"torus:front was evaluated with --hotspots 2 against 0 in", "(torus:inversevis)"});
    hot.at("torus").at("inversevis").at("settings")["--hotspots"] = 2;
    test::writeFile(output("hot.json"), hot.dump());
    const test::CliResult rows = test::runCli("merge " + quoted(output("hot.json")) + " " + quoted(output("other.json")));
    EXPECT_EQ(rows.status, 0) << rows.err;
    other.at("torus").at("front").erase("settings");
    test::writeFile(output("other.json"), other.dump());
    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " " + quoted(output("other.json"))),
                   {"torus:front was evaluated with none (an evaluation of before 2026-11-27) against settings in"});
    // A job of one method is given only the flags it uses, and its entries still join the others'.
    const std::string job = "evaluate scene:sphere --volume-res 48 --opt-res 16 --steps 1 --display-res 32 --cache-dir " +
                            quoted(output("")) + " --methods ";
    for (const auto& [methodAndFlag, part] : std::vector<std::pair<std::string, std::string>>{
             {"inversevis --alpha-scan 3", "a1.json"}, {"inversevis-wrap --min-coherence 0.9", "a2.json"},
             {"front", "a3.json"}}) {
        const test::CliResult one = test::runCli(job + methodAndFlag + " --json " + quoted(output(part)));
        ASSERT_EQ(one.status, 0) << one.err;
    }
    expectBadInput(test::runCli(job + "front --alpha-scan 3"), {"--alpha-scan: no method given has a parameter to scan"});
    const test::CliResult apart = test::runCli("merge " + quoted(output("a1.json")) + " " + quoted(output("a2.json")) +
                                                " " + quoted(output("a3.json")));
    EXPECT_EQ(apart.status, 0) << apart.err;
    test::writeFile(output("empty.json"), "{}");
    expectBadInput(test::runCli("merge " + quoted(output("empty.json"))), {"empty.json: holds no evaluation"});
    // Parts that are not an evaluation's: each named, none an internal error.
    expectBadInput(test::runCli("merge " + quoted(output(""))), {": a folder, not an evaluate --json file"});
    const std::vector<std::pair<std::function<void(nlohmann::json&)>, std::string>> broken = {
        {[](nlohmann::json& j) { j["sphere"]["front"]["visibility"] = "high"; },
         "sphere:front is not an evaluation's (its visibility is not a number from 0 to 1)"},
        {[](nlohmann::json& j) { j["sphere"]["front"]["visibility"] = 7.5; },
         "sphere:front is not an evaluation's (its visibility is not a number from 0 to 1)"},
        {[](nlohmann::json& j) { j["sphere"]["front"].erase("coherence"); },
         "sphere:front is not an evaluation's (its coherence is not a number from 0 to 1)"},
        {[](nlohmann::json& j) { j["sphere"]["magic"] = j["sphere"]["front"]; },
         "sphere:magic is not an evaluation's (no method is named magic)"},
        {[](nlohmann::json& j) { j["sphere"]["front"]["seconds"] = {{"fast", 1.0}}; },
         "sphere:front is not an evaluation's (its seconds are not numbers keyed by resolutions)"},
        {[](nlohmann::json& j) { j["sphere"]["front"]["display_res"] = "x"; },
         "sphere:front is not an evaluation's (its display_res is not a whole number of pixels)"},
        {[](nlohmann::json& j) { j["a\nb"] = j["sphere"]; },  // found by evaluation_json_fuzzer: a message of two lines
         "'a b' is not a mesh's name (it holds a control character)"}};
    for (const auto& [breaking, message] : broken) {
        nlohmann::json part = nlohmann::json::parse(std::ifstream(output("p1.json")));
        breaking(part);
        test::writeFile(output("broken.json"), part.dump());
        expectBadInput(test::runCli("merge " + quoted(output("broken.json"))), {"broken.json: " + message});
    }
    // Parts measured at other picture sizes, each named.
    other = nlohmann::json::parse(std::ifstream(output("p2.json")));
    other.at("torus").at("front")["display_res"] = 64;
    test::writeFile(output("other.json"), other.dump());
    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " " + quoted(output("other.json"))),
                   {"other.json: torus:front was measured at --display-res 64 against 32 in", "p1.json; merge parts"});
    // The tables written over a part (it was replaced, status 0).
    const std::string before = test::readFile(output("p1.json"));
    expectBadInput(test::runCli("merge " + quoted(output("p1.json")) + " --markdown " + quoted(output("p1.json"))),
                   {"p1.json: --markdown would overwrite a part, which this command reads"});
    EXPECT_EQ(test::readFile(output("p1.json")), before);
    expectBadInput(test::runCli(common + " --only sphere"), {"--only 'sphere': expected MESH:METHOD"});
    expectBadInput(test::runCli(common + " --only cube:front"), {"no mesh 'cube'"});
    expectBadInput(test::runCli(common + " --only sphere:mirror"), {"method 'mirror' is not among --methods"});
}

}  // namespace
}  // namespace ivis::app
