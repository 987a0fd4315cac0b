#include "python_call.h"

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

namespace py = pybind11;

namespace ivis::python {
namespace {

/// Cancels on Ctrl-C (the scoped handler's flag) or when the callback raised; reports each new
/// percent of a stage to the callback, taking the GIL for it.
class PythonInterrupter final : public core::Interrupter {
public:
    PythonInterrupter(const py::object& progress, bool watchesCtrlC) : mProgress(progress), mWatchesCtrlC(watchesCtrlC) {}

    void start(const char* name) override
    {
        std::lock_guard<std::mutex> lock(mMutex);
        mStage = name ? name : "";
        mPercent = -1;
    }
    bool wasInterrupted(int percent) override
    {
        if (mFailed || (mWatchesCtrlC && core::interruptRequested())) return true;
        if (mProgress.is_none() || percent < 0) return false;
        std::lock_guard<std::mutex> lock(mMutex);
        if (percent == mPercent) return false;
        mPercent = percent;
        py::gil_scoped_acquire gil;
        try {
            mProgress(mStage, percent);
        } catch (py::error_already_set& e) {
            mError = std::make_unique<py::error_already_set>(std::move(e));
            mFailed = true;
        }
        return mFailed.load();
    }
    /// Rethrows what the callback raised, if anything (with the GIL held).
    void rethrowCallbackError()
    {
        if (mError) throw *mError;
    }

private:
    const py::object& mProgress;
    bool mWatchesCtrlC;
    std::mutex mMutex;
    std::string mStage;
    int mPercent = -1;
    std::atomic<bool> mFailed{false};
    std::unique_ptr<py::error_already_set> mError;
};

/// Whether the calling thread is Python's main thread (the one Ctrl-C interrupts).
bool onMainThread()
{
    const py::module_ threading = py::module_::import("threading");
    return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

}  // namespace

void runReleased(const std::function<void(core::Interrupter&)>& work, const py::object& progress)
{
    if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
        throw py::type_error("progress must be None or a callable (stage: str, percent: int)");
    const bool mainThread = onMainThread();
    PythonInterrupter interrupter(progress, mainThread);
    bool interrupted = false;
    std::exception_ptr failure;
    {
        std::unique_ptr<core::ScopedInterruptHandler> ctrlC;
        if (mainThread) ctrlC = std::make_unique<core::ScopedInterruptHandler>();
        py::gil_scoped_release released;
        try {
            work(interrupter);
        } catch (const Cancelled&) {
            interrupted = true;
        } catch (...) {
            failure = std::current_exception();
        }
        interrupted = interrupted || (mainThread && core::interruptRequested());
    }
    interrupter.rethrowCallbackError();
    if (failure) std::rethrow_exception(failure);
    if (interrupted) {
        PyErr_SetNone(PyExc_KeyboardInterrupt);
        throw py::error_already_set();
    }
}

}  // namespace ivis::python
