// The point-light family's manifest (issue #25): the cube, tetrahedron and dual-paraboloid layouts
// and their presets; the depth representations and accumulations of the other families combine
// with them by name.
#include "part/family.h"
#include "point/directions_view.h"
#include "point/point_layout.h"

namespace sl {

Family pointFamily() {
  Family f{.id = "point",
           .summary =
               "point lights: a cube of six fitted faces (in six layers, or one atlas sized by need) or a "
               "tetrahedron of four (fitted, or Liao's four packed into one layer), or two paraboloid hemispheres, "
               "drawn only where the view needs them (survey: fitting for a "
               "point light; Gerasimov 2004, omnidirectional shadow "
               "mapping; Liao 2010, "
               "tetrahedron shadow mapping; Brabec, Annen & Seidel 2002, dual-paraboloid shadow maps)"};
  registerPointLayouts(f.layouts);
  f.presets = {
      // 6 x 1024² faces: 1.5 times the texels of one 2048² map (measured on street: README). Both
      // faces of every caster: a light inside a closed caster sees only its back faces.
      {"cube",
       "point light: cube shadow map of 6 x 1024² faces, each fitted to the view, nearest depth test",
       "cube",
       "depth-nearest",
       "none",
       {"shadowmap.size=1024", "shadowmap.cull=both"}},
      {"cube-pcf",
       "point light: cube shadow map (6 x 1024²) with 3x3 box PCF in each face",
       "cube",
       "depth-pcf",
       "none",
       {"pcf.kernel=3", "shadowmap.size=1024", "shadowmap.cull=both"}},
      // One 2508² atlas: the six 1024² faces' texels within 0.01 %, shared by the faces' needs.
      {"cube-atlas",
       "point light: the cube's six fitted faces in one 2508² atlas (the cube's texels), each face's square sized "
       "by its screen footprint, nearest depth test",
       "cube-atlas",
       "depth-nearest",
       "none",
       {"shadowmap.size=2508", "shadowmap.cull=both"}},
      // 4 x 1254² faces: the cube's texels (6 x 1024²) within 0.03 %, the equal-texel
      // comparison.
      {"tetrahedron",
       "point light: tetrahedron shadow map of 4 x 1254² faces (the cube's texels), each fitted to the view, "
       "nearest depth test",
       "tetrahedron",
       "depth-nearest",
       "none",
       {"shadowmap.size=1254", "shadowmap.cull=both"}},
      {"tetrahedron-pcf",
       "point light: tetrahedron shadow map (4 x 1254²) with 3x3 box PCF in each face",
       "tetrahedron",
       "depth-pcf",
       "none",
       {"pcf.kernel=3", "shadowmap.size=1254", "shadowmap.cull=both"}},
      // One 2508² layer: exactly the four 1254² layers' texels, each face a quarter of it.
      {"tetrahedron-packed",
       "point light: Liao's tetrahedron map, four faces packed into triangles of one 2508² layer (the cube's "
       "texels), nearest depth test",
       "tetrahedron-packed",
       "depth-nearest",
       "none",
       {"shadowmap.size=2508", "shadowmap.cull=both"}},
      {"tetrahedron-packed-pcf",
       "point light: Liao's packed tetrahedron map (one 2508² layer) with 3x3 box PCF",
       "tetrahedron-packed",
       "depth-pcf",
       "none",
       {"pcf.kernel=3", "shadowmap.size=2508", "shadowmap.cull=both"}},
      // 2 x 1773²: the cube's texels within 0.07 %.
      {"dual-paraboloid",
       "point light: dual-paraboloid shadow map of 2 x 1773² hemispheres (the cube's texels), casters "
       "tessellated, nearest depth test",
       "dual-paraboloid",
       "depth-nearest",
       "none",
       {"shadowmap.size=1773", "shadowmap.cull=both"}},
      {"dual-paraboloid-pcf",
       "point light: dual-paraboloid shadow map (2 x 1773²) with 3x3 box PCF",
       "dual-paraboloid",
       "depth-pcf",
       "none",
       {"pcf.kernel=3", "shadowmap.size=1773", "shadowmap.cull=both"}},
  };
  addDirectionsViewKey(f.viewKeys);
  return f;
}

}  // namespace sl
