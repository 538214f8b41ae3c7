// The reconstruction formulas of every pre-filtered representation, run as their real GLSL
// through a probe (moment_probe.h): finite and within [0,1] in the hard cases, and the
// identities that hold exactly.
#include "prefiltered/tests/moment_probe.h"

#include <limits>

namespace sl {
namespace {

using test::MomentCase;

const std::vector<std::string> kPresets = {"vsm",      "esm",  "evsm2", "evsm4", "convolution",
                                           "gaussian", "ewgf", "msm",   "msm16", "lvsm"};

// Depths a caster can leave in the map, valid or not.
std::vector<float> hardDepths() {
  const float inf = std::numeric_limits<float>::infinity();
  return {0.0f,
          1e-3f,
          0.25f,
          0.5f,
          0.5f + 1e-6f,
          0.999f,
          1.0f,
          -0.5f,
          2.0f,
          1e4f,
          inf,
          -inf,
          std::numeric_limits<float>::quiet_NaN()};
}

// Every pair of hard depths, three coverages, and receivers at both depths (exactly at the
// occluder: the case of a receiver shadowing itself) and across [0, 1].
std::vector<MomentCase> momentHardCases() {
  std::vector<MomentCase> cases;
  const std::vector<float> depths = hardDepths();
  for (float z1 : depths)
    for (float z2 : depths)
      for (float fraction : {0.0f, 0.3f, 1.0f}) {
        std::vector<float> receivers = {0.0f, 0.1f, 0.5f, 0.9f, 1.0f, 1.05f};
        for (float z : {z1, z2})
          if (std::isfinite(z)) receivers.push_back(std::clamp(z, 0.0f, 1.0f));
        for (float r : receivers) cases.push_back({z1, z2, fraction, r});
      }
  return cases;
}

void expectFiniteUnit(const std::vector<float>& v, const std::vector<MomentCase>& cases, const std::string& what) {
  ASSERT_EQ(v.size(), cases.size()) << what;
  int bad = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    if (std::isfinite(v[i]) && v[i] >= 0.0f && v[i] <= 1.0f) continue;
    if (++bad <= 3)
      ADD_FAILURE() << what << ": visibility " << v[i] << " for z1 " << cases[i].z1 << " z2 " << cases[i].z2
                    << " fraction " << cases[i].fraction << " receiver " << cases[i].receiver;
  }
  EXPECT_EQ(bad, 0) << what;
}

TEST(PrefilteredReconstruction, FiniteAndWithinUnitIntervalInTheHardCases) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  const std::vector<MomentCase> cases = momentHardCases();
  for (const auto& preset : kPresets)
    for (const std::string format : {"float16", "float32"}) {
      std::vector<std::string> sets = {"filter.format=" + format};
      if (preset == "msm16" && format == "float32") sets.push_back("msm.quantize=on");
      expectFiniteUnit(probe.visibility(preset, sets, cases), cases, preset + " " + format);
    }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The soft ones' hard reconstruction and blocker estimate over the same cases (their moments are
// always 32-bit sums; CSM-Z for every number of terms its 8 targets hold).
TEST(PrefilteredReconstruction, SoftFiniteAndWithinUnitIntervalInTheHardCases) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  const std::vector<MomentCase> cases = momentHardCases();
  std::vector<std::pair<std::string, std::string>> runs = {{"vssm", "vssm.bleed=0"}, {"vssm", "vssm.bleed=0.5"}};
  for (int m = 1; m <= 7; ++m) runs.push_back({"convolution-soft", "csmz.terms=" + std::to_string(m)});
  for (const auto& [preset, set] : runs) {
    expectFiniteUnit(probe.visibility(preset, {set}, cases), cases, preset + " " + set);
    const auto b = probe.blocker(preset, {set}, cases);
    ASSERT_EQ(b.size(), cases.size());
    int bad = 0;
    for (size_t i = 0; i < b.size(); ++i) {
      if (std::isfinite(b[i].first) && std::isfinite(b[i].second) && b[i].first >= 0.0f && b[i].first <= 1.0f) continue;
      if (++bad <= 3)
        ADD_FAILURE() << preset << " " << set << ": blocker (" << b[i].first << ", " << b[i].second << ") for z1 "
                      << cases[i].z1 << " z2 " << cases[i].z2 << " fraction " << cases[i].fraction << " receiver "
                      << cases[i].receiver;
    }
    EXPECT_EQ(bad, 0) << preset << " " << set;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// One planar blocker at depth a over a fraction p of the search box, the rest the planar receiver
// at depth b: Yang et al.'s estimate is exact; CSM-Z with its receiver weight taken out has the
// fraction within 0.04 (it only decides whether anything blocks) and the depth within
// 0.015 of the blocker's depth at 4 terms (the uncorrected ratio reads 0.32 for a = 0.2, b = 0.7).
TEST(PrefilteredReconstruction, SoftBlockerDepthOfOnePlanarBlockerOverAPlanarReceiver) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  std::vector<MomentCase> cases;
  for (float a : {0.1f, 0.2f, 0.3f})
    for (float b : {0.7f, 0.9f})
      for (float p : {0.25f, 0.5f, 0.75f}) cases.push_back({a, b, p, b});
  const auto vssm = probe.blocker("vssm", {"vssm.min_variance=0"}, cases);
  const auto csmz = probe.blocker("convolution-soft", {"csmz.terms=4", "convolution.offset=0.04"}, cases);
  ASSERT_EQ(vssm.size(), cases.size());
  ASSERT_EQ(csmz.size(), cases.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    const MomentCase& c = cases[i];
    EXPECT_NEAR(vssm[i].first, c.fraction, 1e-3f) << "vssm blocker " << c.z1 << " receiver " << c.z2;
    EXPECT_NEAR(vssm[i].second, c.z1, 1e-3f) << "vssm blocker " << c.z1 << " receiver " << c.z2;
    EXPECT_NEAR(csmz[i].first, c.fraction, 0.04f) << "csm-z blocker " << c.z1 << " receiver " << c.z2;
    EXPECT_NEAR(csmz[i].second, c.z1, 0.015f) << "csm-z blocker " << c.z1 << " receiver " << c.z2;
  }
  // Nothing nearer than the receiver: no blocker, whatever the receiver's own depth.
  const std::vector<MomentCase> lit = {{0.5f, 0.5f, 1.0f, 0.5f}, {0.9f, 0.3f, 0.5f, 0.3f}};
  for (const auto& r : {probe.blocker("vssm", {}, lit), probe.blocker("convolution-soft", {}, lit)})
    for (const auto& [fraction, depth] : r) EXPECT_LT(fraction, 0.02f);
}

TEST(PrefilteredReconstruction, ExponentsAtAndBeyondWhatTheFormatHolds) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  const std::vector<MomentCase> cases = momentHardCases();
  for (const std::string format : {"float16", "float32"}) {
    for (const std::string c : {"5.54", "42", "100"}) {
      for (const auto& [preset, keys] : std::vector<std::pair<std::string, std::vector<std::string>>>{
               {"evsm2", {"evsm.exponent_pos"}},
               {"evsm4", {"evsm.exponent_pos", "evsm.exponent_neg"}},
               {"ewgf", {"ewgf.exponent"}}}) {
        std::vector<std::string> sets = {"filter.format=" + format};
        for (const auto& k : keys) sets.push_back(k + "=" + c);
        expectFiniteUnit(probe.visibility(preset, sets, cases), cases, preset + " " + format + " c=" + c);
      }
    }
    for (const std::string c : {"88", "300", "1000"})
      expectFiniteUnit(probe.visibility("esm", {"filter.format=" + format, "esm.exponent=" + c}, cases), cases,
                       "esm " + format + " c=" + c);
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(PrefilteredReconstruction, ConvolutionFiniteForEveryNumberOfTerms) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  const std::vector<MomentCase> cases = momentHardCases();
  for (int m = 1; m <= 16; ++m)
    for (const std::string format : {"float16", "float32"})
      expectFiniteUnit(
          probe.visibility("convolution", {"convolution.terms=" + std::to_string(m), "filter.format=" + format}, cases),
          cases, "convolution M=" + std::to_string(m) + " " + format);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// One planar occluder at depth a over a fraction p of the kernel, the planar receiver at depth b
// over the rest: mean and variance are those of the two-point distribution, and Cantelli's bound
// at t = b is exactly 1 - p.
TEST(PrefilteredReconstruction, VsmIsExactForOnePlanarOccluderOverAPlanarReceiver) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  std::vector<MomentCase> cases;
  for (float a : {0.1f, 0.3f, 0.6f})
    for (float b : {0.65f, 0.8f, 0.95f})
      for (float p : {0.05f, 0.25f, 0.5f, 0.75f, 0.95f}) cases.push_back({a, b, p, b});
  const auto v = probe.visibility("vsm", {"vsm.min_variance=0", "vsm.bleed=0"}, cases);
  ASSERT_EQ(v.size(), cases.size());
  for (size_t i = 0; i < v.size(); ++i)
    EXPECT_NEAR(v[i], 1.0f - cases[i].fraction, 2e-4f)
        << "occluder " << cases[i].z1 << " receiver " << cases[i].z2 << " coverage " << cases[i].fraction;
}

// The overlap case: two occluders at different depths in the kernel and the receiver behind
// both (truly unlit). VSM's variance spans both occluders and its bound leaks light; layered
// VSM tests the receiver's layer only, where both occluders sit at warped depth 0.
TEST(PrefilteredReconstruction, LayeredVsmDoesNotBleedWhereVsmDoes) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  std::vector<MomentCase> cases;
  for (float p : {0.2f, 0.5f, 0.8f})
    for (float r : {0.55f, 0.6f, 0.7f}) cases.push_back({0.1f, 0.45f, p, r});
  const auto vsm = probe.visibility("vsm", {}, cases);
  const auto lvsm = probe.visibility("lvsm", {}, cases);
  ASSERT_EQ(vsm.size(), cases.size());
  ASSERT_EQ(lvsm.size(), cases.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    EXPECT_GT(vsm[i], 0.05f) << "the case must leak under VSM (receiver " << cases[i].receiver << ")";
    // What is left is the variance floor's bound (1e-5 x 16 over a warped distance >= 0.2).
    EXPECT_LT(lvsm[i], 5e-3f) << "receiver " << cases[i].receiver << " coverage " << cases[i].fraction;
  }
}

