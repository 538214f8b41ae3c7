// The empty accumulation: each frame's shadow test is shown as it is. Its state is the default
// AccumulationState, whose one pass tests and shades while the scene is rasterized (forward).
#include "part/part.h"

namespace sl {

namespace {
class NoAccumulation : public Accumulation {
 public:
  std::string id() const override { return "none"; }
  std::string help() const override { return "no screen-space accumulation: every frame stands alone"; }
  std::unique_ptr<AccumulationState> createState() const override { return std::make_unique<AccumulationState>(); }
};
}  // namespace

void registerPixelCorrect(std::vector<std::unique_ptr<Accumulation>>& out);

void registerAccumulations(std::vector<std::unique_ptr<Accumulation>>& out) {
  out.push_back(std::make_unique<NoAccumulation>());
  registerPixelCorrect(out);
}

}  // namespace sl
