// The SVG charts of the bench report: error against time (with the Pareto front) and
// convergence per frame, and the colours and labels they share with the report's tables.
#pragma once

#include "bench/bench.h"

#include <string>
#include <vector>

namespace sl {

// An entry's colour and dash pattern in every chart and legend of one report.
struct Style {
  std::string color, dash;
};

// Colour per technique and dash pattern per position in its sweep while that tells every entry
// apart; a technique with more than four sweep points takes the next colours too.
std::vector<Style> entryStyles(const BenchResult& r);

// "pcf 1024": technique plus sweep values only, for point labels, legends and file names.
std::string shortLabel(const BenchEntry& e);

// Wrong pixels against median frame time, one point per entry, the Pareto front ringed.
std::string scatterSvg(const BenchResult& r, const std::vector<Style>& styles);

// Wrong pixels per measured frame, one line per entry.
std::string convergenceSvg(const BenchResult& r, const std::vector<Style>& styles);

}  // namespace sl
