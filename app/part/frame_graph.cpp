#include "part/frame_graph.h"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace sl {

void FrameGraph::add(Pass pass) { passes_.push_back(std::move(pass)); }

void FrameGraph::requestSink(const std::string& resource) { sinks_.push_back(resource); }

void FrameGraph::importResource(const std::string& resource) { imports_.push_back(resource); }

void FrameGraph::clear() {
  passes_.clear();
  sinks_.clear();
  imports_.clear();
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

void FrameGraph::execute(const std::function<void(const Pass&, const std::function<void()>&)>& wrapper) const {
  std::vector<bool> live = liveMask();
  for (size_t k = 0; k < passes_.size(); ++k)
    if (live[k]) wrapper(passes_[k], passes_[k].execute);
}

}  // namespace sl
