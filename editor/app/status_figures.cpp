#include "app/status_figures.h"

#include <algorithm>

namespace grass::editor {

namespace {

std::string joined(const std::vector<StatusFigure>& figures) {
    std::string line;
    for (const StatusFigure& figure : figures) {
        if (!line.empty())
            line += STATUS_FIGURE_GAP;
        line += figure.text;
    }
    return line;
}

}  // namespace

std::string fitStatusFigures(std::vector<StatusFigure> figures, float room,
                             const std::function<float(std::string_view)>& width) {
    std::erase_if(figures, [](const StatusFigure& figure) { return figure.text.empty(); });
    std::string line = joined(figures);
    while (figures.size() > 1 && width(line) > room) {
        // The least wanted; of equals, the one furthest right.
        auto least = figures.begin();
        for (auto it = figures.begin(); it != figures.end(); ++it)
            if (it->keep <= least->keep)
                least = it;
        figures.erase(least);
        line = joined(figures);
    }
    return line;
}

}  // namespace grass::editor
