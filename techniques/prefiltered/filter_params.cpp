// The parameters every pre-filtered representation shares, and what follows from them.
#include "prefiltered/moment_spec.h"

namespace sl {

namespace {

ParamDecl viewChannelParam() {
  return {.key = "view.channel",
          .type = ParamType::Int,
          .min = 0,
          .max = 31,
          .defaultValue = 0,
          .help = "moments and fourier views: the stored channel shown (Fourier: 2k-2 = sin, 2k-1 = cos of term k)"};
}

ParamDecl skipUnreadParam() {
  return {.key = "filter.skip_unread",
          .type = ParamType::Bool,
          .defaultValue = 1,
          .help =
              "the blur or summed-area table covers only the texels a visible receiver can read (the "
              "fitted layouts' receiver body in the map, widened by the lookup and the widest box; beyond the "
              "papers); the rest hold an earlier frame's moments. Off: the whole map"};
}

}  // namespace

std::vector<ParamDecl> filterParams(bool withSat) {
  std::vector<std::string> methods = {"blur", "mipmap"};
  if (withSat) methods.push_back("sat");
  return {
      {.key = "filter.format",
       .type = ParamType::Enum,
       .defaultValue = 1,
       .help = "storage of each moment: 16- or 32-bit float (16 halves memory and bandwidth; exponents and "
               "variances are clamped to what it holds)",
       .choices = {"float16", "float32"}},
      {.key = "filter.method",
       .type = ParamType::Enum,
       .defaultValue = 0,
       .help = "pre-filter of the moments: separable box blur of filter.width texels, mip-maps read "
               "trilinearly at the level filter.width texels wide, or a 32-bit summed-area table (any width "
               "at the same cost)",
       .choices = methods},
      {.key = "filter.width",
       .type = ParamType::Int,
       .min = 1,
       .max = 63,
       .defaultValue = 5,
       .unit = "texels",
       .help = "width of the box the moments are averaged over (1 = bilinear lookups only)"},
      skipUnreadParam(),
      viewChannelParam(),
  };
}

std::vector<ParamDecl> softFilterParams() { return {skipUnreadParam(), viewChannelParam()}; }

int formatBits(const ParamSet& params) { return params.i("filter.format") == 0 ? 16 : 32; }

float maxWarpExponent(int bits) { return bits == 16 ? 5.54f : 42.0f; }

}  // namespace sl
