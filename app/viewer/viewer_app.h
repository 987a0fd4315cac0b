/// @file viewer_app.h
/// @brief The `inversevis-view` program: a GLFW window with an OpenGL 4.3 core context, the GPU
///        renderer, a Dear ImGui panel, background loading and optimisation, and the headless
///        screenshot and benchmark modes.
/// @note Its definitions, by concept: viewer_app.cpp (the window's life and main loop),
///       viewer_frames.cpp (a frame: framing, shaders or CPU), viewer_series.cpp (time series),
///       viewer_colour_by.cpp ("colour by"), viewer_sections.cpp (the panel), viewer_input.cpp
///       (mouse and keys), viewer_jobs.cpp (the optimisers), viewer_files.cpp (screenshots, view
///       files), viewer_headless.cpp (--screenshot, --benchmark).
#pragma once

#include "color_bar_overlay.h"
#include "cpu_tracer.h"
#include "gpu_renderer.h"
#include "interaction_scale.h"
#include "orbit_camera.h"
#include "probe_panel.h"
#include "scene_loader.h"
#include "view_optimiser.h"
#include "viewer_options.h"
#include "../series_survey.h"

#include <ivis/core/atomic_file.h>
#include <ivis/core/clustered_vertices.h>
#include <ivis/core/show_array.h>
#include <ivis/core/surface_field.h>
#include <ivis/core/surface_series.h>
#include <ivis/render/method.h>
#include <ivis/render/shading.h>

#include <atomic>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ivis::app {

/// @brief One viewer session on one surface, or on the steps of a time series.
class ViewerApp {
public:
    /// @brief Validates the view options against @a field (colour map, range, method).
    /// @param series when given, @a field is its first step and a time slider shows the others; the
    ///        colour range is @a survey's, over all steps, unless --range is given
    /// @throw InputError / ValueError for bad options
    ViewerApp(const ViewerOptions& options, core::SurfaceField field,
              std::unique_ptr<core::SurfaceSeries> series = nullptr, SeriesSurvey survey = {});
    ~ViewerApp();
    ViewerApp(const ViewerApp&) = delete;
    ViewerApp& operator=(const ViewerApp&) = delete;

