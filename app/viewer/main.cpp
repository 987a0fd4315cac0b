// `inversevis-view`: the interactive viewer; parses arguments and maps errors to exit statuses.
#include "viewer_app.h"
#include "viewer_options.h"
#include "../cli_checks.h"
#include "../series_survey.h"
#include "../version.h"

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/core/log.h>
#include <ivis/core/surface_series.h>
#include <ivis/core/surface_source.h>

#include <CLI/CLI.hpp>

#include <iostream>

#if defined(__SANITIZE_ADDRESS__)
// Under `scripts/test.sh --sanitize` only: Mesa's GL driver keeps a few allocations and is unloaded
// (dlclose) before LeakSanitizer looks, so its frames have no module and no suppression can name
// them (GCC 12's runtime). The viewer keeps AddressSanitizer's other checks; its code shared with
// `inversevis` is leak-checked there.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
#endif

int main(int argc, char** argv)
{
    CLI::App app{"inversevis-view: both sides of a surface, live, on the GPU", "inversevis-view"};
    ivis::core::setLogProgram("inversevis-view");  // the libraries' notes name this program
    ivis::app::ViewerOptions options;
    options.addTo(app);
    app.set_version_flag("--version", ivis::app::versionText("inversevis-view"),
                         "Print the version and those of OpenVDB, Embree and OpenEXR");
    try {
        app.parse(argc, argv);
        options.takeSources();
        options.validate();
        // Headless, Ctrl-C ends the run between frames and leaves no screenshot (a window closes).
        if (options.headless()) ivis::core::installInterruptHandler();
        options.view.showViewScalar(options.mesh, options.mesh.source);
        if (!ivis::core::isSeries(options.sources, options.mesh.load)) {
            if (options.play)
                throw ivis::InputError("--play: " + options.mesh.source + " is one surface, not a time series (a .pvd, "
                                       "several files or a --scalar pattern)");
            ivis::app::ViewerApp viewer(options, ivis::core::loadSurface(options.mesh.source, options.mesh.load));
            return viewer.run();
        }
        auto series = std::make_unique<ivis::core::SurfaceSeries>(options.sources, options.mesh.load);
        const ivis::app::SeriesSurvey survey = ivis::app::surveySeries(*series);  // every step, before a word
        options.view.checkColourFlags(survey.scalar, series->source());
        ivis::core::SurfaceField first = series->load(0);
        ivis::app::ViewerApp viewer(options, std::move(first), std::move(series), survey);
        return viewer.run();
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help
        std::cerr << "inversevis-view: error: " << ivis::app::parseErrorText(app, e) << "\n";
        return 2;
    } catch (const ivis::Cancelled& e) {
        std::cerr << "inversevis-view: " << e.what() << "\n";
        return ivis::core::interruptExitStatus();
    } catch (const ivis::InternalError& e) {
        std::cerr << "inversevis-view: internal error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {  // InputError, ValueError, GlError, I/O
        std::cerr << "inversevis-view: error: " << e.what() << "\n";
        return 2;
    }
}
