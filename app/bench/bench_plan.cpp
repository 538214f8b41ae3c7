// Planning `shadowlab bench`: techniques x --set x --sweep into entries; see bench.h.
#include "bench/bench.h"

#include "cli/args.h"
#include "technique.h"

#include <algorithm>
#include <sstream>

namespace sl {

namespace {

std::vector<std::string> splitList(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep))
    if (!cur.empty()) out.push_back(cur);
  return out;
}

std::pair<std::string, std::string> splitAssignment(const std::string& a, const std::string& option) {
  auto eq = a.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == a.size())
    throw ArgError(option + " expects key=value, got '" + a + "'");
  return {a.substr(0, eq), a.substr(eq + 1)};
}

// "shadowmap.size, bias.mode, ..." of all techniques, for error messages.
std::string knownKeys(const std::vector<Technique>& ts) {
  std::vector<std::string> keys;
  for (const auto& t : ts)
    for (const auto& d : t.params.decls())
      if (std::find(keys.begin(), keys.end(), d.key) == keys.end()) keys.push_back(d.key);
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

}  // namespace

std::vector<BenchPlanEntry> planBench(const BenchOptions& o) {
  if (o.techniques.empty()) throw ArgError("--techniques a,b,c is required (see `shadowlab list`)");
  if (o.frames < 1) throw ArgError("--frames must be at least 1");
  if (o.warmup < 0) throw ArgError("--warmup must be 0 or more");
  std::vector<Technique> base;
  for (const auto& id : o.techniques) base.push_back(makeTechnique(id));  // ParamError names unknown presets

  for (const auto& a : o.sets) {
    auto [key, value] = splitAssignment(a, "--set");
    bool any = false;
    for (auto& t : base)
      if (t.params.has(key)) {
        t.params.setFromString(key, value);  // ParamError for a bad value
        t = recomposed(t);                   // technique.layout: rebuilt over that layout
        any = true;
      }
    if (!any)
      throw ArgError("--set " + a + ": no technique in --techniques has a parameter '" + key +
                     "' (keys: " + knownKeys(base) + ")");
  }

  struct Sweep {
    std::string key;
    std::vector<std::string> values;
  };
  std::vector<Sweep> sweeps;
  for (const auto& s : o.sweeps) {
    auto [key, list] = splitAssignment(s, "--sweep");
    Sweep sw{key, splitList(list, ',')};
    if (sw.values.empty()) throw ArgError("--sweep " + s + ": no values");
    for (const auto& other : sweeps)
      if (other.key == key) throw ArgError("--sweep " + key + " given twice");
    bool any = false;
    for (const auto& t : base)
      if (t.params.has(key)) {
        any = true;
        Technique probe = t;
        for (const auto& v : sw.values) probe.params.setFromString(key, v);  // validate every value now
      }
    if (!any)
      throw ArgError("--sweep " + s + ": no technique in --techniques has a parameter '" + key +
                     "' (keys: " + knownKeys(base) + ")");
    sweeps.push_back(sw);
  }

  std::vector<BenchPlanEntry> plan;
  for (const auto& t : base) {
    // Cartesian product over the sweeps this technique has; the others collapse to one point.
    std::vector<const Sweep*> dims;
    for (const auto& s : sweeps)
      if (t.params.has(s.key)) dims.push_back(&s);
    std::vector<size_t> idx(dims.size(), 0);
    while (true) {
      BenchPlanEntry e{t, {}};
      for (size_t d = 0; d < dims.size(); ++d) {
        e.technique.params.setFromString(dims[d]->key, dims[d]->values[idx[d]]);
        e.sweepPoint.emplace_back(dims[d]->key, dims[d]->values[idx[d]]);
      }
      e.technique = recomposed(e.technique);  // a swept technique.layout
      plan.push_back(std::move(e));
      bool carried = true;  // odometer increment over the sweep dimensions
      for (size_t d = dims.size(); d-- > 0;) {
        if (++idx[d] < dims[d]->values.size()) {
          carried = false;
          break;
        }
        idx[d] = 0;
      }
      if (carried) break;
    }
  }
  return plan;
}

}  // namespace sl
