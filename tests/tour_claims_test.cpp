// What the shipped tours' captions claim, checked numerically: each step's "claims" against the
// ray-traced reference (one test per tour), and the dp/ds step's curves against its caption.
#include "gl_test_util.h"
#include "shipped_tours.h"
#include "gl/shader_library.h"
#include "plot/dpds.h"
#include "tour/tour.h"
#include "tour/tour_claims.h"

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

// At the figures' default panel size (figure --size): the claims were written against it.
class TourClaims : public ::testing::TestWithParam<std::string> {};

TEST_P(TourClaims, EveryStepsClaimsHoldAgainstTheReference) {
  test::GlHarness h;
  const Tour t = loadTour(GetParam());
  int claims = 0;
  for (size_t i = 0; i < t.steps.size(); ++i) {
    SCOPED_TRACE(describeStep(t, i));
    for (const ClaimCheck& c : checkStepClaims(t, i, h.shaders, 480, 270, "")) {
      ++claims;
      EXPECT_TRUE(c.holds) << c.text;
    }
  }
  EXPECT_GT(claims, 0) << "a shipped tour states no claim to check";
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Tours, TourClaims, ::testing::ValuesIn(test::shippedTourFiles()), test::tourTestName);

// log10 of the largest over the smallest finite ratio: how far a curve is from flat.
double dpdsLogSpread(const DpdsCurve& c) {
  double lo = INFINITY, hi = 0;
  for (float r : c.ratio)
    if (std::isfinite(r) && r > 0) lo = std::min(lo, double(r)), hi = std::max(hi, double(r));
  return std::log10(hi / lo);
}

// Survey step 12's caption: uniform ~ 1/z (falls along the view), PSM U-shaped (its minimum
// inside the range, both ends well above it), LogPSM the flattest.
TEST(Dpds, SurveyStepTwelveShowsTheCurvesItsCaptionDescribes) {
  const Tour t = loadTour(std::string(SHADOWLAB_SOURCE_DIR) + "/tours/survey.json");
  const size_t step = 11;
  ASSERT_NE(t.steps[step].caption.find("U"), std::string::npos);
  const Scene scene = loadStepScene(t, step, defaultAssetsDir());
  const Camera cam = stepCamera(t, step, scene);
  const std::vector<DpdsCurve> c = dpdsCurves(scene, cam, 1280, 720, {"uniform", "psm", "logpsm"}, 64);
  auto finite = [](const DpdsCurve& curve) {
    std::vector<float> v;
    for (float r : curve.ratio)
      if (std::isfinite(r) && r > 0) v.push_back(r);
    return v;
  };
  const std::vector<float> uniform = finite(c[0]), psm = finite(c[1]);
  ASSERT_GT(uniform.size(), 32u);
  ASSERT_GT(psm.size(), 32u);
  EXPECT_GT(uniform.front(), 10.0f * uniform.back()) << "uniform: dp/ds ~ 1/z falls along the view";
  const size_t lowest = size_t(std::min_element(psm.begin(), psm.end()) - psm.begin());
  EXPECT_GT(lowest, psm.size() / 8) << "psm's minimum at its near end: no U";
  EXPECT_LT(lowest, psm.size() * 7 / 8) << "psm's minimum at its far end: no U";
  EXPECT_GT(psm.front(), 2.0f * psm[lowest]);
  EXPECT_GT(psm.back(), 2.0f * psm[lowest]);
  EXPECT_LT(dpdsLogSpread(c[2]), dpdsLogSpread(c[1]));
  EXPECT_LT(dpdsLogSpread(c[2]), dpdsLogSpread(c[0]));
}

}  // namespace
}  // namespace sl
