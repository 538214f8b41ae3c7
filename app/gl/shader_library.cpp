#include "gl/shader_library.h"

#include "gl/storage_blocks.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <cstring>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace sl {

namespace fs = std::filesystem;

std::string ProgramSpec::key() const {
  std::string k = name + "|";
  for (const auto& s : stages) k += s.second + ";";
  return k + "|" + prelude;
}

std::string defaultShaderDir() {
  if (const char* env = std::getenv("SHADOWLAB_SHADERS")) return env;
  return std::string(SHADOWLAB_SOURCE_DIR) + "/shaders";
}

std::string defaultAssetsDir() {
  if (const char* env = std::getenv("SHADOWLAB_ASSETS")) return env;
  return std::string(SHADOWLAB_SOURCE_DIR) + "/assets";
}

GLint Program::location(const std::string& name) const {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  GLint loc = id_ ? glGetUniformLocation(id_, name.c_str()) : -1;
  locations_[name] = loc;
  return loc;
}

void Program::markSet(GLint l) const { setLocations_.insert(l); }

void Program::set(const std::string& n, float v) const {
  if (GLint l = location(n); l >= 0) {
    glProgramUniform1f(id_, l, v);
    markSet(l);
  }
}
void Program::set(const std::string& n, int v) const {
  if (GLint l = location(n); l >= 0) {
    glProgramUniform1i(id_, l, v);
    markSet(l);
  }
}
void Program::set(const std::string& n, const glm::vec2& v) const {
  if (GLint l = location(n); l >= 0) {
    glProgramUniform2fv(id_, l, 1, glm::value_ptr(v));
    markSet(l);
  }
}
void Program::set(const std::string& n, const glm::vec3& v) const {
  if (GLint l = location(n); l >= 0) {
    glProgramUniform3fv(id_, l, 1, glm::value_ptr(v));
    markSet(l);
  }
}
void Program::set(const std::string& n, const glm::vec4& v) const {
  if (GLint l = location(n); l >= 0) {
    glProgramUniform4fv(id_, l, 1, glm::value_ptr(v));
    markSet(l);
  }
}
void Program::set(const std::string& n, const glm::ivec4& v) const {
  if (GLint l = location(n); l >= 0) {
    glProgramUniform4iv(id_, l, 1, glm::value_ptr(v));
    markSet(l);
  }
}
void Program::set(const std::string& n, const glm::mat4& v) const {
  if (GLint l = location(n); l >= 0) {
    glProgramUniformMatrix4fv(id_, l, 1, GL_FALSE, glm::value_ptr(v));
    markSet(l);
  }
}

ShaderLibrary::ShaderLibrary(std::string shaderDir) : dir_(std::move(shaderDir)) {}

ShaderLibrary::~ShaderLibrary() {
  for (auto& [key, entry] : programs_)
    if (entry.second->id_) glDeleteProgram(entry.second->id_);
}

static std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error(p.string() + ": cannot read shader file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Each file gets a source-string number in #line so that compiler messages can be mapped back.
// Mesa reports some semantic errors with source string 0 whatever #line said, so the file index
// is also folded into the line number (file * kLineStride + line): either way maps back.
static constexpr long kLineStride = 100000;

static std::string lineDirective(int line, int fileIndex) {
  return "#line " + std::to_string(fileIndex * kLineStride + line) + " " + std::to_string(fileIndex) + "\n";
}

std::string ShaderLibrary::assemble(const std::string& file, const std::string& prelude,
                                    std::vector<std::string>& fileNames) const {
  std::set<std::string> included;
  // Modules can keep stage-specific code (gl_FragCoord, derivatives) behind these defines.
  auto endsWith = [&file](const char* ext) {
    const size_t n = std::strlen(ext);
    return file.size() > n && file.compare(file.size() - n, n, ext) == 0;
  };
  const char* stage = endsWith(".vert")   ? "SL_VERTEX"
                      : endsWith(".tesc") ? "SL_TESS_CONTROL"
                      : endsWith(".tese") ? "SL_TESS_EVALUATION"
                      : endsWith(".comp") ? "SL_COMPUTE"
                                          : "SL_FRAGMENT";
  std::string out = std::string("#version 450 core\n#define ") + stage + "\n";
  static const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");

  std::function<void(const std::string&, const std::string&, const std::string&)> expand =
      [&](const std::string& name, const std::string& text, const std::string& from) {
        int index = static_cast<int>(fileNames.size());
        fileNames.push_back(name);
        out += lineDirective(1, index);
        std::istringstream lines(text);
        std::string line;
        int lineNo = 0;
        while (std::getline(lines, line)) {
          ++lineNo;
          std::smatch m;
          if (std::regex_match(line, m, includeRe)) {
            std::string inc = m[1];
            if (!included.count(inc)) {
              included.insert(inc);
              fs::path p = fs::path(dir_) / inc;
              if (!fs::exists(p))
                throw std::runtime_error(name + ":" + std::to_string(lineNo) + ": included file '" + inc +
                                         "' not found in " + dir_);
              expand(inc, readText(p), name);
            }
            out += lineDirective(lineNo + 1, index);
          } else {
            out += line + "\n";
          }
        }
      };
  if (!prelude.empty()) expand("<technique prelude>", prelude, "");
  included.insert(file);
  expand(file, readText(fs::path(dir_) / file), "");
  return out;
}

// Rewrites "0:12(5): error" (Mesa) and "0(12) : error" (NVIDIA) as "file:12: error".
static std::string mapErrorLog(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
  static const std::regex nv(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nv)) {
      size_t idx = std::stoul(m[1]);
      long line = std::stol(m[2]);
      if (line >= kLineStride) {
        idx = static_cast<size_t>(line / kLineStride);
        line %= kLineStride;
      }
      std::string file = idx < files.size() ? files[idx] : "?";
      out += "shaders/" + file + ":" + std::to_string(line) + ": " + std::string(m[m.size() - 1]) + "\n";
    } else if (!line.empty()) {
      out += line + "\n";
    }
  }
  return out;
}

