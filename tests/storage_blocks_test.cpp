// Storage blocks get their binding points by name (gl/storage_blocks.h): the same name is the
// same binding in every program, different names never share one, whatever the shaders declare.
#include "gl/storage_blocks.h"
#include "tests/gl_test_util.h"

#include <filesystem>
#include <fstream>
#include <set>

#include <unistd.h>

namespace sl {
namespace {

namespace fs = std::filesystem;

GLint blockBinding(const Program& p, const char* block) {
  const GLuint index = glGetProgramResourceIndex(p.id(), GL_SHADER_STORAGE_BLOCK, block);
  if (index == GL_INVALID_INDEX) return -1;
  const GLenum prop = GL_BUFFER_BINDING;
  GLint binding = -1;
  glGetProgramResourceiv(p.id(), GL_SHADER_STORAGE_BLOCK, index, 1, &prop, 1, nullptr, &binding);
  return binding;
}

TEST(StorageBlocksGl, OneBindingPerNameAcrossPrograms) {
  const fs::path dir = fs::temp_directory_path() / ("shadowlab-storage-" + std::to_string(::getpid()));
  fs::create_directories(dir / "passes");
  // Both programs would have used binding 0 for different data before names chose them.
  std::ofstream(dir / "passes/a.comp") << "layout(local_size_x = 1) in;\n"
                                          "layout(std430) buffer TestAlpha { uint a[]; };\n"
                                          "layout(std430) buffer TestShared { uint s[]; };\n"
                                          "void main() { a[0] = s[0]; }\n";
  std::ofstream(dir / "passes/b.comp") << "layout(local_size_x = 1) in;\n"
                                          "layout(std430) buffer TestShared { uint s[]; };\n"
                                          "layout(std430) buffer TestBeta { uint b[]; };\n"
                                          "void main() { b[0] = s[0]; }\n";
  test::GlHarness h(dir.string());
  Program& a = h.shaders.get({"a", {{GL_COMPUTE_SHADER, "passes/a.comp"}}, ""});
  Program& b = h.shaders.get({"b", {{GL_COMPUTE_SHADER, "passes/b.comp"}}, ""});
  ASSERT_TRUE(a.valid()) << a.error();
  ASSERT_TRUE(b.valid()) << b.error();
  EXPECT_EQ(blockBinding(a, "TestShared"), blockBinding(b, "TestShared"));
  EXPECT_EQ(blockBinding(a, "TestShared"), static_cast<GLint>(storageBinding("TestShared")));
  const std::set<GLint> distinct = {blockBinding(a, "TestAlpha"), blockBinding(a, "TestShared"),
                                    blockBinding(b, "TestBeta")};
  EXPECT_EQ(distinct.size(), 3u);
  EXPECT_EQ(distinct.count(-1), 0u);
  EXPECT_EQ(glDebugErrorCount(), 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sl
