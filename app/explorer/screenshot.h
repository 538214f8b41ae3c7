// PNG captures of the whole explorer window (UI included), for slides and bug reports.
#pragma once

#include <string>

namespace sl {

// Reads the default framebuffer's back buffer (call after drawing, before swapping buffers)
// and writes it as an RGB PNG with the top row first. Returns "" or what went wrong.
std::string writeWindowPng(int framebufferWidth, int framebufferHeight, const std::string& path);

// "shadowlab-20240131-154502.png": local time, so a series of captures sorts in order.
std::string timestampedScreenshotName();

}  // namespace sl
