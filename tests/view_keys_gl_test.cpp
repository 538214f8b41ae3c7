// Every debug view a part's state offers has a colour key (the common views' in
// app/render/view_keys.cpp, a part's in its family's manifest), and no family declares a key for
// a view none of its parts offers. GL tier: creating a state may touch GL.
#include "gl_test_util.h"
#include "render/renderer.h"
#include "part/common_view_keys.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <set>

namespace sl {

namespace {
std::set<std::string> offeredViews(const Family& f) {
  std::set<std::string> views;
  auto add = [&](const PartState& s) {
    for (const std::string& v : s.views()) views.insert(v);
  };
  for (const auto& l : f.layouts) add(*l->createState());
  for (const auto& r : f.representations) add(*r->createState());
  for (const auto& a : f.accumulations) add(*a->createState());
  return views;
}
}  // namespace

TEST(ViewKeysGl, EveryOfferedViewHasAKeyAndEveryDeclaredKeyAView) {
  test::GlHarness h;
  for (const std::string& common : commonViewNames()) EXPECT_NE(viewColourKey(common), nullptr) << common;
  for (const Family& f : allFamilies()) {
    const std::set<std::string> offered = offeredViews(f);
    for (const std::string& v : offered) {
      const ColourKey* key = viewColourKey(v);
      ASSERT_NE(key, nullptr) << "family " << f.id << ": view '" << v << "' has no colour key";
      EXPECT_FALSE(key->title.empty()) << v;
      EXPECT_TRUE(!key->stops.empty() || !key->specials.empty()) << v;
      for (const ColourStop& s : key->stops) EXPECT_FALSE(s.label.empty()) << v;
    }
    for (const auto& [name, key] : f.viewKeys) {
      EXPECT_TRUE(offered.count(name)) << "family " << f.id << " keys view '" << name << "' that no part offers";
      EXPECT_EQ(commonViewColourKey(name), nullptr) << name << " is a common view: its key is the renderer's";
    }
  }
}

}  // namespace sl
