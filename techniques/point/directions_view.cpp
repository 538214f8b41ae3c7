#include "point/directions_view.h"

#include "gl/gl_util.h"
#include "gl/texture_units.h"
#include "part/colour_key.h"
#include "part/frame_graph.h"
#include "part/part_view.h"

namespace sl {

void addDirectionsViewPass(FrameGraph& graph, const PartContext& ctx) {
  auto it = ctx.viewTargets.find("directions");
  if (it == ctx.viewTargets.end() || !it->second) return;
  Texture2D* target = it->second;
  const std::string res = "view.directions" + ctx.viewportTag;
  // Reads this frame's shadow map: after the shadow pass.
  graph.add({res, {ctx.shadowMap}, {res}, [ctx, target] {
               const Texture2D* depth = ctx.shadowDepth ? ctx.shadowDepth() : nullptr;
               if (!depth) return;
               drawPartView(ctx, target, "views/light_directions.frag",
                            {.bind = [depth](const Program& p, TextureUnits& units) {
                              units.bind(p, "u_shadowDepth", depth->id());
                            }});
             }});
  graph.requestSink(res);
}

// The tints are shaders/views/light_directions.frag's kViewTints.
void addDirectionsViewKey(std::map<std::string, ColourKey>& keys) {
  keys["directions"] = {"every direction from the light (x: azimuth, y: elevation), the view that holds it",
                        "",
                        {},
                        {{{0.90f, 0.30f, 0.25f}, "view 1 (cube +X, tetrahedron down, paraboloid down)"},
                         {{0.95f, 0.75f, 0.20f}, "view 2"},
                         {{0.35f, 0.75f, 0.30f}, "view 3"},
                         {{0.25f, 0.55f, 0.90f}, "view 4"},
                         {{0.65f, 0.40f, 0.85f}, "view 5"},
                         {{0.30f, 0.80f, 0.80f}, "view 6"},
                         {{0.18f, 0.18f, 0.18f}, "dark grey: outside every fitted window"},
                         {{0.05f, 0.05f, 0.05f}, "hatched: cleared, nothing drawn"}},
                        "darker = farther from the light; white lines: texel edges where a texel spans 3+ pixels"};
}

}  // namespace sl
