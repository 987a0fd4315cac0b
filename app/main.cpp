// The `inversevis` command-line program: parses arguments and maps errors to exit statuses.
#include "cli_checks.h"
#include "commands.h"
#include "version.h"

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/core/log.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <new>
#include <vector>

int main(int argc, char** argv)
{
    CLI::App app{"inversevis: scalar fields on both sides of a surface mesh", "inversevis"};
    app.set_version_flag("--version", ivis::app::versionText("inversevis"), "Print the version and those of OpenVDB, Embree and OpenEXR");
    app.require_subcommand(1);
    app.fallthrough();  // global flags (-q) may follow the subcommand
    bool quiet = false;
    app.add_flag("-q,--quiet", quiet, "Print only warnings and errors");
    const std::vector<ivis::app::Command> commands = {ivis::app::addInfoCommand(app),
                                                       ivis::app::addSdfCommand(app),
                                                       ivis::app::addRenderCommand(app),
                                                       ivis::app::addOptimizeCommand(app),
                                                       ivis::app::addEvaluateCommand(app),
                                                       ivis::app::addMergeCommand(app),
                                                       ivis::app::addCacheCommand(app)};
    ivis::core::installInterruptHandler();
    try {
        ivis::app::rejectEmptyLists(argc, argv);
        app.parse(argc, argv);
        if (quiet) ivis::core::setLogLevel(ivis::core::LogLevel::Warning);
        for (const auto& command : commands)
            if (command.parser->parsed()) command.run();
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help
        std::string message = ivis::app::parseErrorText(app, e);
        const auto word = std::find_if(argv + 1, argv + argc, [](const char* a) { return a[0] != '-'; });
        if (app.get_subcommands().empty() && word != argv + argc) {  // CLI11 says only "A subcommand is required"
            message = std::string("'") + *word + "' is not a command; the commands are";
            for (const auto& command : commands) message += " " + command.parser->get_name();
        } else if (app.get_subcommands().size() == 1) {  // a command of commands (cache) without one of its own
            const CLI::App* parent = app.get_subcommands().front();
            const std::vector<const CLI::App*> own = parent->get_subcommands({});
            if (!own.empty() && parent->get_subcommands().empty() && e.get_name() == "RequiredError") {
                message = parent->get_name() + " needs one of its commands:";
                for (const CLI::App* command : own) message += " " + command->get_name();
            }
        }
        std::cerr << "inversevis: error: " << message << "\n";
        return 2;
    } catch (const ivis::UserError& e) {
        std::cerr << "inversevis: error: " << e.what() << "\n";
        return 2;
    } catch (const ivis::Cancelled& e) {
        std::cerr << "inversevis: " << e.what() << "\n";
        return ivis::core::interruptExitStatus();
    } catch (const std::filesystem::filesystem_error& e) {  // a path the system refuses: too long, not permitted
        std::cerr << "inversevis: error: " << (e.path1().empty() ? std::string("a path") : e.path1().string()) << ": "
                  << e.code().message() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {  // a picture or volume larger than the memory (outputs not yet renamed)
        std::cerr << "inversevis: error: out of memory: a smaller --res, --spp or --volume-res needs less\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "inversevis: internal error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