    /// @brief Opens the window and runs until it closes (or the headless job is done).
    /// @return the exit status (0)
    /// @throw GlError when no OpenGL 4.3 core context can be had; InputError / ValueError from loading
    int run();

private:
    void openWindow();
    void closeWindow();
    void startLoading();
    /// Shows step @a step of the series: its scalar replaces the shown one when its geometry is the
    /// same (the volume stays); other geometry is uploaded and its volume loaded in the background.
    void showStep(std::size_t step);
    /// showStep for the slider, the arrow keys and playing: an error goes to the panel's status line.
    void switchStep(std::size_t step);
    /// Starts or stops playing the series (from its first step when it stands at its last).
    void setPlaying(bool playing);
    /// While playing: the next step once the shown step's volume is loaded, no job runs and
    /// 1 / rate seconds have passed since; at the last step, the first again with "loop", else the
    /// end of playing.
    void advancePlayback(double time);
    /// Uploads the loaded scene once the loader is done; true when it did so this call.
    bool pollLoader();
    void waitForScene();
    /// What the colour bar shows now: the look, the scalar's name (a series: with its step), --units.
    core::ColorBarContent legendContent() const;
    GpuFrame frame(int width, int height) const;
    /// True when the CPU renderer traces the picture (--tracer; it needs the loaded scene).
    bool tracesOnCpu() const { return mCpuTracing && mLoaded; }
    /// What the CPU renderer draws for a width x height picture of the window's look (no colour bar).
    render::RenderOptions cpuOptions(int width, int height) const;
    /// The CPU's picture of a width x height window: a frame at the moving scale when the picture
    /// is stale, the full picture in the background once the camera rests (@a moving false), shown
    /// when it is done; true when the full picture was shown this call.
    bool traceOnCpu(int width, int height, bool moving);
    /// Whether the camera moves for the CPU's picture: during a drag, a wheel click's rest time or
    /// an eased camera; a released drag rests at once (its full picture is cancelled by a move).
    bool cameraMovesForCpu() const;
    /// Stops the CPU's resting picture before what it reads changes; the next rest draws it again.
    void stopCpuPicture();
    /// Fits the orbit's field of view to the picture of a width x height frame (the object alone
    /// until the volume is loaded); a picture that cannot be framed ends the framing, with a status.
    void frameOrbit(int width, int height);
    void renderFrame(int width, int height);
    /// Writes the picture shown (with its colour bar, in a margin at least @a legendMargin wide) to
    /// @a path and, unless empty, its regions to @a regionPath, into @a files (renamed into place
    /// when the caller commits them).
    void writeScreenshot(core::AtomicFileSet& files, const std::string& path, const std::string& regionPath,
                         int legendMargin = 0);
    /// Writes inversevis-view-<mesh>-<n>.png and reports it (or the error) in the panel.
    void takeNumberedScreenshot();
    /// Writes the view file of the picture shown (inversevis-view-<stem>-<n>.view.json).
    void saveView();
    /// Writes the window's back buffer (scene and panel) to @a path.
    void writeWindow(const std::string& path);
    int runHeadlessScreenshot();
    int runBenchmark();
    int runInteractive();
    /// The panel: the source's lines, then collapsible sections (method, colour, optimise and probe
    /// open; picture closed), the screenshot and view buttons and the status line.
    void drawPanel();
    /// The mesh, the time slider of a series and the loading bar, above the sections.
    void drawSourceLines();
    /// The optimiser's settings and buttons.
    void drawOptimiserSection();
    /// "colour by": the scalar opened with and every array of the file (of a series: of its first
    /// step; not of a pattern's steps); true when it changed.
    bool drawColourByCombo();
    /// Shows choice @a choice of mArrayChoices (-1: mOpenedScalar) and rescales the colours to its
    /// data; a series' steps are surveyed again in the background first (startSeriesColouring).
    void colourBy(int choice);
    /// The colour scale of choice @a choice over @a data: the opened one's own, else the range
    /// options' rules over the data (no fixed --range; no log scale where nothing is positive).
    core::ColorScale choiceDataScale(int choice, const std::vector<float>& data) const;
    /// Makes choice @a choice, whose data mField shows now, the one shown, with @a dataScale.
    void showChoice(int choice, const core::ColorScale& dataScale);
    /// Starts the background job that makes a copy of the series show choice @a choice and
    /// surveys its steps.
    void startSeriesColouring(int choice);
    /// Shows the surveyed series once its survey is done (its error goes to the status line).
    void pollSeriesColouring();
    /// The loading options that give choice @a choice of "colour by" (the opened options for it).
    core::SurfaceLoadOptions choiceLoad(int choice) const;
    /// The loading options that give the scalar shown (for a view file).
    core::SurfaceLoadOptions shownScalarLoad() const { return choiceLoad(mArrayChoice); }
    /// True while an optimiser or a series' survey runs in the background.
    bool jobRunning() const { return mJob.valid() || mColouring.valid(); }
    /// The units of the scalar shown: the opened scalar's, none for another.
    std::string shownUnits() const { return mArrayChoice == mOpenedChoice ? mOpenedUnits : std::string(); }
    /// Framing, camera, trace scales, frame time, volume and OpenGL renderer; true when the picture changed.
    bool drawPictureSection();
    void handleInput();
    /// Probes @a pixel of the picture last drawn (from its top left) into the panel and on stdout.
    void probeAt(const glm::ivec2& pixel);
    /// Eases the camera to the angles @a view on the radius-2.5 sphere around the origin, framed.
    void turnTo(const glm::dvec2& view);
    /// The CPU jobs the panel's buttons start.
    enum class Job { Parameters, View, ReadableRule };
    /// Runs @a job in the background.
    void startOptimiser(Job job);
    /// True when the method's rule for drawing rays is chosen, not given (--stable-shift, --view).
    bool choosesReadableRule() const;
    void pollOptimiser(double now);
    /// Eases the camera (and, when @a sameMethod, the method's optimised parameters) to @a view from @a time.
    void moveTo(const ViewState& view, bool sameMethod, double time);

