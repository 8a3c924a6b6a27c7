#include "tools/tradeoff_plot.h"

#include <cstdlib>

#include "tools/tradeoff_report.h"
#include "util/atomic_file.h"
#include "util/printable_text.h"

namespace grass::render {

namespace {

// Every string here comes from tradeoff.json, which `--replot` reads back from any folder: it is
// data, never script. Control characters (a newline would end the gnuplot command) become
// spaces, and text goes into single-quoted gnuplot strings, the one kind in which gnuplot runs
// no `backquoted` command and reads no backslash escape ('' is a quote).

// A single-quoted string for the enhanced-text terminal, which reads _ ^ { } @ & ~ \ as markup:
// the metrics' "v2_ref" must print as written.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : printableText(text)) {
        if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@' || c == '&' || c == '~' ||
            c == '\\')
            out += '\\';
        out += c == '\'' ? std::string("''") : std::string(1, c);
    }
    return out + "'";
}

// A quoted column of the data file: gnuplot's data files have no escape for '"'.
std::string dataLabel(const std::string& text) {
    std::string out = printableText(text);
    for (char& c : out)
        if (c == '"')
            c = '\'';
    return out;
}

// Columns: cost median, min, max, error, on the front (0/1), role (0 setting, 1 reference,
// 2 check), label, the presets this run would choose there ("" for none). Sorted as swept; the
// front is re-sorted by cost in the script.
std::string dataFile(const KnobResult& knob) {
    std::string out = "# " + knob.name + ": " + printableText(knob.description) +
                      "\n# cost: " + printableText(knob.costMetric) +
                      "\n# error: " + printableText(knob.errorMetric) +
                      "\n# cost_median cost_min cost_max error front role label presets\n";
    char line[256];
    const std::vector<std::string> presets = presetLabels(knob);
    for (std::size_t i = 0; i < knob.settings.size(); ++i) {
        const SettingResult& s = knob.settings[i];
        std::snprintf(line, sizeof line, "%.6g %.6g %.6g %.6g %d %d ", s.costMs.median,
                      s.costMs.min, s.costMs.max, s.error, s.pareto ? 1 : 0,
                      s.reference ? 1
                      : s.check   ? 2
                                  : 0);
        out += line + ("\"" + dataLabel(s.label) + "\" \"" + dataLabel(presets[i]) + "\"\n");
    }
    return out;
}

std::string script(const TradeoffReport& report, const KnobResult& knob) {
    const std::string dat = knob.name + ".dat";
    std::string out;
    out += "# gnuplot " + knob.name + ".gp  (writes " + knob.name + ".png)\n";
    out += "set terminal pngcairo size 1000,640 enhanced font 'Sans,11'\n";
    out += "set output '" + knob.name + ".png'\n";
    out += "set title " + quoted(report.project + ": " + knob.description) +
           " . \"\\n\" . '{/*0.8 ' . " +
           quoted(report.device + ", " + std::to_string(report.width) + "×" +
                  std::to_string(report.height)) +
           " . '}'\n";
    out += "set xlabel " + quoted("cost: " + knob.costMetric) + "\n";
    out += "set ylabel " + quoted("error: " + knob.errorMetric) + " font ',9'\n";
    // Costs and errors are never negative: the axes start at 0 and leave room for the labels.
    out += "set grid\nset key top right\nset xrange [0:*]\nset yrange [0:*]\n";
    out += "set offsets 0, graph 0.08, graph 0.12, 0\n";
    // Error bars: the spread (min–max) of the timed frames.
    out += "plot '" + dat +
           "' using 1:4:2:3 with xerrorbars lc rgb '#888888' pt 7 ps 0.8 "
           "title 'setting (cost min–max)', \\\n";
    out += "     '" + dat +
           "' using ($5==1 ? $1 : 1/0):4 smooth unique with linespoints "
           "lc rgb '#d62728' lw 2 pt 7 ps 1.4 title 'Pareto front', \\\n";
    out += "     '" + dat +
           "' using ($6==1 ? $1 : 1/0):4 with points lc rgb '#1f77b4' pt 5 ps 1.8 "
           "title 'reference', \\\n";
    if (!knob.checkLabel.empty())
        out += "     '" + dat +
               "' using ($6==2 ? $1 : 1/0):4 with points lc rgb '#2ca02c' pt 9 ps 1.6 "
               "title 'reference check (finer)', \\\n";
    out += "     '" + dat + "' using 1:4:7 with labels offset 0,1.1 font ',10' notitle, \\\n";
    // The presets the rule picks from this run, under their settings.
    out += "     '" + dat +
           "' using 1:4:8 with labels left offset 0.9,-0.9 font ',9' tc rgb '#9467bd' notitle\n";
    return out;
}

std::string shellQuote(const std::string& text) {
    std::string out = "'";
    for (const char c : text)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

}  // namespace

Result<PlotFiles> writeTradeoffPlots(const TradeoffReport& report,
                                     const std::filesystem::path& folder) {
    PlotFiles files;
    const bool haveGnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
    for (const KnobResult& knob : report.knobs) {
        if (!knob.skipped.empty() || knob.settings.empty())
            continue;
        for (const auto& [name, text] : {std::pair{knob.name + ".dat", dataFile(knob)},
                                         {knob.name + ".gp", script(report, knob)}}) {
            if (auto written = writeFileAtomic(folder / name, text); !written)
                return written.error();
            files.written.push_back(folder / name);
        }
        if (!haveGnuplot)
            continue;
        const std::string command = "cd " + shellQuote(folder.string()) + " && gnuplot " +
                                    shellQuote(knob.name + ".gp") + " 2>&1";
        if (std::system(command.c_str()) != 0) {
            files.warning = "gnuplot failed on " + (folder / (knob.name + ".gp")).string();
            continue;
        }
        files.written.push_back(folder / (knob.name + ".png"));
    }
    if (!haveGnuplot)
        files.warning =
            "gnuplot is not installed (Debian: apt install gnuplot-nox); the plots are "
            "scripts only: run `gnuplot <knob>.gp` in " +
            folder.string();
    return files;
}

}  // namespace grass::render
