#include "prefiltered/moment_views.h"
#include "part/part_view.h"

#include "gl/gl_util.h"
#include "gl/texture_units.h"
#include "part/frame_graph.h"

namespace sl {

std::vector<std::string> momentViewNames(bool hasVariance, bool fourier, bool soft) {
  std::vector<std::string> v = {"moments"};
  if (hasVariance) v.push_back("variance");
  if (fourier) v.push_back("fourier");
  if (soft) {
    v.push_back("blocker-depth");
    v.push_back("penumbra");
  }
  return v;
}

void addMomentViewPasses(FrameGraph& graph, const PartContext& ctx, const std::string& moments,
                         const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    auto it = ctx.viewTargets.find(name);
    if (it == ctx.viewTargets.end() || !it->second) continue;
    Texture2D* target = it->second;
    const std::string resource = "view." + name + ctx.viewportTag;
    if (name == "blocker-depth" || name == "penumbra") {
      // The soft ones' blocker estimate per G-buffer pixel (soft_moments_view.frag).
      const std::string defines = name == "penumbra" ? "#define SL_VIEW_PENUMBRA\n" : "";
      graph.add({resource, {moments, "gbuffer"}, {resource}, [ctx, target, defines] {
                   drawPartView(ctx, target, "representations/prefiltered/soft_moments_view.frag",
                                {.defines = defines, .withGBuffer = true});
                 }});
      graph.requestSink(resource);
      continue;
    }
    // The view shader includes the technique's modules through the same prelude as the
    // visibility passes (ctx.bindTechnique binds the moment targets and the parameters).
    std::string defines = name == "variance"  ? "#define SL_VIEW_VARIANCE\n"
                          : name == "fourier" ? "#define SL_VIEW_SIGNED\n"
                                              : "";
    graph.add({resource, {moments}, {resource}, [ctx, target, defines] {
                 drawPartView(ctx, target, "views/moments.frag", {.defines = defines});
               }});
    graph.requestSink(resource);
  }
}

}  // namespace sl
