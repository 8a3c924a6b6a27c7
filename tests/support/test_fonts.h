// The real DejaVu Sans (fonts-dejavu-core), loaded once per test process, for every test that
// lays out or draws UI text: layout depends on true text metrics. Without the font the process
// stops with the reason (quickstart.sh installs the package).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "ui/font.h"

namespace grass::test {

inline const ui::FontAtlas& testFonts() {
    static std::optional<ui::FontAtlas> fonts = [] {
        std::string error;
        std::optional<ui::FontAtlas> f =
            ui::FontAtlas::load(ui::FontAtlas::defaultFontPath(), &error);
        if (!f) {
            std::fprintf(stderr, "tests need %s: %s\n",
                         ui::FontAtlas::defaultFontPath().string().c_str(), error.c_str());
            std::abort();
        }
        return f;
    }();
    return *fonts;
}

}  // namespace grass::test
