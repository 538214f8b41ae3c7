// The HTML report of `shadowlab bench`: one self-contained page (inline CSS + SVG, a few lines of
// inline script to sort the table, no libraries, no network) plus PNG images and results.csv.
#include "bench/bench.h"
#include "bench/bench_charts.h"
#include "plot/plot.h"
#include "cli/args.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sl {

namespace {

// Excess mean change per frame shown white in the flicker map: an edge pixel the truth flips
// once in a path of 60 frames changes by ~0.017 per frame.
constexpr float kFlickerFullScale = 0.1f;

std::string fixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

const char* kCss = R"(
body{font:16px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;color:#222;max-width:1000px;margin:24px auto;padding:0 16px}
h1{font-size:28px;margin:0 0 4px}h2{font-size:22px;margin:32px 0 8px;border-bottom:2px solid #ddd}
h3{font-size:17px;margin:18px 0 6px}.meta{color:#555;font-size:14px}code{font-size:13px;background:#f3f3f3;padding:1px 4px;word-break:break-all}
.chart{width:100%;height:auto;font-size:14px;font-family:inherit}.chart .grid{stroke:#e3e3e3}.chart .axis{font-size:16px;font-weight:600}
.chart .pt{font-size:13px}.chart .pt.front{font-weight:700}.chart .note{font-size:14px}
.chart .pareto{fill:none;stroke:#333;stroke-width:1.5;stroke-dasharray:5 4}.chart .ring{fill:none;stroke:#333;stroke-width:2}
table{border-collapse:collapse;font-size:14px;width:100%}th,td{padding:4px 8px;border-bottom:1px solid #ddd;text-align:right}
th{background:#f3f3f3;cursor:pointer;user-select:none;position:sticky;top:0}th:first-child,td:first-child{text-align:left}
.strip{display:grid;grid-template-columns:1fr 1fr 1fr;gap:6px}.strip figure{margin:0}.strip img{width:100%;display:block;image-rendering:pixelated;border:1px solid #ccc}
.strip figcaption{font-size:13px;color:#555}.swatch{display:inline-block;width:12px;height:12px;border:1px solid #888;vertical-align:-1px;margin:0 3px 0 10px}
.caption{font-size:14px;color:#444;margin:4px 0 0}
)";

const char* kSortScript = R"(<script>
for (const th of document.querySelectorAll('#results th')) th.addEventListener('click', () => {
  const tb = th.closest('table').tBodies[0], i = th.cellIndex, asc = th.dataset.asc !== '1';
  th.dataset.asc = asc ? '1' : '0';
  const key = td => { const v = parseFloat(td.dataset.v ?? td.textContent); return isNaN(v) ? td.textContent : v; };
  [...tb.rows].sort((a, b) => { const x = key(a.cells[i]), y = key(b.cells[i]);
    return (x < y ? -1 : x > y ? 1 : 0) * (asc ? 1 : -1); }).forEach(r => tb.appendChild(r));
});
</script>)";

std::string fileSafe(const std::string& s) {
  std::string o;
  for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return o;
}

// The chart as a file of its own (docs embed it): its namespace and the page's chart styles.
std::string standaloneSvg(const std::string& svg) {
  const size_t open = svg.find("<svg ");
  const size_t close = svg.find('>', open);
  if (open == std::string::npos || close == std::string::npos) return svg;
  return svg.substr(0, open) + "<svg xmlns='http://www.w3.org/2000/svg' " + svg.substr(open + 5, close - open - 5) +
         " font-family='system-ui,sans-serif' font-size='14'>\n<style>.grid{stroke:#e3e3e3}.axis{font-size:16px;"
         "font-weight:600}</style>\n" +
         svg.substr(close + 1);
}

// The sortable table: one row per entry, and what the columns mean.
std::string resultsTable(const BenchResult& r) {
  const bool path = !r.options.path.empty();
  const std::string base = r.entries.empty() ? std::string() : xmlEscaped(r.entries.front().label);
  std::ostringstream s;
  s << "<h2>Results</h2>\n<table "
       "id='results'><thead><tr><th>entry</th><th>ms/frame<br>median</th><th>ms/frame<br>p95</th>"
       "<th>× entry 1<br>(p25–p75)</th><th>wrong<br>%</th><th>image<br>wrong %</th><th>false shadow<br>%</th>"
       "<th>false light<br>%</th><th>RMSE</th>"
    << (path ? "<th>flicker<br>excess</th><th>world<br>flicker</th>" : "")
    << "<th>NaN/Inf<br>pixels</th></tr></thead><tbody>\n";
  for (const auto& e : r.entries) {
    s << "<tr><td>" << xmlEscaped(e.label) << "</td><td>" << fixed(e.msMedian, 2) << "</td><td>" << fixed(e.msP95, 2)
      << "</td><td data-v='" << e.msRatio << "'>" << fixed(e.msRatio, 2) << " (" << fixed(e.msRatioP25, 2) << "–"
      << fixed(e.msRatioP75, 2) << ")</td><td>" << fixed(e.error.wrongPixelPct, 2) << "</td><td>"
      << fixed(e.image.imageWrongPct, 2) << "</td><td>" << fixed(e.error.falseShadowPct, 2) << "</td><td>"
      << fixed(e.error.falseLightPct, 2) << "</td><td>" << fixed(e.error.rmse, 4) << "</td>";
    if (path) s << "<td>" << fixed(e.flicker, 4) << "</td><td>" << fixed(e.worldFlicker, 5) << "</td>";
    s << "<td>" << e.nonfinite << "</td></tr>\n";
  }
  s << "</tbody></table>\n<p class='caption'>Click a column header to sort. <b>× entry 1</b>: the entries are "
       "rendered in turn at each frame index, and this is the median over frames of the entry's frame time over "
       "that of entry 1 ("
    << base
    << ") at the same frame, with its quartiles: compare costs by this, it holds from run to run where the "
       "ms columns drift with the machine. <b>Image wrong</b>: pixels of the shaded colour image whose R, G or "
       "B differs by more than 30/255 from the same shading with the reference's visibility (Scherzer et al.'s "
       "figure 3); a visibility error the shading hides (grazing light, dark albedo) is wrong but not image "
       "wrong. Per-pass medians are in the JSON (<code>passes</code>) and all columns in <a "
       "href='results.csv'>results.csv</a>."
    << (path ? " Flicker excess: mean absolute frame-to-frame visibility change of the technique minus that of "
               "the reference along the path."
             : "")
    << "</p>\n";
  return s.str();
}

}  // namespace

// The PNGs of each entry (visibility, error view, flicker map along a path); returns their
// file-name stems ("01-standard" ...), in entry order.
std::vector<std::string> writeEntryImages(const BenchResult& r, const std::string& dir) {
  const ReferenceImage& ref = r.lastReference;
  const int w = r.options.width, h = r.options.height;
  std::vector<std::string> names;
  for (size_t i = 0; i < r.entries.size(); ++i) {
    const auto& e = r.entries[i];
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "%02zu-", i + 1);
    std::string base = prefix + fileSafe(shortLabel(e));
    names.push_back(base);
    writePng(dir + "/" + base + "-visibility.png", w, h, visibilityToRgba(e.lastVisibility));
    writePng(dir + "/" + base + "-error.png", w, h,
             errorImage(e.lastVisibility.data(), ref.visibility.data(), ref.valid.data(), e.lastVisibility.size()));
    if (!e.changeMap.empty() && e.changeMap.size() == r.referenceChangeMap.size())
      writePng(dir + "/" + base + "-flicker.png", w, h,
               flickerImage(e.changeMap, r.referenceChangeMap, r.pathValid.data(), kFlickerFullScale));
  }
  return names;
}

// Size, camera, frames, renderer, timer, machine, date, reference, command and source.
std::string metaParagraph(const BenchResult& r) {
  const int w = r.options.width, h = r.options.height;
  const bool path = !r.options.path.empty();
  std::ostringstream s;
  s << "<p class='meta'>" << w << "×" << h << " pixels, "
    << (path ? "camera path <b>" + xmlEscaped(r.options.path) + "</b>"
             : "camera <b>" + xmlEscaped(r.options.camera) + "</b>")
    << ", " << r.options.frames << " measured frames after " << r.options.warmup
    << " warm-up frames, the entries rendered in turn at each frame. Renderer " << xmlEscaped(r.renderer)
    << ", timer <b>" << xmlEscaped(r.timer) << "</b>"
    << (r.timer == "cpu-fence" ? " (glFinish + steady clock around each pass)" : " (GL_TIME_ELAPSED queries)") << ", "
    << r.cores << " cores" << (r.cpu.empty() ? "" : " (" + xmlEscaped(r.cpu) + ")") << ", " << xmlEscaped(r.date)
    << ". Reference: Embree ray-traced visibility of the same G-buffer, " << r.referenceSamples
    << " light sample(s) per pixel.<br>Command: <code>" << xmlEscaped(r.options.commandLine) << "</code><br>Source: "
    << (r.commit.empty() ? std::string("not a git checkout") : "commit <code>" + xmlEscaped(r.commit) + "</code>")
    << (r.dirty ? " with uncommitted changes" : "") << ", build type " << xmlEscaped(r.buildType) << "</p>\n";

  return s.str();
}

// Each entry's images beside the reference, with the colour key of the error and flicker views.
std::string imagesSection(const BenchResult& r, const std::vector<std::string>& names) {
  const bool path = !r.options.path.empty();
  std::ostringstream s;
  s << "<h2>Images (last frame)</h2>\n<p class='caption'>Visibility (white = lit) of the technique, the reference, "
       "and the <b>error view</b>: grey = agrees (reference at half brightness),<span class='swatch' "
       "style='background:#e67800'></span>orange = false shadow,<span class='swatch' style='background:#2878ff'>"
       "</span>blue = false light (light leak),<span class='swatch' style='background:#f0f'></span>magenta = "
       "NaN/Inf, black = background."
    << (path ? " <b>Flicker map</b> (along the path): per pixel, the technique's mean frame-to-frame change minus "
               "the reference's; grey = as steady as the truth, yellow to white = flickers more (white at " +
                   fixed(kFlickerFullScale, 2) + " per frame), blue = steadier (edges that lag or blur)."
             : std::string())
    << "</p>\n";
  for (size_t i = 0; i < r.entries.size(); ++i) {
    const auto& e = r.entries[i];
    s << "<h3 id='e" << i + 1 << "'>" << xmlEscaped(e.label) << " — " << fixed(e.error.wrongPixelPct, 2) << " % wrong, "
      << fixed(e.image.imageWrongPct, 2) << " % image wrong, " << fixed(e.msMedian, 2)
      << " ms</h3>\n<div class='strip'><figure><img src='" << names[i]
      << "-visibility.png' alt='technique'><figcaption>" << xmlEscaped(e.technique)
      << "</figcaption></figure><figure><img src='reference.png' alt='reference'><figcaption>reference (ray "
         "traced)</figcaption></figure><figure><img src='"
      << names[i] << "-error.png' alt='error view'><figcaption>error view</figcaption></figure>";
    if (!e.changeMap.empty())
      s << "<figure><img src='" << names[i] << "-flicker.png' alt='flicker map'><figcaption>flicker map</figcaption>"
        << "</figure>";
    s << "</div>\n";
  }
  return s.str();
}

void writeBenchReport(const BenchResult& r, const std::string& dir) {
  std::filesystem::create_directories(dir);
  writeBenchCsv(r, dir + "/results.csv");
  writePng(dir + "/reference.png", r.options.width, r.options.height, visibilityToRgba(r.lastReference.visibility));
  const std::vector<std::string> names = writeEntryImages(r, dir);
  auto styles = entryStyles(r);
  const bool path = !r.options.path.empty();

  std::ostringstream s;
  s << "<!doctype html>\n<html lang='en'><head><meta charset='utf-8'><title>shadowlab bench: "
    << xmlEscaped(r.sceneName) << "</title>\n<style>" << kCss << "</style></head><body>\n";
  s << "<h1>Shadow error against frame time — scene <em>" << xmlEscaped(r.sceneName) << "</em></h1>\n";
  s << metaParagraph(r);
  if (!r.shaderErrors.empty()) {
    s << "<p style='border:2px solid #c00;padding:8px;color:#900'><b>Shader errors during this run</b>: entries "
         "using the broken shader measured nothing meaningful.<br><code>";
    for (const auto& e : r.shaderErrors) s << xmlEscaped(e.substr(0, 300)) << "<br>";
    s << "</code></p>\n";
  }
  s << "<h2>Error against time</h2>\n" << scatterSvg(r, styles);
  std::string sweepKeys;
  for (const auto& sw : r.options.sweeps) sweepKeys += (sweepKeys.empty() ? "" : ", ") + sw.substr(0, sw.find('='));
  s << "<p class='caption'>Each point is one technique at one sweep setting, labelled with its technique"
    << (sweepKeys.empty() ? std::string() : " and " + xmlEscaped(sweepKeys))
    << ". "
       "Lower left is better. Wrong pixels are those whose visibility differs from the ray-traced reference by "
       "more than 30/255 (Scherzer et al. 2007), in percent of pixels covered by geometry, in the last frame.</p>\n";

  const std::string convergence = convergenceSvg(r, styles);
  {
    std::ofstream svg(dir + "/convergence.svg");
    if (!svg) throw std::runtime_error(dir + "/convergence.svg: cannot write");
    svg << standaloneSvg(convergence);
  }
  s << "<h2>Convergence</h2>\n" << convergence;
  s << "<p class='caption'>Wrong pixels per measured frame, "
    << (path ? "each frame against its own reference (the camera moves)" : "against one reference (still camera)")
    << ". Techniques without temporal accumulation are flat.</p>\n";

  s << resultsTable(r);

  s << imagesSection(r, names);
  s << kSortScript << "\n</body></html>\n";
  std::ofstream f(dir + "/index.html");
  if (!f) throw std::runtime_error(dir + "/index.html: cannot write");
  f << s.str();
}

}  // namespace sl
