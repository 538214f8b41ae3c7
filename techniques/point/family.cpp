// The point-light family's manifest (issue #25): the cube layout and its presets; the depth
// representations and accumulations of the other families combine with it by name.
#include "part/family.h"
#include "point/cube_layout.h"

namespace sl {

Family pointFamily() {
  Family f{.id = "point",
           .summary =
               "point lights: a cube of six fitted faces, drawn only where the view needs them (survey: "
               "fitting for a point light; Gerasimov 2004, omnidirectional shadow mapping)"};
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
  };
  return f;
}

}  // namespace sl
