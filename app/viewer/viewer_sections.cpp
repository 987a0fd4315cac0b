// ViewerApp: the panel and its sections.
#include "viewer_app.h"

#include "viewer_clock.h"
#include "viewer_panel.h"

#include <ivis/core/surface_source.h>
#include <ivis/render/framing.h>

#include <imgui.h>

namespace ivis::app {

namespace {

/// The panel's text width and its widgets' width, in font heights: narrow enough that the picture
/// keeps most of the window.
constexpr float kPanelWidthEm = 20.0f;
constexpr float kPanelItemWidthEm = 11.0f;
/// The panel's distance from the window's top left corner where it opens.
constexpr float kPanelMargin = 8.0f;

}  // namespace

void ViewerApp::drawPanel()
{
    ImGui::SetNextWindowPos(ImVec2(kPanelMargin, kPanelMargin), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("inversevis", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * kPanelWidthEm);
    ImGui::PushItemWidth(ImGui::GetFontSize() * kPanelItemWidthEm);
    drawSourceLines();
    bool changed = false;
    if (ImGui::CollapsingHeader("method##section", ImGuiTreeNodeFlags_DefaultOpen))
        changed |= methodWidgets(mMethod, mLoaded ? mLoaded->slices.reach : 0.6f);
    if (ImGui::CollapsingHeader("colour##section", ImGuiTreeNodeFlags_DefaultOpen)) {
        changed |= drawColourByCombo();
        const std::string colormap = mShading.colormap;
        changed |= lookWidgets(mShading, mColormapIndex, mDataScale, mField->hasScalar());
        changed |= ImGui::Checkbox("outline", &mOutline);
        tooltip("dark outline around the directly visible object, so direct and indirect parts are told apart");
        if (mField->hasScalar()) {
            ImGui::SameLine();
            ImGui::Checkbox("colour bar", &mShowLegend);
        }
        if (mShading.colormap != colormap) mRenderer->setColormap(mShading.colormap);
    }
    if (ImGui::CollapsingHeader("optimise##section", ImGuiTreeNodeFlags_DefaultOpen)) drawOptimiserSection();
    if (ImGui::CollapsingHeader("probe##section", ImGuiTreeNodeFlags_DefaultOpen))
        if (const std::optional<glm::dvec2> view = mProbe.widgets(*mField)) turnTo(*view);
    if (ImGui::CollapsingHeader("picture##section")) changed |= drawPictureSection();
    ImGui::Separator();
    if (ImGui::Button("screenshot (P)")) takeNumberedScreenshot();
    ImGui::SameLine();
    if (ImGui::Button("save view")) saveView();
    tooltip("write the view file of this picture (camera, method and parameters, scalar, colour): "
            "`inversevis render --view FILE` and `inversevis-view --view FILE` show it again");
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    tooltip(mSeries ? "drag: orbit; right/middle or shift-drag: pan; wheel: zoom; F: frame; P: screenshot; "
                      "left/right: time step; space: play / pause"
                    : "drag: orbit; right/middle or shift-drag: pan; wheel: zoom; F: frame; P: screenshot");
    if (!mStatus.empty()) ImGui::TextUnformatted(mStatus.c_str());
    ImGui::PopItemWidth();
    ImGui::PopTextWrapPos();
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    mPanelSize = glm::ivec2(int(ImGui::GetWindowWidth() * scale.x), int(ImGui::GetWindowHeight() * scale.y));
    const ImVec2 corner = ImGui::GetWindowPos();
    const bool atTopLeft = corner.x <= 2.0f * kPanelMargin && corner.y <= 2.0f * kPanelMargin;
    mPanelDock = atTopLeft && !ImGui::IsWindowCollapsed() ? (corner.x + ImGui::GetWindowWidth()) * scale.x : 0.0f;
    ImGui::End();
    if (changed) mDirty = true;
}

void ViewerApp::drawSourceLines()
{
    ImGui::Text("%s: %zu triangles, scalar '%s'", core::sourceStem(mOptions.mesh.source).c_str(),
                mField->mesh.triangles.size(), mField->hasScalar() ? mField->name.c_str() : "(none)");
    if (mSeries) {
        const std::size_t count = mSeries->steps().size();
        int step = int(mStep);
        const core::SeriesStep& shown = mSeries->steps()[mStep];
        std::string format;  // the slider's text is a printf format: a '%' of the label doubled
        for (const char c : shown.label) format += c == '%' ? std::string("%%") : std::string(1, c);
        ImGui::BeginDisabled(jobRunning());
        if (ImGui::SliderInt("time step", &step, 0, int(count) - 1, format.c_str(), ImGuiSliderFlags_AlwaysClamp)) {
            mPlaying = false;  // the hand that holds the slider chooses the step
            switchStep(std::size_t(step));
        }
        ImGui::EndDisabled();
        tooltip("The steps of the time series (time of each from the .pvd; its index for files, a --scalar "
                "pattern or a .pvd without times); one colour range over all steps; the volume stays while the geometry does. Disabled "
                "while an optimiser or the survey of 'colour by' runs.");
        ImGui::BeginDisabled(jobRunning() && !mPlaying);  // a pause is always possible
        if (ImGui::Button(mPlaying ? "pause" : "play")) setPlaying(!mPlaying);
        ImGui::EndDisabled();
        tooltip("play (space): the steps one after the other at steps/s, each shown a whole interval once its volume "
                "is loaded, from the first when the slider is at the last; it waits while an optimiser or 'colour by' "
                "runs, and the slider pauses it");
        ImGui::SameLine();
        ImGui::Checkbox("loop", &mLoop);
        tooltip("play on from the last step to the first");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
        ImGui::DragFloat("steps/s", &mPlayRate, 0.1f, 0.1f, 60.0f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
        tooltip("steps per second while playing (--play-rate)");
        if (mSeries->timed()) ImGui::Text("step %zu of %zu, time %g", mStep + 1, count, shown.time);
        else ImGui::Text("step %zu of %zu, %s", mStep + 1, count, shown.label.c_str());
    }
    if (mLoader) {
        const int percent = mLoader->progress().percent();
        const std::string label = mLoader->progress().stage() + (percent >= 0 ? " " + std::to_string(percent) + "%" : "");
        ImGui::ProgressBar(percent >= 0 ? percent / 100.0f : 0.0f, ImVec2(ImGui::GetFontSize() * kPanelWidthEm, 0),
                           label.c_str());
        ImGui::TextUnformatted("loading the volume in the background; the direct part shows meanwhile");
    }
}

void ViewerApp::drawOptimiserSection()
{
    const bool busy = jobRunning() || !mLoaded;
    optimiserWidgets(mOptimiser, mField->hasScalar());
    const bool hasParameters = !render::optimisedParameters(*mMethod).empty();
    ImGui::BeginDisabled(busy || !hasParameters);
    if (ImGui::Button(optimiseLabel(*mMethod).c_str())) startOptimiser(Job::Parameters);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: optimize::optimizeParameters, gradient ascent of the method's optimised "
            "parameters with golden-section line searches on the true energy, at this view; they then ease to the "
            "result");
    ImGui::SameLine();
    ImGui::BeginDisabled(busy);
    if (ImGui::Button("optimise view")) startOptimiser(Job::View);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: optimize::annealViewpoint, simulated annealing of the camera on the radius-2.5 "
            "sphere from this view, the parameters optimised at every proposal; the camera then eases to the best "
            "view. Closing the window stops it.");
    ImGui::SameLine();
    ImGui::BeginDisabled(busy || mMethod->info().readableRuleParameter.empty());
    if (ImGui::Button("readable rule")) startOptimiser(Job::ReadableRule);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: optimize::loosestReadable, the loosest rule for drawing rays (inversevis-wrap: "
            "stable_shift, from an eighth of its default to 8 times it) whose 1000 x 1000 picture from this view keeps the "
            "mapping coherence --min-coherence (0.99), as render chooses it; done at start when the rule is not given");
    if (mJob.valid()) ImGui::Text("running %.0f s", now() - mJobStart);
    for (std::size_t k = 0; k < mViewSet.size() && mViewSet.size() > 1; ++k) {
        if (k > 0) ImGui::SameLine();
        ImGui::BeginDisabled(busy || mViewSet[k].method->name() != mMethod->name());
        if (ImGui::Button(("view " + std::to_string(k + 1)).c_str())) moveTo(mViewSet[k], true, now());
        ImGui::EndDisabled();
    }
    if (mViewSet.size() > 1)
        tooltip("the last 'optimise view''s several views (views > 1, as optimize --views): the best first, then "
                "those showing the most surface the views before miss; the camera and parameters ease there");
}

bool ViewerApp::drawPictureSection()
{
    bool changed = false;
    bool framed = mOrbit.framed;
    if (ImGui::Checkbox("frame the picture (F)", &framed)) {
        mAnimation.stop();
        if (framed) mOrbit.frameAgain();
        else mOrbit.framed = false;
        changed = true;
    }
    tooltip("render::frameView each frame: the field of view fitted to the object and the method's whole indirect "
            "region (hull, rings or mirror footprint) with a margin, the eye back on the radius-2.5 sphere; a zoom "
            "or pan ends it");
    ImGui::Text("camera theta %.1f phi %.1f distance %.2f, field of view %.1f", mOrbit.thetaDeg, mOrbit.phiDeg,
                mOrbit.distance, mOrbit.fovYDeg);
    if (tracesOnCpu()) {
        changed |= ImGui::SliderFloat("render scale", &mRenderScale, 0.25f, 1.0f, "%.2f");
        tooltip("fraction of the window's pixels the CPU traces once the camera rests");
        ImGui::Text("traced by the CPU (--tracer); moving: %.0f%% of each side", 100.0 * mCpuTracer.movingScale());
        tooltip("the CPU renderer draws the picture render writes: while the camera moves, as many pixels as keep 12 "
                "frames per second; once it rests, the full picture, shown when done (--tracer gpu: the shaders)");
    } else {
        changed |= traceScaleWidgets(mRenderScale, mInteraction.reduction);
    }
    ImGui::Text("frame %.1f ms (%.1f fps) at %dx%d", mLastFrameMs, mLastFrameMs > 0.0 ? 1000.0 / mLastFrameMs : 0.0,
                mRenderer->width(), mRenderer->height());
    if (mLoaded) ImGui::TextUnformatted(mVolumeText.c_str());
    ImGui::TextDisabled("%s", mGlRenderer.c_str());
    return changed;
}

}  // namespace ivis::app
