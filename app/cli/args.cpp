#include "cli/args.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>

namespace sl {

Args::Args(int argc, char** argv, int first, const std::vector<std::string>& known,
           const std::vector<std::string>& flags) {
  for (int i = first; i < argc; ++i) {
    std::string a = argv[i];
    if (std::find(flags.begin(), flags.end(), a) != flags.end()) {
      values_.emplace_back(a, "1");
      continue;
    }
    if (std::find(known.begin(), known.end(), a) == known.end()) throw ArgError("unknown option '" + a + "'");
    if (i + 1 >= argc) throw ArgError("option '" + a + "' needs a value");
    values_.emplace_back(a, argv[++i]);
  }
}

bool Args::has(const std::string& key) const {
  return std::any_of(values_.begin(), values_.end(), [&](const auto& kv) { return kv.first == key; });
}

std::string Args::get(const std::string& key, const std::string& fallback) const {
  std::string v = fallback;
  for (const auto& kv : values_)
    if (kv.first == key) v = kv.second;
  return v;
}

std::vector<std::string> Args::all(const std::string& key) const {
  std::vector<std::string> out;
  for (const auto& kv : values_)
    if (kv.first == key) out.push_back(kv.second);
  return out;
}

int Args::getInt(const std::string& key, int fallback) const {
  if (!has(key)) return fallback;
  std::string v = get(key);
  char* end = nullptr;
  long n = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || n < 0 || n > 1000000) throw ArgError(key + ": '" + v + "' is not a valid count");
  return static_cast<int>(n);
}

void Args::getSize(const std::string& key, int& w, int& h) const {
  if (!has(key)) return;
  std::string v = get(key);
  auto x = v.find('x');
  // strtol's end pointers point into these strings, so they must outlive the checks below.
  const std::string ws = x == std::string::npos ? "" : v.substr(0, x);
  const std::string hs = x == std::string::npos ? "" : v.substr(x + 1);
  char* e1 = nullptr;
  char* e2 = nullptr;
  long a = std::strtol(ws.c_str(), &e1, 10);
  long b = std::strtol(hs.c_str(), &e2, 10);
  if (x == std::string::npos || *e1 || *e2 || a < 8 || b < 8 || a > 8192 || b > 8192)
    throw ArgError(key + ": expected WIDTHxHEIGHT between 8 and 8192, got '" + v + "'");
  w = static_cast<int>(a);
  h = static_cast<int>(b);
}

void writePng(const std::string& path, int width, int height, const std::vector<unsigned char>& rgbaBottomUp) {
  std::vector<unsigned char> flipped(rgbaBottomUp.size());
  size_t row = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(&rgbaBottomUp[static_cast<size_t>(height - 1 - y) * row], row, &flipped[static_cast<size_t>(y) * row]);
  if (!stbi_write_png(path.c_str(), width, height, 4, flipped.data(), static_cast<int>(row)))
    throw std::runtime_error(path + ": cannot write PNG");
}

}  // namespace sl
