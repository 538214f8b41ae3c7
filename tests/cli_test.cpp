// The command line as a user meets it: list, render with stats, and clear errors for bad input.
#include "gl_test_util.h"
#include "sanitizer_report.h"
#include "technique.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <fstream>

namespace sl {

struct CliRunResult {
  int code = -1;
  std::string output;
};

static CliRunResult runCli(const std::string& args) {
  std::string cmd = std::string(SHADOWLAB_BINARY) + " " + args + " 2>&1";
  CliRunResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  test::expectNoSanitizerReport(r.output, args);
  return r;
}

TEST(Cli, ListShowsEveryPresetParameterAndScene) {
  CliRunResult r = runCli("list");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const auto& p : allPresets()) EXPECT_NE(r.output.find(p.id), std::string::npos) << p.id;
  for (const auto& d : commonParams()) EXPECT_NE(r.output.find(d.key), std::string::npos) << d.key;
  EXPECT_NE(r.output.find("64..8192"), std::string::npos);
  EXPECT_NE(r.output.find("pcf.kernel"), std::string::npos);
  for (const std::string s : {"basic", "columns", "dueling-frusta", "terrain", "thin-casters"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s;
}

// Each family's README quotes its parameters from this table: every key its parts declare, each
// with the values its presets set; an unknown family is an error naming it.
TEST(Cli, FamilyParameterTableHoldsEveryKeyOfItsParts) {
  for (const Family& f : allFamilies()) {
    CliRunResult r = runCli("list --markdown params:" + f.id);
    ASSERT_EQ(r.code, 0) << f.id << ": " << r.output;
    auto expectKeys = [&](const std::vector<ParamDecl>& decls) {
      for (const auto& d : decls)
        EXPECT_NE(r.output.find("| `" + d.key + "` |"), std::string::npos) << f.id << " " << d.key;
    };
    for (const auto& l : f.layouts) expectKeys(l->params());
    for (const auto& rep : f.representations) expectKeys(rep->params());
    for (const auto& a : f.accumulations) expectKeys(a->params());
  }
  CliRunResult common = runCli("list --markdown params:common");
  for (const auto& d : commonParams())
    EXPECT_NE(common.output.find("| `" + d.key + "` |"), std::string::npos) << "common " << d.key;
  CliRunResult prefiltered = runCli("list --markdown params:prefiltered");
  EXPECT_NE(prefiltered.output.find("`msm16`: float16"), std::string::npos) << prefiltered.output;
  CliRunResult unknown = runCli("list --markdown params:no-such-family");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.output.find("no family 'no-such-family'"), std::string::npos) << unknown.output;
}

TEST(Cli, RenderWritesPngAndStats) {
  std::string png = ::testing::TempDir() + "cli_render.png", stats = ::testing::TempDir() + "cli_render.json";
  CliRunResult r =
      runCli("render --scene basic --technique pcf --set shadowmap.size=512 --size 96x64 --frames 3 --out " + png +
             " --stats " + stats);
  ASSERT_EQ(r.code, 0) << r.output;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["technique"], "pcf");
  EXPECT_EQ(j["params"]["shadowmap.size"], "512");
  EXPECT_EQ(j["nonfinite_pixels"], 0);
  EXPECT_TRUE(j["shader_errors"].empty());
  EXPECT_GT(j["ms_per_frame"].get<double>(), 0.0);
  EXPECT_EQ(j["passes"].size(), 3u);  // gbuffer, shadowmap, shade (+visibility)
  EXPECT_EQ(j["gl_errors"], 0);
  EXPECT_EQ(j["shadow_texels"], 512 * 512);  // the one depth layer
  EXPECT_TRUE(std::ifstream(png).good());
}

TEST(Cli, RenderStatsOfAVirtualMapCountAtlasAndPageTable) {
  std::string png = ::testing::TempDir() + "cli_virtual.png", stats = ::testing::TempDir() + "cli_virtual.json";
  CliRunResult r = runCli(
      "render --scene basic --technique virtual --set virtual.size=4096 --set virtual.pool=512 "
      "--size 96x64 --frames 2 --out " +
      png + " --stats " + stats);
  ASSERT_EQ(r.code, 0) << r.output;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
  // 512² atlas + page table of 32 pages per side (the finest resident page per level-0 page).
  EXPECT_EQ(j["shadow_texels"], 512 * 512 + 32 * 32);
  EXPECT_NE(j["status"]["layout"].get<std::string>().find("virtual 4096² in 16 tiles"), std::string::npos)
      << j["status"];
  EXPECT_EQ(j["passes"][1], "virtual.pages[0]");
  EXPECT_EQ(j["nonfinite_pixels"], 0);
  EXPECT_EQ(j["gl_errors"], 0);
}

TEST(Cli, RenderViewAddsItsPass) {
  std::string png = ::testing::TempDir() + "cli_view.png", stats = ::testing::TempDir() + "cli_view.json";
  CliRunResult r = runCli("render --scene basic --view aliasing --size 64x40 --out " + png + " --stats " + stats);
  ASSERT_EQ(r.code, 0) << r.output;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["passes"].back(), "view.aliasing[0]");
  r = runCli("render --scene basic --view nosuch --size 64x40 --out " + png);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("unknown view 'nosuch'"), std::string::npos) << r.output;
}

TEST(Cli, BadInputGetsAClearErrorNamingTheFile) {
  std::string out = " --size 32x32 --out " + ::testing::TempDir() + "bad.png";
  struct Case {
    std::string file, text, expect;
  };
  std::vector<Case> cases = {
      {"malformed.json", "{\"objects\": [", "malformed.json"},
      {"unknown_key.json", R"({"objetcs": []})", "objetcs"},
      {"near_far.json",
       R"({"objects":[{"shape":"box","size":[1,1,1]}],"cameras":[{"name":"c","position":[0,0,5],"target":[0,0,0],"near":5,"far":1}]})",
       "near"},
      {"missing_gltf.json", R"({"models":[{"file":"nowhere.gltf"}]})", "nowhere.gltf"},
      {"empty.json", R"({"objects": []})", "empty.json"},
      {"zero_size.json", R"({"objects":[{"shape":"box","size":[1,0,1]}]})", "size"},
  };
  for (const auto& c : cases) {
    std::string path = test::writeTempFile(c.file, c.text);
    CliRunResult r = runCli("render --scene " + path + out);
    EXPECT_EQ(r.code, 1) << c.file << ": " << r.output;
    EXPECT_NE(r.output.find(c.file), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("Segmentation"), std::string::npos);
  }
  CliRunResult r = runCli("render --scene basic --set shadowmap.size=99999" + out);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("shadowmap.size"), std::string::npos) << r.output;
  r = runCli("render --scene basic --technique nosuch" + out);
  EXPECT_NE(r.output.find("unknown technique 'nosuch'"), std::string::npos) << r.output;
  r = runCli("render --scene basic --size 0x10 --out " + ::testing::TempDir() + "bad.png");
  EXPECT_NE(r.output.find("WIDTHxHEIGHT"), std::string::npos) << r.output;
  r = runCli("render --scene nosuchscene" + out);
  EXPECT_NE(r.output.find("nosuchscene"), std::string::npos) << r.output;
}

}  // namespace sl