// A single depth in the kernel: the Gaussian of a (floored) zero variance is a step, up to the
// erfc approximation's error (1.5e-7) once the receiver is many standard deviations away.
TEST(PrefilteredReconstruction, GaussianAndEwgfAreTheStepForASingleDepth) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  std::vector<MomentCase> cases;
  std::vector<float> expected;
  for (float z : {0.05f, 0.3f, 0.5f, 0.8f, 0.95f})
    for (float d : {-0.04f, -0.02f, 0.02f, 0.04f})
      if (z + d > 0.0f && z + d < 1.0f) {
        cases.push_back({z, z, 1.0f, z + d});
        expected.push_back(d < 0 ? 1.0f : 0.0f);
      }
  for (const std::string preset : {"gaussian", "ewgf"}) {
    const auto v = probe.visibility(preset, {}, cases);
    ASSERT_EQ(v.size(), cases.size());
    for (size_t i = 0; i < v.size(); ++i)
      EXPECT_NEAR(v[i], expected[i], 5e-7f) << preset << " depth " << cases[i].z1 << " receiver " << cases[i].receiver;
  }
}

// Visibility never increases as the receiver moves away from the light, for every mixture of
// two depths (the CDF-based and bound-based representations; the Fourier one rings on purpose).
TEST(PrefilteredReconstruction, MonotonicInReceiverDepth) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  const int steps = 200;
  std::vector<MomentCase> cases;
  for (float z1 : {0.1f, 0.4f, 0.7f})
    for (float z2 : {0.45f, 0.9f, 1.0f})
      for (float p : {0.2f, 0.5f, 1.0f})
        for (int s = 0; s <= steps; ++s) cases.push_back({z1, z2, p, float(s) / steps});
  for (const std::string preset : {"vsm", "gaussian", "ewgf", "esm", "evsm2", "evsm4", "msm"}) {
    const auto v = probe.visibility(preset, {}, cases);
    ASSERT_EQ(v.size(), cases.size());
    // The Hamburger solve in single precision jitters by ~1e-4 near full shadow.
    const float tolerance = preset == "msm" ? 5e-4f : 1e-5f;
    int rises = 0;
    for (size_t i = 1; i < v.size(); ++i)
      if (i % (steps + 1) != 0 && v[i] > v[i - 1] + tolerance && ++rises <= 3)
        ADD_FAILURE() << preset << ": visibility rises from " << v[i - 1] << " to " << v[i] << " at receiver "
                      << cases[i].receiver << " (z1 " << cases[i].z1 << " z2 " << cases[i].z2 << " p "
                      << cases[i].fraction << ")";
    EXPECT_EQ(rises, 0) << preset;
  }
}

