#pragma once

#include <string>

namespace sl {
int runRenderCommand(int argc, char** argv);
int runListCommand(int argc, char** argv);
// `list --markdown TABLE` (families, presets, parts): the docs' tables (cli/list_markdown.cpp).
int runListMarkdown(const std::string& table);
int runReferenceCommand(int argc, char** argv);
int runBenchCommand(int argc, char** argv);
int runPlotCommand(int argc, char** argv);
int runFigureCommand(int argc, char** argv);    // tour steps as figures (tour/figure.h)
int runPlotDpdsCommand(int argc, char** argv);  // `plot dpds`, dispatched by runPlotCommand
}  // namespace sl
