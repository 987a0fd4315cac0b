/// @file frame_video.h
/// @brief Numbered frame files and the MP4 that `ffmpeg`, when it is on PATH, makes of them
///        (ffmpeg is not a dependency: without it the frames are written alone).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace ivis::app {

/// @brief Digits of a frame number in a series of @a count frames: 4, or more when needed.
int frameDigits(std::size_t count);

/// @brief The file of frame @a index of @a count for the output @a path: "_" and the index in
///        frameDigits(count) digits before the extension ("out.png" -> "out_0003.png").
std::string framePath(const std::string& path, std::size_t index, std::size_t count);

/// @brief The video beside the frames of @a path: its extension replaced by ".mp4" ("out.png" -> "out.mp4").
std::string videoPath(const std::string& path);

/// @brief The `ffmpeg` program found on PATH, if any.
std::optional<std::string> findFfmpeg();

/// @brief Runs @a ffmpeg to encode the frames of @a path (framePath's names, 0 to @a count - 1, and
///        no more even when older frames follow) at
///        @a fps frames per second into an H.264 (or ffmpeg's default) MP4 at @a video, written
///        through a temporary file.
/// @return "" when the video was written, else why not (ffmpeg's last line of error)
std::string writeVideo(const std::string& ffmpeg, const std::string& path, std::size_t count, double fps,
                       const std::string& video);

}  // namespace ivis::app
