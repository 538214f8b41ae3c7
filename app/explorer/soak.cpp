#include "explorer/soak.h"

#include "gl/gl_util.h"
#include "technique.h"

#include <epoxy/gl.h>
#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace sl {

namespace {

constexpr int kFramesPerAction = 3;         // each state is drawn a few times (history, reloads)
constexpr double kShaderWaitSeconds = 8.0;  // hot reload polls every 0.25 s; shader builds are slow here
// A file most techniques include, so that breaking it is noticed whatever is shown.
const char* const kBrokenShader = "common/shading.glsl";

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeAll(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

}  // namespace

long residentKiB() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  return -1;
}

long heldKiB() {
  // Free heap pages go back to the system first, so the number is what is held, not what
  // glibc keeps cached after a large texture was freed (its mmap threshold adapts upwards).
  malloc_trim(0);
  return residentKiB();
}

SoakDriver::SoakDriver(double seconds, const std::string& shaderDir) : seconds_(seconds) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path source = fs::weakly_canonical(fs::path(SHADOWLAB_SOURCE_DIR) / "shaders", ec);
  const fs::path used = fs::weakly_canonical(shaderDir, ec);
  brokenFile_ = (fs::path(shaderDir) / kBrokenShader).string();
  canBreak_ = used != source && fs::exists(brokenFile_);
  if (!canBreak_)
    std::cout << "soak: shaders are the source tree's (or lack " << kBrokenShader
              << "): the break/fix step is skipped; pass --shaders COPY to include it\n";
  glErrorsAtStart_ = glDebugErrorCount();
}

void SoakDriver::fail(const std::string& what) {
  if (failures_.size() < 50) failures_.push_back(what);
  std::cerr << "soak: FAILURE: " << what << "\n";
}

void SoakDriver::breakShader() {
  original_ = readAll(brokenFile_);
  writeAll(brokenFile_, original_ + "\nthis is not GLSL +;\n");
  broken_ = true;
}

void SoakDriver::fixShader() {
  writeAll(brokenFile_, original_);
  broken_ = false;
}

void SoakDriver::nextAction(ExplorerState& state, Renderer& renderer) {
  const std::vector<Preset>& presets = allPresets();
  switch (step_ % kActionKinds) {
    case 0:  // every preset in turn, in the first viewport
      setViewportPreset(state, 0, presets[presetIndex_++ % presets.size()].id);
      if (!state.slots[0].error.empty()) fail("preset: " + state.slots[0].error);
      break;
    case 1: {  // 1 to 4 viewports
      static const int counts[] = {1, 2, 4, 3};
      state.viewportCount = counts[viewportStep_++ % 4];
      ensureViewportSlots(state);
      break;
    }
    case 2:  // the next debug view in every viewport's big image
      cycleEnlargedView(state, 1);
      break;
    case 3:  // every builtin scene in turn (a missing shared file is reported, not fatal)
      if (!state.sceneIds.empty()) {
        const std::string id = state.sceneIds[sceneIndex_++ % state.sceneIds.size()];
        if (!switchScene(state, renderer, id))
          std::cout << "soak: scene " << id << " not loaded: " << state.sceneError << "\n";
      }
      break;
    case 4:
      if (canBreak_) breakShader();
      break;
  }
  ++action_;
  ++step_;
}

bool SoakDriver::cycleCompleted(size_t sceneCount) {
  // Every preset and every scene shown once (each kind of action comes every kActionKinds
  // steps); the counters start again, so each cycle repeats the first one's states exactly.
  if (step_ < kActionKinds * std::max(allPresets().size(), sceneCount)) return false;
  step_ = presetIndex_ = sceneIndex_ = viewportStep_ = 0;
  ++cycles_;
  return true;
}

void SoakDriver::goToBaseline(ExplorerState& state, Renderer& renderer) {
  state.viewportCount = 1;
  ensureViewportSlots(state);
  setViewportPreset(state, 0, allPresets().front().id);
  state.selectedViews.clear();
  applySelectedViews(state);
  if (!state.sceneIds.empty() && state.sceneLabel != state.sceneIds.front())
    switchScene(state, renderer, state.sceneIds.front());
  sampling_ = true;
  framesInAction_ = 0;
}

