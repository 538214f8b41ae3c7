// PNG captures of the explorer: the whole window (UI included) for bug reports, and each
// viewport's image alone (no UI chrome) for slides; both into one folder outside the repository.
#pragma once

#include <string>

namespace sl {

class Texture2D;

// Reads the default framebuffer's back buffer (call after drawing, before swapping buffers)
// and writes it as an RGB PNG with the top row first. Returns "" or what went wrong.
std::string writeWindowPng(int framebufferWidth, int framebufferHeight, const std::string& path);
// Writes a colour texture (a viewport's image or debug view) as an RGB PNG, top row first.
std::string writeTexturePng(const Texture2D& texture, const std::string& path);

// "shadowlab-20240131-154502.png": local time, so a series of captures sorts in order.
std::string timestampedScreenshotName();
// The same stamp with another suffix: "shadowlab-20240131-154502" + suffix.
std::string timestampedName(const std::string& suffix);

// Where captures and exports go by default: $XDG_PICTURES_DIR/shadowlab, else
// ~/Pictures/shadowlab, else /tmp/shadowlab; never the working directory (scripts/run.sh starts
// in the repository). `env` reads a variable (getenv by default; tests pass their own).
std::string defaultScreenshotDir(const char* (*env)(const char*) = nullptr);
// Creates `dir` (and parents) if needed; returns "" or the problem, naming the folder.
std::string ensureFolder(const std::string& dir);
// Writes text to dir/name atomically enough for exports (temporary file + rename). Returns the
// full path written, or throws std::runtime_error naming the file.
std::string writeTextFile(const std::string& dir, const std::string& name, const std::string& text);

}  // namespace sl
