#include "gl/storage_blocks.h"

#include <mutex>
#include <stdexcept>

namespace sl {

namespace {

std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}

std::vector<std::string>& registry() {
  static std::vector<std::string> names;
  return names;
}

}  // namespace

GLuint storageBinding(const std::string& block) {
  std::lock_guard<std::mutex> lock(registryMutex());
  std::vector<std::string>& names = registry();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == block) return static_cast<GLuint>(i);
  GLint limit = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &limit);
  if (static_cast<GLint>(names.size()) >= limit)
    throw std::runtime_error("storage block '" + block + "': the context has " + std::to_string(limit) +
                             " storage-buffer bindings and " + std::to_string(names.size()) +
                             " block names hold them all");
  names.push_back(block);
  return static_cast<GLuint>(names.size() - 1);
}

void bindStorage(const std::string& block, GLuint buffer) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, storageBinding(block), buffer);
}

void assignStorageBindings(GLuint program) {
  GLint blocks = 0;
  glGetProgramInterfaceiv(program, GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
  for (GLint i = 0; i < blocks; ++i) {
    char name[128] = {};
    glGetProgramResourceName(program, GL_SHADER_STORAGE_BLOCK, static_cast<GLuint>(i), sizeof name, nullptr, name);
    glShaderStorageBlockBinding(program, static_cast<GLuint>(i), storageBinding(name));
  }
}

std::vector<std::string> storageBlockNames() {
  std::lock_guard<std::mutex> lock(registryMutex());
  return registry();
}

}  // namespace sl
