// libFuzzer target: lecture-tour text (docs/tour-format.md) through parseTour, which validates
// every step against the technique registry (presets, overrides, views) without a GL context.
// A bad tour must be a TourError naming the file and field, never a crash, hang or leak; other
// exception types (a ParamError escaping the validation, a JSON library error) are bugs too.
#include "tour/tour.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    sl::parseTour(text, "fuzz.json");
  } catch (const sl::TourError&) {
    // the expected answer to bad input
  }
  return 0;
}
