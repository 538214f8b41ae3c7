// `shadowlab list`: every technique preset, part and parameter, and the builtin scenes — all
// printed from the same declarations that drive the UI and --set.
#include "cli/commands.h"
#include "gl/shader_library.h"
#include "render/renderer.h"
#include "technique.h"

#include <iomanip>
#include <iostream>

namespace sl {

static void printParams(const std::vector<ParamDecl>& decls) {
  for (const auto& d : decls) {
    // Columns are padded but never run together: a long key or range just pushes the rest right.
    std::cout << "    " << std::left << std::setw(22) << d.key << " " << std::setw(5) << paramTypeName(d.type) << " "
              << std::setw(24) << describeRange(d) << " default " << std::setw(9) << formatValue(d, d.defaultValue)
              << " " << d.help << (d.unit.empty() ? "" : " [" + d.unit + "]") << "\n";
  }
}

int runListCommand(int argc, char** argv) {
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--markdown") {
      if (i + 1 >= argc) {
        std::cerr << "shadowlab list --markdown: name a table (families, presets, parts, params:FAMILY)\n";
        return 2;
      }
      return runListMarkdown(argv[i + 1]);
    }
  std::cout << "techniques (--technique ID, any key below with --set key=value):\n";
  for (const auto& p : allPresets()) {
    std::cout << "  " << std::left << std::setw(18) << p.id << " " << p.help << "  [" << p.layout << " + "
              << p.representation << " + " << p.accumulation << "]\n";
    for (const auto& o : p.overrides) std::cout << "      preset sets " << o << "\n";
  }
  std::cout << "\nparameters of every technique:\n";
  printParams(commonParams());
  std::cout << "\nlayouts (where texels go):\n";
  for (const auto& l : allLayouts()) {
    std::cout << "  " << std::setw(16) << l->id() << " " << l->help() << "\n";
    printParams(l->params());
  }
  std::cout << "\nrepresentations (what a texel stores, how visibility is reconstructed):\n";
  for (const auto& r : allRepresentations()) {
    std::cout << "  " << std::setw(16) << r->id() << " " << r->help() << "\n";
    printParams(r->params());
    auto views = r->createState()->views();  // states make their GL objects on first use
    if (!views.empty()) {
      std::cout << "    debug views:";
      for (const auto& v : views) std::cout << " " << v;
      std::cout << "\n";
    }
  }
  std::cout << "\naccumulations (screen space over time):\n";
  for (const auto& a : allAccumulations()) {
    std::cout << "  " << std::setw(16) << a->id() << " " << a->help() << "\n";
    printParams(a->params());
    auto views = a->createState()->views();
    if (!views.empty()) {
      std::cout << "    debug views:";
      for (const auto& v : views) std::cout << " " << v;
      std::cout << "\n";
    }
  }
  std::cout << "\ndebug views of every technique (--view NAME; representations and accumulations add theirs, above; "
               "the explorer adds "
               "`error`):";
  for (const auto& v : commonViewNames()) std::cout << " " << v;
  std::cout << "\n\nscenes (--scene ID or a path to .json/.gltf/.glb):\n";
  try {
    for (const auto& id : builtinSceneIds(defaultAssetsDir())) std::cout << "  " << id << "\n";
  } catch (const std::exception& e) {
    std::cout << "  (cannot list scenes: " << e.what() << ")\n";
  }
  return 0;
}

}  // namespace sl
