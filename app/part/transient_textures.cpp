#include "part/transient_textures.h"

#include <algorithm>
#include <stdexcept>

namespace sl {

void* TransientTextures::acquire(const TextureDesc& desc, const std::string& name) {
  for (Entry& e : entries_)
    if (!e.inUse && e.desc == desc) {
      e.inUse = true;
      e.idleFrames = 0;
      return e.texture.get();
    }
  Entry e;
  e.desc = desc;
  const std::string label = "transient " + name;
  e.texture = std::make_unique<Texture2D>(
      desc.layers > 0 ? Texture2D::array(desc.format, desc.width, desc.height, desc.layers, desc.levels, label)
                      : Texture2D(desc.format, desc.width, desc.height, label));
  e.inUse = true;
  entries_.push_back(std::move(e));
  return entries_.back().texture.get();
}

void TransientTextures::release(void* texture) {
  for (Entry& e : entries_)
    if (e.texture.get() == texture) e.inUse = false;
}

void TransientTextures::beginFrame() {
  for (Entry& e : entries_) {
    e.inUse = false;
    ++e.idleFrames;
  }
  entries_.erase(
      std::remove_if(entries_.begin(), entries_.end(), [](const Entry& e) { return e.idleFrames > kKeepFrames; }),
      entries_.end());
}

long long TransientTextures::texels() const {
  long long n = 0;
  for (const Entry& e : entries_)
    n += static_cast<long long>(e.desc.width) * e.desc.height * std::max(e.desc.layers, 1);
  return n;
}

Texture2D& transientTexture(const FrameGraph& graph, const std::string& resource) {
  void* t = graph.transient(resource);
  if (!t) throw std::logic_error("frame graph: no transient texture '" + resource + "' lent to the running pass");
  return *static_cast<Texture2D*>(t);
}

}  // namespace sl
