// The `cascades` debug view: which split's map each pixel reads, for teaching where the texel
// density steps and where the blend bands hide the steps.
#include "gl/gl_util.h"
#include "part/part_view.h"
#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "layouts/cascaded.h"
#include "part/frame_graph.h"

namespace sl {

void addCascadesViewPass(FrameGraph& graph, const PartContext& ctx) {
  auto it = ctx.viewTargets.find("cascades");
  if (it == ctx.viewTargets.end() || !it->second) return;
  Texture2D* target = it->second;
  const std::string res = "view.cascades" + ctx.viewportTag;
  graph.add({res, {"gbuffer"}, {res}, [ctx, target] {
               drawPartView(ctx, target, "views/cascades.frag", {.withGBuffer = true});
             }});
  graph.requestSink(res);
}

}  // namespace sl
