// `shadowlab list --markdown TABLE`: the tables the README and docs/architecture.md quote (between
// `<!-- generated: shadowlab list --markdown TABLE -->` markers, checked by scripts/doc-tables.py),
// written from the same declarations as the panel, --set and `list`: nothing typed twice.
#include "cli/commands.h"
#include "technique.h"

#include <iostream>
#include <string>

namespace sl {

namespace {

// A table cell: pipes escaped, so help texts cannot break the table.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string joined(const std::vector<std::string>& items, const std::string& sep = ", ") {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : sep) + i;
  return out;
}

template <typename Part>
std::vector<std::string> idsOf(const std::vector<std::unique_ptr<Part>>& parts) {
  std::vector<std::string> ids;
  for (const auto& p : parts) ids.push_back("`" + p->id() + "`");
  return ids;
}

void familiesTable() {
  std::cout << "| family | layouts | representations | accumulations | presets | what it holds |\n"
               "|---|---|---|---|---:|---|\n";
  for (const Family& f : allFamilies())
    std::cout << "| `techniques/" << f.id << "/` | " << joined(idsOf(f.layouts)) << " | "
              << joined(idsOf(f.representations)) << " | " << joined(idsOf(f.accumulations)) << " | "
              << f.presets.size() << " | " << cell(f.summary) << " |\n";
}

void presetsTable() {
  std::cout << "| preset | layout | representation | accumulation | preset sets | what it is |\n"
               "|---|---|---|---|---|---|\n";
  for (const Preset& p : allPresets())
    std::cout << "| `" << p.id << "` | " << p.layout << " | " << p.representation << " | " << p.accumulation << " | "
              << cell(joined(p.overrides)) << " | " << cell(p.help) << " |\n";
}

// Every part with its family, parameters and debug views.
void partsTable() {
  std::cout << "| part | kind | family | parameters | debug views |\n|---|---|---|---|---|\n";
  auto keys = [](const std::vector<ParamDecl>& decls) {
    std::vector<std::string> k;
    for (const auto& d : decls) k.push_back("`" + d.key + "`");
    return joined(k);
  };
  for (const Family& f : allFamilies()) {
    for (const auto& l : f.layouts)
      std::cout << "| `" << l->id() << "` | layout | " << f.id << " | " << keys(l->params()) << " | "
                << joined(l->createState()->views()) << " |\n";
    for (const auto& r : f.representations)
      std::cout << "| `" << r->id() << "` | representation | " << f.id << " | " << keys(r->params()) << " | "
                << joined(r->createState()->views()) << " |\n";
    for (const auto& a : f.accumulations)
      std::cout << "| `" << a->id() << "` | accumulation | " << f.id << " | " << keys(a->params()) << " | "
                << joined(a->createState()->views()) << " |\n";
  }
}

}  // namespace

int runListMarkdown(const std::string& table) {
  if (table == "families")
    familiesTable();
  else if (table == "presets")
    presetsTable();
  else if (table == "parts")
    partsTable();
  else {
    std::cerr << "shadowlab list --markdown: no table '" << table << "' (tables: families, presets, parts)\n";
    return 2;
  }
  return 0;
}

}  // namespace sl
