// `inversevis-view`: the interactive viewer; parses arguments and maps errors to exit statuses.
#include "viewer_app.h"
#include "viewer_options.h"
#include "../version.h"

#include <ivis/core/errors.h>
#include <ivis/core/surface_source.h>

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv)
{
    CLI::App app{"inversevis-view: both sides of a surface, live, on the GPU"};
    ivis::app::ViewerOptions options;
    options.addTo(app);
    app.set_version_flag("--version", ivis::app::versionText("inversevis-view"),
                         "Print the version and those of OpenVDB, Embree and OpenEXR");
    try {
        app.parse(argc, argv);
        options.validate();
        ivis::core::SurfaceField field = ivis::core::loadSurface(options.mesh.source, options.mesh.load);
        ivis::app::ViewerApp viewer(options, std::move(field));
        return viewer.run();
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help
        std::cerr << "inversevis-view: error: " << e.what() << "\n";
        return 2;
    } catch (const ivis::Cancelled& e) {
        std::cerr << "inversevis-view: " << e.what() << "\n";
        return 130;
    } catch (const ivis::InternalError& e) {
        std::cerr << "inversevis-view: internal error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {  // InputError, ValueError, GlError, I/O
        std::cerr << "inversevis-view: error: " << e.what() << "\n";
        return 2;
    }
}