// Mean distance to the true step over receivers away from the edge: shrinks as M grows.
TEST(PrefilteredReconstruction, FourierApproachesTheStepAsTermsGrow) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  std::vector<MomentCase> cases;
  for (float z : {0.3f, 0.5f, 0.7f})
    for (int s = 0; s <= 100; ++s) {
      float r = s / 100.0f;
      if (std::abs(r - z) > 0.05f) cases.push_back({z, z, 1.0f, r});
    }
  std::vector<double> errors;
  for (int m : {1, 2, 4, 8, 16}) {
    const auto v = probe.visibility("convolution",
                                    {"convolution.terms=" + std::to_string(m), "convolution.alpha=0",
                                     "convolution.scale=1", "convolution.offset=0"},
                                    cases);
    ASSERT_EQ(v.size(), cases.size());
    double e = 0;
    for (size_t i = 0; i < v.size(); ++i) e += std::abs(v[i] - (cases[i].receiver < cases[i].z1 ? 1.0 : 0.0));
    errors.push_back(e / v.size());
  }
  std::printf("fourier mean |error| for M = 1, 2, 4, 8, 16: %.4f %.4f %.4f %.4f %.4f\n", errors[0], errors[1],
              errors[2], errors[3], errors[4]);
  for (size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]);
  EXPECT_LT(errors.back(), 0.02);
}

}  // namespace
}  // namespace sl
