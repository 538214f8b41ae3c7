// Shader storage blocks get their binding points by name, as samplers get texture units: the
// shader library points every block of a program it links at storageBinding(block name), and
// C++ binds a buffer with bindStorage(block name, buffer). No shader or part writes a binding
// number, and two blocks of different names never share one (they did: 3 was DepthBounds,
// DeepCounts and IzbAlpha, 6 SlVolumes and IzbBlockSums).
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace sl {

// The binding point of storage block `block` (its name in GLSL: `buffer NAME { ... }`), the same
// for the whole process; the first request assigns the next free one. Throws std::runtime_error
// when the names outnumber the context's GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS.
GLuint storageBinding(const std::string& block);
// glBindBufferBase of `buffer` at the binding point of `block`.
void bindStorage(const std::string& block, GLuint buffer);
// Points each active storage block of a linked program at its binding (the shader library does
// this after every link).
void assignStorageBindings(GLuint program);
// The block names assigned so far, in binding order (index = binding point).
std::vector<std::string> storageBlockNames();

// A float a shader stored with atomicMin/atomicMax as an order-preserving uint (GLSL
// `orderedBits`: the sign bit set for positives, every bit flipped for negatives), read back.
inline float floatFromOrderedBits(uint32_t u) {
  u = (u & 0x80000000u) != 0u ? u & 0x7fffffffu : ~u;
  float f;
  std::memcpy(&f, &u, sizeof(f));
  return f;
}

}  // namespace sl
