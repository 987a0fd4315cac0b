// docs/cli.md holds every command's --help word for word (scripts/cli_doc.sh writes it).
#include "app/viewer_run.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace ivis::app {
namespace {

/// The text of docs/cli.md.
std::string cliPage()
{
    std::ifstream in(std::string(IVIS_SOURCE_DIR) + "/docs/cli.md");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Whether @a page shows @a help as one of its text blocks.
bool holdsBlock(const std::string& page, const std::string& help)
{
    return page.find("```text\n" + help + "```\n") != std::string::npos;
}

TEST(CliDoc, HoldsEveryCommandsHelp)
{
    const std::string page = cliPage();
    ASSERT_FALSE(page.empty()) << "docs/cli.md is missing: scripts/cli_doc.sh writes it";
    for (const std::string command :
         {"", "info", "sdf", "render", "optimize", "evaluate", "merge", "cache", "cache list", "cache clear"}) {
        const test::CliResult help = test::runCli(command + " --help");
        ASSERT_EQ(help.status, 0) << command << ": " << help.err;
        ASSERT_FALSE(help.out.empty()) << command;
        EXPECT_TRUE(holdsBlock(page, help.out))
            << "docs/cli.md does not hold `inversevis" << (command.empty() ? "" : " " + command)
            << " --help` as it is now: run scripts/cli_doc.sh";
    }
#ifdef IVIS_VIEW_PATH
    const test::TempDir dir;
    const test::RunResult viewer = test::runViewer("--help", false, dir);
    ASSERT_EQ(viewer.status, 0) << viewer.output;
    EXPECT_TRUE(holdsBlock(page, viewer.output))
        << "docs/cli.md does not hold `inversevis-view --help` as it is now: run scripts/cli_doc.sh";
#endif
}

}  // namespace
}  // namespace ivis::app
