// GLSL programs assembled from modules with `#include "path"` (resolved against the shader
// folder, each file once, with #line so errors point at the real file and line), rebuilt when
// any file they use changes on disk, and kept at their last good version when a rebuild fails.
#pragma once

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace sl {

struct ProgramSpec {
  std::string name;                                    // for labels and messages
  std::vector<std::pair<GLenum, std::string>> stages;  // stage, file relative to the shader folder
  std::string prelude;  // generated text placed after #version (technique module includes, defines)
  std::string key() const;
};

class Program {
 public:
  GLuint id() const { return id_; }
  bool valid() const { return id_ != 0; }
  const std::string& error() const { return error_; }  // last build error ("" when the last build worked)
  const std::string& name() const { return name_; }
  void use() const {
    used_ = true;
    glUseProgram(id_);
  }
  GLint location(const std::string& name) const;
  // Setters ignore uniforms the program does not use, so modules may omit parameters. Each
  // one also records that its uniform was set (see ShaderLibrary::checkUnsetUniforms).
  void set(const std::string& name, float v) const;
  void set(const std::string& name, int v) const;
  void set(const std::string& name, const glm::vec2& v) const;
  void set(const std::string& name, const glm::vec3& v) const;
  void set(const std::string& name, const glm::vec4& v) const;
  void set(const std::string& name, const glm::ivec4& v) const;
  void set(const std::string& name, const glm::mat4& v) const;

 private:
  friend class ShaderLibrary;
  void markSet(GLint location) const;
  GLuint id_ = 0;
  std::string name_;
  std::string error_;
  std::map<std::string, std::filesystem::file_time_type> files_;
  mutable std::unordered_map<std::string, GLint> locations_;
  // Since the last link: locations some setter wrote, whether a draw used the program, and
  // whether its active uniforms were already checked against what was set.
  mutable std::set<GLint> setLocations_;
  mutable bool used_ = false;
  bool checked_ = false;
};

class ShaderLibrary {
 public:
  explicit ShaderLibrary(std::string shaderDir);
  ~ShaderLibrary();
  const std::string& directory() const { return dir_; }

  // Builds on first use; later calls return the cached program (last good build).
  Program& get(const ProgramSpec& spec);
  // Rebuilds programs whose files changed; returns how many were rebuilt (successfully or not).
  int reloadChanged();
  // Errors of all programs whose latest build failed, each "file:line: message".
  std::vector<std::string> errors() const;
  int buildCount() const { return builds_; }
  size_t programCount() const { return programs_.size(); }

  // A uniform nobody sets reads 0, so a typo in its name (in GLSL or in C++) fails silently.
  // For every program used since its last link and not checked yet: each active `u_*` uniform
  // that no setter wrote is printed once to stderr ("program 'p': uniform 'u_x' is never
  // set") and kept in unsetUniformReports(). Call it after everything of a frame was drawn
  // (Renderer::render does); GL tests require the reports to stay empty.
  std::vector<std::string> checkUnsetUniforms();
  const std::vector<std::string>& unsetUniformReports() const { return unsetReports_; }

  // Expands includes for a stage; public for tests. Throws std::runtime_error for a missing file.
  std::string assemble(const std::string& file, const std::string& prelude, std::vector<std::string>& fileNames) const;

 private:
  void build(const ProgramSpec& spec, Program& program);
  std::string dir_;
  std::map<std::string, std::pair<ProgramSpec, std::unique_ptr<Program>>> programs_;
  int builds_ = 0;
  std::vector<std::string> unsetReports_;
  std::set<std::string> reported_;  // "program|uniform": each is reported once, even across rebuilds
};

// Default shader folder: $SHADOWLAB_SHADERS, else <source tree>/shaders.
std::string defaultShaderDir();
std::string defaultAssetsDir();

}  // namespace sl