void ShaderLibrary::build(const ProgramSpec& spec, Program& program) {
  ++builds_;
  std::string error;
  std::map<std::string, fs::file_time_type> files;
  std::vector<GLuint> shaders;
  GLuint prog = 0;
  try {
    for (const auto& [stage, file] : spec.stages) {
      std::vector<std::string> names;
      std::string src = assemble(file, spec.prelude, names);
      for (const auto& n : names)
        if (n[0] != '<') files[n] = fs::last_write_time(fs::path(dir_) / n);
      GLuint sh = glCreateShader(stage);
      shaders.push_back(sh);
      const char* p = src.c_str();
      glShaderSource(sh, 1, &p, nullptr);
      glCompileShader(sh);
      GLint ok = 0;
      glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
      if (!ok) {
        GLint len = 0;
        glGetShaderiv(sh, GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
        glGetShaderInfoLog(sh, len, nullptr, log.data());
        error += mapErrorLog(log.c_str(), names);
      }
    }
    if (error.empty()) {
      prog = glCreateProgram();
      for (GLuint sh : shaders) glAttachShader(prog, sh);
      glLinkProgram(prog);
      GLint ok = 0;
      glGetProgramiv(prog, GL_LINK_STATUS, &ok);
      if (!ok) {
        GLint len = 0;
        glGetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
        glGetProgramInfoLog(prog, len, nullptr, log.data());
        error = spec.name + ": link failed: " + std::string(log.c_str());
      }
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  for (GLuint sh : shaders) glDeleteShader(sh);
  // Remember the files even on failure, so that fixing the file triggers the next rebuild.
  for (const auto& [n, t] : files) program.files_[n] = t;
  if (!error.empty()) {
    if (prog) glDeleteProgram(prog);
    program.error_ = spec.name + ":\n" + error;
    return;
  }
  if (program.id_) glDeleteProgram(program.id_);
  program.id_ = prog;
  program.error_.clear();
  program.files_ = files;
  program.locations_.clear();
  program.setLocations_.clear();
  program.used_ = false;
  program.checked_ = false;
  assignStorageBindings(prog);  // storage blocks by name (gl/storage_blocks.h)
  glObjectLabel(GL_PROGRAM, prog, static_cast<GLsizei>(spec.name.size()), spec.name.c_str());
}

Program& ShaderLibrary::get(const ProgramSpec& spec) {
  std::string key = spec.key();
  auto it = programs_.find(key);
  if (it != programs_.end()) return *it->second.second;
  auto program = std::make_unique<Program>();
  program->name_ = spec.name;
  build(spec, *program);
  Program& ref = *program;
  programs_.emplace(key, std::make_pair(spec, std::move(program)));
  return ref;
}

int ShaderLibrary::reloadChanged() {
  int rebuilt = 0;
  for (auto& [key, entry] : programs_) {
    Program& p = *entry.second;
    bool changed = p.files_.empty();
    for (const auto& [file, stamp] : p.files_) {
      std::error_code ec;
      auto now = fs::last_write_time(fs::path(dir_) / file, ec);
      if (ec || now != stamp) changed = true;
    }
    if (changed) {
      build(entry.first, p);
      ++rebuilt;
    }
  }
  return rebuilt;
}

std::vector<std::string> ShaderLibrary::errors() const {
  std::vector<std::string> out;
  for (const auto& [key, entry] : programs_)
    if (!entry.second->error_.empty()) out.push_back(entry.second->error_);
  return out;
}

// Active `u_*` uniforms of `p` (default block only) that no setter wrote since the last link.
static std::vector<std::string> unsetUniforms(const Program& p, const std::set<GLint>& set) {
  std::vector<std::string> out;
  GLint count = 0;
  glGetProgramInterfaceiv(p.id(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    const GLenum props[] = {GL_LOCATION, GL_ARRAY_SIZE, GL_NAME_LENGTH};
    GLint v[3] = {-1, 1, 0};
    glGetProgramResourceiv(p.id(), GL_UNIFORM, static_cast<GLuint>(i), 3, props, 3, nullptr, v);
    if (v[0] < 0 || v[2] <= 1) continue;  // in a uniform block, or a built-in
    std::string name(static_cast<size_t>(v[2]), '\0');
    glGetProgramResourceName(p.id(), GL_UNIFORM, static_cast<GLuint>(i), v[2], nullptr, name.data());
    name.resize(name.find('\0') == std::string::npos ? name.size() : name.find('\0'));
    if (name.compare(0, 2, "u_") != 0) continue;
    // An array counts as set when any element was: callers may fill only what they use.
    auto it = set.lower_bound(v[0]);
    if (it != set.end() && *it < v[0] + std::max(v[1], 1)) continue;
    out.push_back(name);
  }
  return out;
}

std::vector<std::string> ShaderLibrary::checkUnsetUniforms() {
  std::vector<std::string> found;
  for (auto& [key, entry] : programs_) {
    Program& p = *entry.second;
    if (!p.valid() || !p.used_ || p.checked_) continue;
    p.checked_ = true;
    for (const auto& u : unsetUniforms(p, p.setLocations_)) {
      if (!reported_.insert(p.name_ + "|" + u).second) continue;
      std::string msg = "program '" + p.name_ + "': uniform '" + u + "' is never set (reads 0; a misspelt name?)";
      std::fprintf(stderr, "shader warning: %s\n", msg.c_str());
      unsetReports_.push_back(msg);
      found.push_back(msg);
    }
  }
  return found;
}

}  // namespace sl
