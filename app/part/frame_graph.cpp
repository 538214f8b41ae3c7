#include "part/frame_graph.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace sl {

void FrameGraph::add(Pass pass) { passes_.push_back(std::move(pass)); }

void FrameGraph::requestSink(const std::string& resource) { sinks_.push_back(resource); }

bool FrameGraph::requested(const std::string& resource) const {
  return std::find(sinks_.begin(), sinks_.end(), resource) != sinks_.end();
}

bool FrameGraph::neededLive(const std::string& resource) const {
  if (requested(resource)) return true;
  const std::vector<bool> live = liveMask();
  for (size_t k = 0; k < passes_.size(); ++k)
    if (live[k] && std::find(passes_[k].reads.begin(), passes_[k].reads.end(), resource) != passes_[k].reads.end())
      return true;
  return false;
}

void FrameGraph::importResource(const std::string& resource) { imports_.push_back(resource); }

void FrameGraph::createTexture(const std::string& resource, const TextureDesc& desc) {
  transients_.emplace_back(resource, desc);
}

void* FrameGraph::transient(const std::string& resource) const {
  auto it = lent_.find(resource);
  return it == lent_.end() ? nullptr : it->second;
}

void FrameGraph::clear() {
  passes_.clear();
  sinks_.clear();
  imports_.clear();
  transients_.clear();
  lent_.clear();
}

namespace {
bool uses(const Pass& p, const std::string& r) {
  return std::find(p.reads.begin(), p.reads.end(), r) != p.reads.end() ||
         std::find(p.writes.begin(), p.writes.end(), r) != p.writes.end();
}
}  // namespace

std::vector<FrameGraph::Lifetime> FrameGraph::transientLifetimes() const {
  const std::vector<bool> live = liveMask();
  std::vector<Lifetime> out;
  for (const auto& [name, desc] : transients_) {
    Lifetime l{name, desc, passes_.size(), 0};
    for (size_t k = 0; k < passes_.size(); ++k)
      if (live[k] && uses(passes_[k], name)) l.first = std::min(l.first, k), l.last = k;
    if (l.first < passes_.size()) out.push_back(l);
  }
  return out;
}

// Wiring mistakes of transient textures: what they must be, declared once, not also imported.
void FrameGraph::checkTransients() const {
  std::map<std::string, TextureDesc> seen;
  for (const auto& [name, d] : transients_) {
    if (d.format == 0 || d.width <= 0 || d.height <= 0 || d.layers < 0 || d.levels < 1)
      throw std::logic_error("frame graph: transient texture '" + name + "' has no format or an empty size");
    auto [it, fresh] = seen.emplace(name, d);
    if (!fresh && !(it->second == d))
      throw std::logic_error("frame graph: transient texture '" + name + "' declared twice, differently");
    if (std::find(imports_.begin(), imports_.end(), name) != imports_.end())
      throw std::logic_error("frame graph: '" + name + "' is both imported and transient");
  }
}

// Walk backwards: a pass is live when it writes something a later live pass (or a sink) needs.
std::vector<bool> FrameGraph::liveMask() const {
  std::vector<bool> live(passes_.size(), false);
  std::set<std::string> needed(sinks_.begin(), sinks_.end());
  for (size_t k = passes_.size(); k-- > 0;) {
    const Pass& p = passes_[k];
    bool producesNeeded =
        std::any_of(p.writes.begin(), p.writes.end(), [&](const std::string& w) { return needed.count(w) > 0; });
    if (!producesNeeded) continue;
    live[k] = true;
    // A resource written here and also read here (ping-pong history) stays needed upstream.
    for (const auto& w : p.writes)
      if (std::find(p.reads.begin(), p.reads.end(), w) == p.reads.end()) needed.erase(w);
    for (const auto& r : p.reads) needed.insert(r);
  }
  return live;
}

std::vector<std::string> FrameGraph::compile() const {
  checkTransients();
  std::set<std::string> names;
  for (const Pass& p : passes_)
    if (!names.insert(p.name).second)
      throw std::logic_error("frame graph: two passes named '" + p.name +
                             "' (pass names are debug groups and timings)");
  std::vector<bool> live = liveMask();
  std::set<std::string> produced(imports_.begin(), imports_.end());
  std::vector<std::string> order;
  for (size_t k = 0; k < passes_.size(); ++k) {
    if (!live[k]) continue;
    for (const auto& r : passes_[k].reads) {
      bool self = std::find(passes_[k].writes.begin(), passes_[k].writes.end(), r) != passes_[k].writes.end();
      if (!produced.count(r) && !self)
        throw std::logic_error("frame graph: pass '" + passes_[k].name + "' reads '" + r +
                               "' which no earlier pass writes");
    }
    for (const auto& w : passes_[k].writes) produced.insert(w);
    order.push_back(passes_[k].name);
  }
  return order;
}

void FrameGraph::execute(const std::function<void(const Pass&, const std::function<void()>&)>& wrapper,
                         TransientAllocator* allocator) const {
  const std::vector<bool> live = liveMask();
  const std::vector<Lifetime> lifetimes = transientLifetimes();
  if (!lifetimes.empty() && !allocator)
    throw std::logic_error("frame graph: transient textures declared but no allocator to lend them");
  lent_.clear();
  for (size_t k = 0; k < passes_.size(); ++k) {
    if (!live[k]) continue;
    for (const Lifetime& l : lifetimes)
      if (l.first == k) lent_[l.resource] = allocator->acquire(l.desc, l.resource);
    wrapper(passes_[k], passes_[k].execute);
    for (const Lifetime& l : lifetimes)
      if (l.last == k) {
        allocator->release(lent_[l.resource]);
        lent_.erase(l.resource);
      }
  }
}

}  // namespace sl
