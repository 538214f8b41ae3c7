// The point-light family's manifest (issue #25): the cube and tetrahedron layouts and their
// presets; the depth representations and accumulations of the other families combine with them by
// name.
#include "part/family.h"
#include "point/light_faces.h"

namespace sl {

Family pointFamily() {
  Family f{.id = "point",
           .summary =
               "point lights: a cube of six or a tetrahedron of four fitted faces, drawn only where the view needs "
               "them (survey: fitting for a point light; Gerasimov 2004, omnidirectional shadow mapping; Liao 2010, "
               "tetrahedron shadow mapping)"};
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
  };
  return f;
}

}  // namespace sl