void SoakDriver::takeSampleWhenSettled(const ShaderLibrary& shaders) {
  if (++framesInAction_ < kFramesPerAction) return;
  const long rss = heldKiB();
  (rssStart_ < 0 ? rssStart_ : rssEnd_) = rss;
  std::printf(
      "soak: cycle %zu (every preset and scene) ended at frame %d; %zu shader programs; RSS in the "
      "baseline state %.1f MiB\n",
      cycles_, frames_, shaders.programCount(), rss / 1024.0);
  sampling_ = false;
  framesInAction_ = 0;
}

void SoakDriver::beforeFrame(ExplorerState& state, Renderer& renderer, const ShaderLibrary& shaders, double now) {
  if (start_ < 0) start_ = actionStart_ = now;
  if (broken_) {
    // Wait for the error to be reported, then fix it; the window must keep drawing meanwhile.
    if (!shaders.errors().empty()) {
      fixShader();
      actionStart_ = now;
    } else if (now - actionStart_ > kShaderWaitSeconds) {
      fail(std::string("broken ") + kBrokenShader + " was not reported within 8 s");
      fixShader();
    }
    return;
  }
  if (!shaders.errors().empty()) {
    if (now - actionStart_ > kShaderWaitSeconds) {
      fail("shader errors remain after the fix: " + shaders.errors().front());
      actionStart_ = now;
    }
    return;
  }
  if (sampling_) {
    takeSampleWhenSettled(shaders);
    return;
  }
  if (now - start_ >= seconds_) {
    done_ = true;
    return;
  }
  if (++framesInAction_ < kFramesPerAction) return;
  framesInAction_ = 0;
  actionStart_ = now;
  nextAction(state, renderer);
  if (cycleCompleted(state.sceneIds.size())) goToBaseline(state, renderer);
}

void SoakDriver::afterFrame(const ExplorerState& state) {
  ++frames_;
  rssPeak_ = std::max(rssPeak_, residentKiB());
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", e);
    fail(std::string("glGetError ") + hex + " after frame " + std::to_string(frames_));
  }
  if (glDebugErrorCount() > glErrorsAtStart_) {
    fail("GL debug output reported " + std::to_string(glDebugErrorCount() - glErrorsAtStart_) + " error(s) by frame " +
         std::to_string(frames_));
    glErrorsAtStart_ = glDebugErrorCount();
  }
  // While a shader is broken the last good program keeps drawing, so a failed frame is a bug.
  if (!state.renderError.empty() && !broken_) fail("frame " + std::to_string(frames_) + ": " + state.renderError);
}

int SoakDriver::finish() {
  if (broken_) fixShader();  // never leave the copy broken
  std::printf("soak: %d actions, %d frames, %zu of %zu presets shown, %zu full cycles\n", action_, frames_,
              cycles_ > 0 ? allPresets().size() : presetIndex_, allPresets().size(), cycles_);
  if (rssEnd_ < 0) {
    // Not a pass by default: the report says plainly that the bound was not applied.
    std::printf(
        "soak: RSS at the end %.1f MiB, peak %.1f MiB; growth not judged: it needs two full cycles (the first "
        "is the warm-up; scripts/soak.sh 6 is long enough)\n",
        heldKiB() / 1024.0, rssPeak_ / 1024.0);
  } else {
    const long growth = rssEnd_ - rssStart_;
    std::printf(
        "soak: RSS after the first cycle %.1f MiB, after the last %.1f MiB (growth %+.1f MiB, bound %.0f MiB), "
        "peak %.1f MiB\n",
        rssStart_ / 1024.0, rssEnd_ / 1024.0, growth / 1024.0, kRssGrowthBoundKiB / 1024.0, rssPeak_ / 1024.0);
    if (growth > kRssGrowthBoundKiB) fail("resident memory grew by more than the bound");
  }
  std::printf("soak: %s\n",
              failures_.empty() ? "PASSED" : ("FAILED (" + std::to_string(failures_.size()) + ")").c_str());
  return failures_.empty() ? 0 : 1;
}

}  // namespace sl
