// The frame graph culls what nobody reads; tested without a GPU (no-op passes).
#include "part/frame_graph.h"

#include <gtest/gtest.h>

namespace sl {

static FrameGraph exampleGraph(std::vector<std::string>& ran) {
  FrameGraph g;
  auto pass = [&ran](const std::string& name, std::vector<std::string> reads, std::vector<std::string> writes) {
    return Pass{name, std::move(reads), std::move(writes), [&ran, name] { ran.push_back(name); }};
  };
  g.add(pass("gbuffer", {}, {"gbuffer"}));
  g.add(pass("shadowmap", {}, {"sm"}));
  g.add(pass("blur", {"sm"}, {"sm.blurred"}));  // a representation that is not used
  g.add(pass("visibility", {"gbuffer", "sm"}, {"vis"}));
  g.add(pass("shade", {"gbuffer", "vis"}, {"color"}));
  g.add(pass("view.texels", {"gbuffer"}, {"view.texels"}));
  g.add(pass("view.shadowmap", {"sm"}, {"view.shadowmap"}));
  return g;
}

TEST(FrameGraph, RunsOnlyPassesThatReachASink) {
  std::vector<std::string> ran;
  FrameGraph g = exampleGraph(ran);
  g.requestSink("color");
  EXPECT_EQ(g.compile(), (std::vector<std::string>{"gbuffer", "shadowmap", "visibility", "shade"}));
  g.execute([](const Pass&, const std::function<void()>& run) { run(); });
  EXPECT_EQ(ran, (std::vector<std::string>{"gbuffer", "shadowmap", "visibility", "shade"}));
}

// A pass writing several resources asks, while it runs, which of them something live reads (the
// G-buffer pass draws positions alone when only they are read).
TEST(FrameGraph, PassLearnsWhichOfItsOutputsAreNeeded) {
  FrameGraph g;
  bool wholeNeeded = true, positionsNeeded = false;
  g.add({"gbuffer", {}, {"gbuffer", "gbuffer.position"}, [&] {
           wholeNeeded = g.neededLive("gbuffer");
           positionsNeeded = g.neededLive("gbuffer.position");
         }});
  g.add({"marking", {"gbuffer.position"}, {"pages"}, [] {}});
  g.add({"view.texels", {"gbuffer"}, {"view.texels"}, [] {}});
  g.requestSink("pages");
  g.execute([](const Pass&, const std::function<void()>& run) { run(); });
  EXPECT_FALSE(wholeNeeded) << "the view is culled: nothing live reads the whole G-buffer";
  EXPECT_TRUE(positionsNeeded);
  g.requestSink("view.texels");
  g.execute([](const Pass&, const std::function<void()>& run) { run(); });
  EXPECT_TRUE(wholeNeeded);
  g.requestSink("gbuffer");  // read back after the frame
  EXPECT_TRUE(g.neededLive("gbuffer"));
}

TEST(FrameGraph, ShownDebugViewAddsExactlyItsPass) {
  std::vector<std::string> ran;
  FrameGraph g = exampleGraph(ran);
  g.requestSink("color");
  g.requestSink("view.shadowmap");
  auto order = g.compile();
  EXPECT_NE(std::find(order.begin(), order.end(), "view.shadowmap"), order.end());
  EXPECT_EQ(std::find(order.begin(), order.end(), "view.texels"), order.end());
  EXPECT_EQ(std::find(order.begin(), order.end(), "blur"), order.end());
}

TEST(FrameGraph, NothingRequestedRunsNothing) {
  std::vector<std::string> ran;
  FrameGraph g = exampleGraph(ran);
  EXPECT_TRUE(g.compile().empty());
}

TEST(FrameGraph, HistoryFromLastFrameIsImported) {
  FrameGraph g;
  g.add({"accumulate", {"vis", "history.prev"}, {"history.next", "vis.final"}, [] {}});
  g.add({"vis", {}, {"vis"}, [] {}});
  g.requestSink("vis.final");
  EXPECT_THROW(g.compile(), std::logic_error);  // reads 'vis' before it is written
  FrameGraph ok;
  ok.add({"vis", {}, {"vis"}, [] {}});
  ok.add({"accumulate", {"vis", "history.prev"}, {"vis.final"}, [] {}});
  ok.requestSink("vis.final");
  EXPECT_THROW(ok.compile(), std::logic_error);  // history.prev not declared as imported
  ok.importResource("history.prev");
  EXPECT_EQ(ok.compile().size(), 2u);
}

TEST(FrameGraph, TwoPassesOfOneNameAreAWiringMistake) {
  FrameGraph g;
  g.add({"shade[0]", {}, {"color[0]"}, [] {}});
  g.add({"shade[0]", {}, {"color[1]"}, [] {}});
  g.requestSink("color[0]");
  EXPECT_THROW(g.compile(), std::logic_error);
}

}  // namespace sl

