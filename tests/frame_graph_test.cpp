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
