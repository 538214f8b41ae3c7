// The point-light family's manifest (issue #25): the cube layout and its presets; the depth
// representations and accumulations of the other families combine with it by name.
#include "part/family.h"
#include "point/cube_layout.h"

namespace sl {

Family pointFamily() {
  Family f{.id = "point",
           .summary = "point lights: a cube of six fitted faces, drawn only where the view needs them (survey: "
                      "fitting for a point light; Gerasimov 2004, omnidirectional shadow mapping)"};
  registerPointLayouts(f.layouts);
  f.presets = {
      {"cube", "point light: cube shadow map, each face fitted to the view, nearest depth test", "cube",
       "depth-nearest", "none", {}},
      {"cube-pcf", "point light: cube shadow map with 3x3 box PCF in each face", "cube", "depth-pcf", "none",
       {"pcf.kernel=3"}},
  };
  return f;
}

}  // namespace sl
