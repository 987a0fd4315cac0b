// ViewerApp: what the window writes: screenshots, view files, the window itself.
#include "viewer_app.h"

#include "gl_window.h"

#include <ivis/core/image_io.h>
#include <ivis/core/surface_source.h>

#include <cstdio>

namespace ivis::app {

void ViewerApp::takeNumberedScreenshot()
{
    if (tracesOnCpu() && (mRestWanted || mCpuTracer.resting())) {  // the full picture, not a moving frame
        mCpuTracer.cancel();
        renderFrame(mCpuSize.x, mCpuSize.y);
        mRestWanted = false;
    }
    const std::string path =
        "inversevis-view-" + core::sourceStem(mOptions.mesh.source) + "-" + std::to_string(++mScreenshots) + ".png";
    try {
        core::AtomicFileSet files;
        writeScreenshot(files, path, "");
        files.commit();
        mStatus = "wrote " + path;
    } catch (const std::exception& e) {
        mStatus = e.what();
    }
}

void ViewerApp::saveView()
{
    const std::string path =
        "inversevis-view-" + core::sourceStem(mOptions.mesh.source) + "-" + std::to_string(++mSavedViews) + ".view.json";
    render::RenderOptions look = mOptions.view.renderOptions();
    look.width = mPicture.width > 0 ? mPicture.width : mOptions.width;
    look.height = mPicture.height > 0 ? mPicture.height : mOptions.height;
    look.method = mMethod;
    look.shading = mShading;
    look.legend = mShowLegend;
    look.legendSide = mLegendSide;
    look.outline = mOutline;
    look.units = shownUnits();
    try {
        writeViewFile(viewOfPicture(mOrbit.camera(), look, shownScalarLoad(), mField->normalization), path);
        mStatus = "wrote " + path;
    } catch (const std::exception& e) {
        mStatus = e.what();
    }
}

void ViewerApp::writeScreenshot(core::AtomicFileSet& files, const std::string& path, const std::string& regionPath,
                                int legendMargin)
{
    const core::Image picture = mRenderer->readColour();
    const bool legend = mShowLegend && mField->hasScalar();
    files.write(path, [&](const std::string& temporary) {
        core::writePng(legend ? core::withColorBar(picture, legendContent(), mLegendSide,
                                                   glm::vec4(mShading.background, 1.0f), legendMargin)
                              : picture,
                       temporary, false);
    });
    if (!regionPath.empty()) {
        files.write(regionPath, [&](const std::string& temporary) {
            core::writePng(regionImage(mRenderer->readRegion(), mRenderer->width(), mRenderer->height()), temporary,
                           false);
        });
    }
}

void ViewerApp::writeWindow(const std::string& path)
{
    const core::Image image = readWindow(mWindow);
    core::writePng(image, path, false);
    std::printf("inversevis-view: wrote %s (window %dx%d, panel %dx%d, picture %dx%d from x %d, %s)\n", path.c_str(),
                image.width(), image.height(), mPanelSize.x, mPanelSize.y, mPicture.width, mPicture.height, mPicture.x,
                mStatus.c_str());
}

}  // namespace ivis::app
