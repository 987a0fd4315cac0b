// ViewerApp: "colour by": the arrays of the file (of a series, of every step) and their colour scales.
#include "viewer_app.h"

#include "viewer_panel.h"

#include <ivis/core/errors.h>
#include <ivis/core/log.h>

#include <imgui.h>

#include <cstdio>

namespace ivis::app {

bool ViewerApp::drawColourByCombo()
{
    if (mArrayChoices.empty()) return false;
    auto label = [&](int i) {
        if (i < 0) return mOpenedScalar ? mOpenedScalar->name : std::string("(none)");
        const core::ArrayChoice& c = mArrayChoices[std::size_t(i)];
        return c.association == core::Association::Cell ? c.name + " (cell)" : c.name;
    };
    const int shown = mArrayChoice;
    // A series waits for its volume: the loader's end may start the readable rule, which waits for no survey.
    ImGui::BeginDisabled(jobRunning() || (mSeries && mLoader));
    if (ImGui::BeginCombo("colour by", label(mArrayChoice).c_str())) {
        for (int i = mOpenedScalar ? -1 : 0; i < int(mArrayChoices.size()); ++i) {
            ImGui::PushID(i);
            if (ImGui::Selectable(label(i).c_str(), i == mArrayChoice) && i != mArrayChoice) colourBy(i);
            ImGui::PopID();
        }
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    tooltip("the scalar shown: each array of the file (a vector's magnitude or one component; a cell array flat per "
            "triangle), as --scalar names it; the colour range follows the data (the range options' rules, not a "
            "fixed --range). A time series: the array of every step, its range over all steps (each step read again "
            "in the background; disabled while its volume loads). Disabled while an optimiser or that reading runs.");
    return mArrayChoice != shown;
}

void ViewerApp::colourBy(int choice)
{
    if (mSeries) {
        startSeriesColouring(choice);
        return;
    }
    stopCpuPicture();  // it reads the field's values
    std::vector<float> shownValues = mField->values;  // shown again when the choice fails
    const core::Association shownOn = mField->valuesOn;
    std::string shownName = mField->name;
    core::ColorScale dataScale;
    try {
        if (choice < 0) {
            mField->values = mOpenedScalar->values;
            mField->valuesOn = mOpenedScalar->on;
            mField->name = mOpenedScalar->name;
        } else {
            core::showArray(*mField, mArrayChoices[std::size_t(choice)].spec, false);
        }
        dataScale = choiceDataScale(choice, mField->values);
    } catch (const std::exception& e) {
        mField->values = std::move(shownValues);
        mField->valuesOn = shownOn;
        mField->name = std::move(shownName);
        mStatus = e.what();
        return;
    }
    showChoice(choice, dataScale);
}

core::ColorScale ViewerApp::choiceDataScale(int choice, const std::vector<float>& data) const
{
    if (choice == mOpenedChoice) return mOpenedDataScale;
    core::ColorScaleRequest request = mOptions.view.colorScaleRequest();
    request.range.reset();  // a range given was the opened scalar's
    try {
        return request.resolve(data);
    } catch (const ValueError&) {  // a log scale over data without a positive value
        request.log = false;
        return request.resolve(data);
    }
}

void ViewerApp::showChoice(int choice, const core::ColorScale& dataScale)
{
    if (mArrayChoice == mOpenedChoice) mOpenedScale = mShading.scale;  // as the panel left it
    mArrayChoice = choice;
    mDataScale = dataScale;
    // The opened scalar gets its own scale again (--range, a view file's, the panel's).
    mShading.scale = choice == mOpenedChoice ? mOpenedScale : mDataScale;
    mRenderer->setMesh(*mField, mNormals);
    mProbe.readScalar(*mField);
    std::printf("inversevis-view: colour by %s, range %g to %g%s\n", mField->name.c_str(), mDataScale.range.lo,
                mDataScale.range.hi, mDataScale.log ? ", log" : "");
    std::fflush(stdout);
    mDirty = true;
}

void ViewerApp::startSeriesColouring(int choice)
{
    auto series = std::make_unique<core::SurfaceSeries>(*mSeries);
    const core::SurfaceLoadOptions load = choiceLoad(choice);
    const std::size_t step = mStep;  // the slider waits for the job
    mCancelJob = false;
    mColouring = std::async(std::launch::async, [this, choice, load, step, series = std::move(series)]() mutable {
        series->chooseScalar(load);
        SeriesSurvey survey = surveySeries(*series, nullptr, &mCancelJob);
        const core::ScopedLogLevel silent(core::LogLevel::Silent);  // the survey has loaded it: nothing new to say
        core::SurfaceField shown = series->load(step);
        return SeriesColouring{std::move(series), std::move(survey), std::move(shown), choice};
    });
    mStatus = "colour by: reading every step of the series...";
}

void ViewerApp::pollSeriesColouring()
{
    if (!mColouring.valid() || mColouring.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    core::ColorScale dataScale;
    SeriesColouring colouring;
    try {
        colouring = mColouring.get();
        if (colouring.survey.meshHashes != mSurvey.meshHashes)
            throw InputError(mSeries->source() + ": a step's geometry changed on disk since the series was opened; "
                                                 "open it again");
        dataScale = choiceDataScale(colouring.choice, colouring.survey.sample);
    } catch (const std::exception& e) {  // a step without the array, a file changed on disk, a cancel
        mStatus = std::string("colour by: ") + e.what();
        return;
    }
    stopCpuPicture();  // it reads the field's values
    mSeries = std::move(colouring.series);
    mSurvey = std::move(colouring.survey);
    core::showStepData(*mField, std::move(colouring.shown));  // the same geometry (its hash)
    mStatus.clear();
    showChoice(colouring.choice, dataScale);
}

core::SurfaceLoadOptions ViewerApp::choiceLoad(int choice) const
{
    core::SurfaceLoadOptions load = mOptions.mesh.load;
    if (choice != mOpenedChoice) {
        load.read = core::MeshReadOptions{mArrayChoices[std::size_t(choice)].spec, "", false};
        load.hotSpots = 0;
    }
    return load;
}

}  // namespace ivis::app
