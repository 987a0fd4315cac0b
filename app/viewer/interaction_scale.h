/// @file interaction_scale.h
/// @brief Fewer pixels while the camera moves: the viewer's level of detail during interaction,
///        as ParaView renders at a reduced resolution while the mouse moves the camera.
#pragma once

#include <algorithm>

namespace ivis::app {

/// @brief While the user orbits, pans or zooms, the viewer traces only a fraction of its render
///        scale; the full picture follows once the camera rests: when the drag ends and
///        kRestSeconds have passed since the last move (a wheel click has no release), or, for a
///        full picture that a move cancels at once (the CPU tracer's), when the drag ends.
class InteractionScale {
public:
    /// Seconds after the last camera move before a camera without a drag counts as resting.
    static constexpr double kRestSeconds = 0.3;

    /// Fraction of the render scale traced while the camera moves, in [0.25, 1] (1: always the
    /// full render scale).
    float reduction = 1.0f;

    /// @brief The user moved the camera at @a now (seconds), by a drag or by the wheel.
    void moved(double now, bool dragging)
    {
        mLastMove = now;
        mDragging = dragging;
        mLastMoveDragged = dragging;
    }
    /// @brief Every mouse button is up: a drag has ended.
    void released() { mDragging = false; }
    /// @brief Whether the camera counts as moving at @a now.
    bool moving(double now) const { return mDragging || now - mLastMove < kRestSeconds; }
    /// @brief Whether the camera counts as moving at @a now for a full picture that the next move
    ///        cancels at once: as moving(), but a released drag rests at once (the user let go).
    bool movingBeforeCancellableRest(double now) const
    {
        return mDragging || (!mLastMoveDragged && now - mLastMove < kRestSeconds);
    }
    /// @brief Seconds from @a now until the camera rests by the rest time (0 once it has; a drag
    ///        held still rests only when released, so it has none).
    double secondsUntilRest(double now) const
    {
        return mDragging ? kRestSeconds : std::max(0.0, kRestSeconds - (now - mLastMove));
    }
    /// @brief The fraction of the picture's pixels to trace at @a now, given the full @a renderScale.
    float scale(float renderScale, double now) const { return moving(now) ? renderScale * reduction : renderScale; }

private:
    double mLastMove = -1.0e9;
    bool mDragging = false;
    bool mLastMoveDragged = false;  ///< whether the last move was a drag's (not a wheel click's)
};

}  // namespace ivis::app