    ViewerOptions mOptions;
    std::unique_ptr<core::SurfaceField> mField;  ///< heap: the scene and renderer keep its address
    std::vector<glm::vec3> mNormals;             ///< vertex normals of mField's mesh
    std::unique_ptr<core::ClusteredVertices> mVertices;  ///< mField's vertices, which framing scans before a scene loads
    std::unique_ptr<core::SurfaceSeries> mSeries;  ///< the time series shown (null for one surface)
    SeriesSurvey mSurvey;
    std::string mCacheFolder;  ///< where volumes are cached; "" when none can be written (optionalCacheFolder)
    std::size_t mStep = 0;                         ///< the step of mSeries shown
    bool mPlaying = false;                         ///< the series' steps follow each other (play)
    bool mLoop = false;                            ///< playing goes on from the last step to the first
    float mPlayRate = 0.0f;                        ///< steps per second while playing (--play-rate)
    double mNextStepTime = 0.0;                    ///< when playing shows the next step (seconds, now())
    render::MethodPtr mMethod;
    std::string mAnimatedMethod;  ///< the method whose parameters mAnimation eases
    render::ShadingOptions mShading;
    core::LegendSide mLegendSide = core::LegendSide::Right;
    /// The scalar the window opened with, when no array choice gives it (hot spots, --scalar-file, a
    /// cell array averaged): the first entry of "colour by" (of a series, without values: each step
    /// loads its own).
    struct OpenedScalar {
        std::vector<float> values;
        core::Association on = core::Association::Point;
        std::string name;
    };
    std::optional<OpenedScalar> mOpenedScalar;
    std::vector<core::ArrayChoice> mArrayChoices;  ///< what "colour by" offers (none for a pattern's steps)
    int mArrayChoice = -1;                         ///< the choice shown; -1: mOpenedScalar, or none
    int mOpenedChoice = -1;                        ///< the choice the window opened with
    core::ColorScale mOpenedScale, mOpenedDataScale;  ///< its scale and data scale (--range, a view file's)
    std::string mOpenedUnits;                      ///< its units (--units, a view file's): the others have none
    glm::ivec2 mPanelSize{0};  ///< the panel's size when last drawn, framebuffer pixels
    float mPanelDock = 0.0f;   ///< the open panel's right edge while at the window's top left (framebuffer pixels); 0 otherwise
    bool mShowLegend = true;   ///< the colour bar in its margin (--no-legend; the panel's checkbox)
    bool mOutline = true;      ///< the direct part's outline (--no-outline; the panel's checkbox)
    std::unique_ptr<ColorBarOverlay> mColorBar;  ///< created with the window
    core::ColorScale mDataScale;  ///< the colour scale the flags give over the data ("data" resets to it)
    OrbitCamera mOrbit;
    OptimiserSettings mOptimiser;

    GLFWwindow* mWindow = nullptr;
    bool mGlfwReady = false;
    bool mImGuiReady = false;
    std::string mGlRenderer;
    std::unique_ptr<GpuRenderer> mRenderer;
    bool mCpuTracing = false;    ///< the CPU renderer traces the picture (--tracer, software GL)
    CpuTracer mCpuTracer;        ///< its moving frames and resting pictures
    glm::ivec2 mCpuSize{0};      ///< the full size of the CPU's last picture
    bool mRestWanted = false;    ///< the CPU's full picture is still to be started once the camera rests
    double mRestStart = 0.0;     ///< when the resting picture started (seconds, now())
    std::unique_ptr<SceneLoader> mLoader;
    std::unique_ptr<LoadedScene> mLoaded;
    std::string mVolumeText;

    /// A series showing another choice of "colour by", what its steps hold and its step shown.
    struct SeriesColouring {
        std::unique_ptr<core::SurfaceSeries> series;
        SeriesSurvey survey;
        core::SurfaceField shown;
        int choice = -1;
    };
    /// The series' survey for "colour by", while it runs; it reads mCancelJob, so the destructor
    /// waits for it.
    std::future<SeriesColouring> mColouring;

    std::future<OptimiserResult> mJob;
    render::MethodPtr mJobMethod;  ///< the method the job started from
    std::vector<ViewState> mViewSet;  ///< the last "optimise view"'s several views (--views), the best first
    std::atomic<bool> mCancelJob{false};
    std::string mJobName;
    double mJobStart = 0.0;
    std::string mStatus;
    CameraAnimation mAnimation;

    bool mDirty = true;
    float mRenderScale = 1.0f;
    InteractionScale mInteraction;  ///< fewer pixels while the camera moves
    double mLastFrameMs = 0.0;
    int mScreenshots = 0;
    int mSavedViews = 0;
    PictureViewport mPicture;  ///< the picture's part of the window, last frame (framebuffer pixels)
    ProbePanel mProbe;         ///< the last pixel clicked
    bool mProbePending = false;  ///< --probe waits for the loaded volume and a settled camera
    int mColormapIndex = 0;
};

}  // namespace ivis::app