namespace sl {

// Records what the graph borrows and returns, in order.
struct RecordingAllocator : TransientAllocator {
  std::vector<std::string> log;
  int next = 1;
  void* acquire(const TextureDesc& d, const std::string& name) override {
    log.push_back("acquire " + name + " " + std::to_string(d.width));
    return reinterpret_cast<void*>(static_cast<intptr_t>(next++));
  }
  void release(void* t) override { log.push_back("release " + std::to_string(reinterpret_cast<intptr_t>(t))); }
};

TEST(FrameGraph, TransientTextureIsLentFromItsFirstToItsLastLivePass) {
  FrameGraph g;
  RecordingAllocator alloc;
  std::vector<std::string> seen;
  auto look = [&](const std::string& pass) { seen.push_back(pass + (g.transient("scratch") ? " has" : " none")); };
  g.createTexture("scratch", {0x822F /* RG16F */, 64, 32});
  g.add({"blur.h", {}, {"scratch"}, [&] { look("blur.h"); }});
  g.add({"blur.v", {"scratch"}, {"blurred"}, [&] { look("blur.v"); }});
  g.add({"shade", {"blurred"}, {"color"}, [&] { look("shade"); }});
  g.requestSink("color");
  g.compile();
  g.execute([](const Pass&, const std::function<void()>& run) { run(); }, &alloc);
  EXPECT_EQ(seen, (std::vector<std::string>{"blur.h has", "blur.v has", "shade none"}));
  EXPECT_EQ(alloc.log, (std::vector<std::string>{"acquire scratch 64", "release 1"}));
}

TEST(FrameGraph, CulledPassesBorrowNothing) {
  FrameGraph g;
  RecordingAllocator alloc;
  g.createTexture("scratch", {0x822F, 64, 64});
  g.add({"blur", {}, {"scratch", "blurred"}, [] {}});  // nothing reads "blurred"
  g.add({"shade", {}, {"color"}, [] {}});
  g.requestSink("color");
  g.execute([](const Pass&, const std::function<void()>& run) { run(); }, &alloc);
  EXPECT_TRUE(alloc.log.empty());
  EXPECT_TRUE(g.transientLifetimes().empty());
}

TEST(FrameGraph, TransientWiringMistakesThrow) {
  auto graphWith = [](TextureDesc d) {
    FrameGraph g;
    g.createTexture("t", d);
    g.add({"p", {}, {"t", "out"}, [] {}});
    g.requestSink("out");
    return g;
  };
  EXPECT_NO_THROW(graphWith({0x822F, 8, 8}).compile());
  EXPECT_THROW(graphWith({0, 8, 8}).compile(), std::logic_error);             // no format
  EXPECT_THROW(graphWith({0x822F, 0, 8}).compile(), std::logic_error);        // empty
  EXPECT_THROW(graphWith({0x822F, 8, 8, 1, 0}).compile(), std::logic_error);  // no level
  FrameGraph twice = graphWith({0x822F, 8, 8});
  twice.createTexture("t", {0x822F, 16, 8});
  EXPECT_THROW(twice.compile(), std::logic_error);
  FrameGraph both = graphWith({0x822F, 8, 8});
  both.importResource("t");
  EXPECT_THROW(both.compile(), std::logic_error);
  // A live transient with nowhere to borrow it from.
  EXPECT_THROW(graphWith({0x822F, 8, 8}).execute([](const Pass&, const std::function<void()>& run) { run(); }),
               std::logic_error);
}

}  // namespace sl
