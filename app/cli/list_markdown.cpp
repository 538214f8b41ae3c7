// `shadowlab list --markdown TABLE`: the tables the README, docs/architecture.md and each family's
// README quote (between
// `<!-- generated: shadowlab list --markdown TABLE -->` markers, checked by scripts/doc-tables.py),
// written from the same declarations as the panel, --set and `list`: nothing typed twice.
#include "cli/commands.h"
#include "technique.h"

#include <algorithm>
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

// One family's parameters: a row per distinct declaration (a key that two parts declare alike
// is one row naming both), with the values the family's presets set, so a family's README never
// types its parameters again. Pipes in ranges ("a|b") become ", " to read as a list.
struct ParamRow {
  ParamDecl decl;  // a copy: parts return their declarations by value
  std::vector<std::string> parts;
};

bool sameDeclaration(const ParamDecl& a, const ParamDecl& b) {
  return a.key == b.key && a.type == b.type && describeRange(a) == describeRange(b) &&
         formatValue(a, a.defaultValue) == formatValue(b, b.defaultValue) && a.unit == b.unit && a.help == b.help;
}

void addParamRows(std::vector<ParamRow>& rows, const std::string& part, const std::vector<ParamDecl>& decls) {
  for (const ParamDecl& d : decls) {
    auto same = std::find_if(rows.begin(), rows.end(), [&](const ParamRow& r) { return sameDeclaration(r.decl, d); });
    if (same != rows.end())
      same->parts.push_back("`" + part + "`");
    else
      rows.push_back({d, {"`" + part + "`"}});
  }
}

std::string presetsSetting(const Family& family, const std::string& key) {
  std::vector<std::string> set;
  for (const Preset& p : family.presets)
    for (const std::string& o : p.overrides)
      if (o.rfind(key + "=", 0) == 0) set.push_back("`" + p.id + "`: " + o.substr(key.size() + 1));
  return joined(set);
}

std::string listedRange(const ParamDecl& d) {
  std::string r = describeRange(d);
  std::string out;
  for (char c : r) out += c == '|' ? std::string(", ") : std::string(1, c);
  return out;
}

void paramsTable(const std::vector<ParamRow>& rows, const Family* family) {
  std::cout << "| key | values | default | presets set | parts | meaning |\n|---|---|---|---|---|---|\n";
  for (const ParamRow& row : rows) {
    const ParamDecl& d = row.decl;
    std::cout << "| `" << d.key << "` | " << cell(listedRange(d)) << (d.unit.empty() ? "" : " " + d.unit) << " | "
              << cell(formatValue(d, d.defaultValue)) << " | " << cell(family ? presetsSetting(*family, d.key) : "")
              << " | " << joined(row.parts) << " | " << cell(d.help) << " |\n";
  }
}

int familyParamsTable(const std::string& id) {
  if (id == "common") {  // what every technique has (techniques/registry.cpp), in no family
    std::vector<ParamRow> rows;
    addParamRows(rows, "every technique", commonParams());
    paramsTable(rows, nullptr);
    return 0;
  }
  const Family* family = nullptr;
  for (const Family& f : allFamilies())
    if (f.id == id) family = &f;
  if (!family) {
    std::cerr << "shadowlab list --markdown: no family '" << id << "' (`shadowlab list --markdown families`)\n";
    return 2;
  }
  std::vector<ParamRow> rows;
  for (const auto& l : family->layouts) addParamRows(rows, l->id(), l->params());
  for (const auto& r : family->representations) addParamRows(rows, r->id(), r->params());
  for (const auto& a : family->accumulations) addParamRows(rows, a->id(), a->params());
  paramsTable(rows, family);
  return 0;
}

}  // namespace

int runListMarkdown(const std::string& table) {
  const std::string familyParams = "params:";
  if (table.rfind(familyParams, 0) == 0) return familyParamsTable(table.substr(familyParams.size()));
  if (table == "families")
    familiesTable();
  else if (table == "presets")
    presetsTable();
  else if (table == "parts")
    partsTable();
  else {
    std::cerr << "shadowlab list --markdown: no table '" << table
              << "' (tables: families, presets, parts, params:FAMILY)\n";
    return 2;
  }
  return 0;
}

}  // namespace sl
