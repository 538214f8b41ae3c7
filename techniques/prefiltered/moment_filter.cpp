// The filter passes of the moment maps: a separable box blur (two fullscreen passes per layer,
// through a scratch target) or a mip chain built by 2x2 box downsampling. Both filter in log
// space for ESM (SL_MOMENT_LOG_FILTER) and drop non-finite taps, so one broken texel cannot
// spread into a lit or black square.
#include "gl/texture_units.h"
#include "prefiltered/moment_state.h"

namespace sl {

namespace {

std::string filterDefines(const MomentConfig& c, bool logFilter) {
  return "#define SL_MOMENT_TARGETS " + std::to_string(c.targets()) + "\n" +
         (logFilter ? "#define SL_MOMENT_LOG_FILTER\n" : "");
}

void bindSources(const Program& p, TextureUnits& units, const std::vector<const Texture2D*>& src) {
  for (size_t t = 0; t < src.size(); ++t) units.bind(p, "u_src" + std::to_string(t), src[t]->id());
}

std::vector<const Texture2D*> pointers(const std::vector<Texture2D>& v) {
  std::vector<const Texture2D*> out;
  for (const auto& t : v) out.push_back(&t);
  return out;
}

std::vector<const Texture2D*> pointers(const std::vector<Texture2D*>& v) { return {v.begin(), v.end()}; }

}  // namespace

void MomentMapState::filter(ShaderLibrary& shaders, const std::function<void()>& drawFullscreen,
                            const std::vector<Texture2D*>& scratch) {
  if (config_.method == FilterMethod::Sat) return buildSat(shaders);
  const bool mips = config_.method == FilterMethod::Mipmap;
  const ProgramSpec spec{mips ? "moment downsample" : "moment blur",
                         {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                          {GL_FRAGMENT_SHADER, mips ? "passes/moment_downsample.frag" : "passes/moment_blur.frag"}},
                         filterDefines(config_, spec_.logFilter)};
  Program& p = shaders.get(spec);
  if (!p.valid()) return;
  p.use();
  if (spec_.logFilter) p.set("u_logExponent", logExponent_);
  const int layers = std::max(depth_.layers(), 1);
  if (!mips) {
    p.set("u_width", static_cast<float>(config_.width));
    for (int l = 0; l < layers; ++l) {
      p.set("u_layer", l);
      for (int pass = 0; pass < 2; ++pass) {
        // Horizontal into the scratch targets, then vertical back into the moments.
        const std::vector<const Texture2D*> src = pass == 0 ? pointers(moments_) : pointers(scratch);
        Framebuffer fbo("moment blur");
        fbo.attachLayer(pass == 0 ? pointers(scratch) : pointers(moments_), nullptr, l);
        fbo.bind();
        TextureUnits units;
        bindSources(p, units, src);
        p.set("u_direction", pass == 0 ? glm::vec2(1, 0) : glm::vec2(0, 1));
        drawFullscreen();
      }
    }
    return;
  }
  const int levels = moments_.front().levels();
  for (int level = 1; level < levels; ++level) {
    // Reading level-1 while level is attached is only defined when the sampled range excludes
    // the attached level: restrict every target to its source level for this step.
    for (auto& m : moments_) {
      glTextureParameteri(m.id(), GL_TEXTURE_BASE_LEVEL, level - 1);
      glTextureParameteri(m.id(), GL_TEXTURE_MAX_LEVEL, level - 1);
    }
    for (int l = 0; l < layers; ++l) {
      p.set("u_layer", l);
      Framebuffer fbo("moment mip");
      fbo.attachLayer(pointers(moments_), nullptr, l, level);
      fbo.bind();
      TextureUnits units;
      bindSources(p, units, pointers(moments_));
      drawFullscreen();
    }
  }
  for (auto& m : moments_) {
    glTextureParameteri(m.id(), GL_TEXTURE_BASE_LEVEL, 0);
    glTextureParameteri(m.id(), GL_TEXTURE_MAX_LEVEL, levels - 1);
  }
}

}  // namespace sl
