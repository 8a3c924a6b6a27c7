#include "app/input_script.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace grass::editor {

namespace {

constexpr int MAX_WAIT_FRAMES = 100000;

// The state carried from frame to frame: where the pointer is, what is held.
struct Player {
    InputState now;
    std::vector<ScriptFrame> frames;
    std::string phase;

    // Frames still to be merged into the next (`batch N`).
    int merging = 0;

    // One frame with `input`; per-frame fields start cleared again. While merging, the input
    // stays for the next frame instead (all of it arrives in one, as at a low frame rate).
    void emit(const std::string& screenshot = {}) {
        if (merging > 0 && screenshot.empty()) {
            --merging;
            return;
        }
        frames.push_back(ScriptFrame{now, screenshot, 0.0, phase});
        now.dragDx = now.dragDy = now.scrollSteps = 0.0;
        now.leftPressed = now.escapePressed = now.frameRequested = false;
        now.typed.clear();
        now.keys.clear();
        now.buttonEvents.clear();
        now.leftPath.clear();
        now.dropped.clear();
        now.toggledCullTest = 0;
        now.nextTechnique = now.toggleLighting = false;
    }
    void moveTo(double x, double y) {
        if (now.leftDown || now.middleDown || now.rightDown) {
            now.dragDx += x - now.cursorX;
            now.dragDy += y - now.cursorY;
        }
        if (now.leftDown)
            now.leftPath.emplace_back(float(x), float(y));
        now.cursorX = x;
        now.cursorY = y;
    }
    // A left drag through `points` as the window delivers it at a low frame rate: the press at
    // the first point, the moves to the others spread over `frameCount` frames, the release at the
    // last with the last frame's moves (each button change an event at its place, the moves
    // the pointer's path); one frame: a whole flick.
    void slowStroke(const std::vector<ui::Vec2>& points, int frameCount) {
        moveTo(points[0].x, points[0].y);
        now.buttonEvents.push_back(
            {0, true, points[0], -1.0, now.typed.size(), now.leftPath.size(), now.keys.size()});
        now.leftDown = now.leftPressed = true;
        const std::size_t moves = points.size() - 1;
        const auto frameOf = [&](std::size_t move) {
            return (move - 1) * std::size_t(frameCount) / moves;
        };
        for (std::size_t i = 1; i <= moves; ++i) {
            moveTo(points[i].x, points[i].y);
            if (i == moves) {
                now.buttonEvents.push_back({0, false, points[i], -1.0, now.typed.size(),
                                            now.leftPath.size(), now.keys.size()});
                now.leftDown = false;
            }
            // The frame ends after the last move that falls into it.
            if (i == moves || frameOf(i + 1) != frameOf(i))
                emit();
        }
    }
    bool* button(const std::string& name) {
        if (name.empty() || name == "left")
            return &now.leftDown;
        if (name == "right")
            return &now.rightDown;
        if (name == "middle")
            return &now.middleDown;
        return nullptr;
    }
};

std::optional<ui::Key> keyNamed(const std::string& name) {
    static const std::pair<const char*, ui::Key> KEYS[] = {
        {"left", ui::Key::Left},   {"right", ui::Key::Right}, {"up", ui::Key::Up},
        {"down", ui::Key::Down},   {"home", ui::Key::Home},   {"end", ui::Key::End},
        {"backspace", ui::Key::Backspace}, {"delete", ui::Key::Delete},
        {"enter", ui::Key::Enter}, {"escape", ui::Key::Escape}, {"tab", ui::Key::Tab},
        {"a", ui::Key::A}, {"c", ui::Key::C}, {"v", ui::Key::V}, {"x", ui::Key::X},
        {"z", ui::Key::Z}, {"y", ui::Key::Y}, {"s", ui::Key::S},
        {"n", ui::Key::N}, {"o", ui::Key::O}};
    for (const auto& [text, key] : KEYS)
        if (name == text)
            return key;
    return std::nullopt;
}

// A key as GLFW would deliver it: a UI key event for keys the UI knows, typed text for
// printable characters without Ctrl, and the viewport's shortcut flags.
bool pressKey(Player& p, std::string spec) {
    ui::Modifiers mods = p.now.modifiers;
    for (;;) {
        if (spec.rfind("ctrl+", 0) == 0 && spec.size() > 5) {
            mods.ctrl = true;
            spec = spec.substr(5);
        } else if (spec.rfind("shift+", 0) == 0 && spec.size() > 6) {
            mods.shift = true;
            spec = spec.substr(6);
        } else {
            break;
        }
    }
    if (spec == "space")
        spec = " ";
    const auto key = keyNamed(spec);
    if (key)
        p.now.keys.push_back(ui::KeyEvent{*key, mods, p.now.typed.size()});
    if (spec == "escape")
        p.now.escapePressed = true;
    if (spec.size() == 1 && !mods.ctrl) {
        const char c = spec[0];
        p.now.typed += mods.shift && c >= 'a' && c <= 'z' ? char(c - 'a' + 'A') : c;
        if (c == 'f')
            p.now.frameRequested = true;
        else if (c >= '1' && c <= '4')
            p.now.toggledCullTest = c - '0';
        else if (c == 't')
            p.now.nextTechnique = true;
        else if (c == 'l')
            p.now.toggleLighting = true;
    } else if (!key) {
        return false;
    }
    return true;
}

bool finite(std::initializer_list<double> values) {
    for (const double v : values)
        if (!std::isfinite(v))
            return false;
    return true;
}

}  // namespace

Result<std::vector<ScriptFrame>> parseInputScript(const std::string& text,
                                                  const std::filesystem::path& file) {
    Player p;
    p.now.cursorInside = true;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    const auto fail = [&](const std::string& message) {
        return Error{file.string() + ":" + std::to_string(number), message};
    };
    while (std::getline(lines, line)) {
        ++number;
        if (const auto hash = line.find('#'); hash != std::string::npos)
            line.erase(hash);
        std::istringstream in(line);
        std::string command;
        if (!(in >> command))
            continue;
        if (command == "wait") {
            int frames = 0;
            if (!(in >> frames) || frames < 1 || frames > MAX_WAIT_FRAMES)
                return fail("wait: expected a frame count 1…" + std::to_string(MAX_WAIT_FRAMES));
            for (int i = 0; i < frames; ++i)
                p.emit();
        } else if (command == "wait-s") {
            double seconds = 0.0;
            if (!(in >> seconds) || !(seconds > 0.0 && seconds <= 86400.0))
                return fail("wait-s: expected seconds, more than 0 and at most 86400");
            p.emit();
            p.frames.back().holdS = seconds;
        } else if (command == "phase") {
            if (!(in >> p.phase))
                return fail("phase: expected a name");
        } else if (command == "move") {
            double x = 0, y = 0;
            if (!(in >> x >> y) || !finite({x, y}))
                return fail("move: expected X Y");
            p.moveTo(x, y);
            p.emit();
        } else if (command == "press" || command == "release") {
            std::string which;
            in >> which;
            bool* button = p.button(which);
            if (!button)
                return fail(command + ": unknown button '" + which + "' (left, right, middle)");
            *button = command == "press";
            if (command == "press" && button == &p.now.leftDown)
                p.now.leftPressed = true;
            p.emit();
        } else if (command == "click" || command == "doubleclick") {
            // Press and release inside one frame, as a quick click arrives at a low frame rate.
            double x = 0, y = 0;
            if (!(in >> x >> y) || !finite({x, y}))
                return fail(command + ": expected X Y");
            p.moveTo(x, y);
            const ui::Vec2 at{float(x), float(y)};
            for (int i = 0; i < (command == "click" ? 1 : 2); ++i) {
                p.now.buttonEvents.push_back({0, true, at, -1.0, p.now.typed.size(),
                                              p.now.leftPath.size(), p.now.keys.size()});
                p.now.buttonEvents.push_back({0, false, at, -1.0, p.now.typed.size(),
                                              p.now.leftPath.size(), p.now.keys.size()});
            }
            p.now.leftPressed = true;
            p.emit();
        } else if (command == "drag") {
            double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
            int steps = 0;
            if (!(in >> x0 >> y0 >> x1 >> y1 >> steps) || !finite({x0, y0, x1, y1}) ||
                steps < 1 || steps > MAX_WAIT_FRAMES)
                return fail("drag: expected X0 Y0 X1 Y1 N (N frames, at least 1)");
            p.moveTo(x0, y0);
            p.emit();
            p.now.leftDown = p.now.leftPressed = true;
            p.emit();
            for (int i = 1; i <= steps; ++i) {
                const double f = double(i) / steps;
                p.moveTo(x0 + f * (x1 - x0), y0 + f * (y1 - y0));
                p.emit();
            }
            p.now.leftDown = false;
            p.emit();
        } else if (command == "stroke") {
            double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
            int steps = 0;
            if (!(in >> x0 >> y0 >> x1 >> y1 >> steps) || !finite({x0, y0, x1, y1}) || steps < 1 ||
                steps > MAX_WAIT_FRAMES)
                return fail("stroke: expected X0 Y0 X1 Y1 N (N frames, at least 1)");
            std::vector<ui::Vec2> points{{float(x0), float(y0)}};
            for (int i = 1; i <= steps; ++i) {
                const double f = double(i) / steps;
                points.emplace_back(float(x0 + f * (x1 - x0)), float(y0 + f * (y1 - y0)));
            }
            p.slowStroke(points, steps);
        } else if (command == "strokepath") {
            int steps = 0;
            std::vector<ui::Vec2> points;
            double x = 0, y = 0;
            in >> steps;
            while (in >> x >> y && finite({x, y}))
                points.emplace_back(float(x), float(y));
            if (steps < 1 || steps > MAX_WAIT_FRAMES || points.size() < 2 ||
                std::size_t(steps) > points.size() - 1)
                return fail("strokepath: expected N X0 Y0 X1 Y1 ... (N frames, 1 to the moves)");
            p.slowStroke(points, steps);
        } else if (command == "batch") {
            int count = 0;
            if (!(in >> count) || count < 2 || count > MAX_WAIT_FRAMES)
                return fail("batch: expected N, the frames to merge into one (at least 2)");
            p.merging = count - 1;
        } else if (command == "hold") {
            std::string what;
            in >> what;
            ui::Modifiers mods;
            if (what != "none") {
                std::istringstream parts(what);
                std::string part;
                while (std::getline(parts, part, '+')) {
                    if (part == "ctrl")
                        mods.ctrl = true;
                    else if (part == "shift")
                        mods.shift = true;
                    else
                        return fail("hold: expected ctrl, shift, ctrl+shift or none");
                }
            }
            p.now.modifiers = mods;
            p.now.shiftDown = mods.shift;
        } else if (command == "key") {
            std::string spec;
            if (!(in >> spec) || !pressKey(p, spec))
                return fail("key: unknown key '" + spec + "'");
            p.emit();
        } else if (command == "type") {
            std::string rest;
            std::getline(in >> std::ws, rest);
            p.now.typed += rest;
            p.emit();
        } else if (command == "drop") {
            // A file dropped on the window (relative to the script's folder), as GLFW delivers it.
            std::string name;
            std::getline(in >> std::ws, name);
            if (name.empty())
                return fail("drop: expected a file path");
            const std::filesystem::path path = std::filesystem::path(name).is_absolute()
                                                   ? std::filesystem::path(name)
                                                   : file.parent_path() / name;
            p.now.dropped.push_back(path.string());
            p.emit();
        } else if (command == "pressure") {
            double pressure = 0;
            if (!(in >> pressure) || !(pressure >= 0.0 && pressure <= 1.0))
                return fail("pressure: expected a value in 0…1");
            p.now.pressure = float(pressure);
        } else if (command == "minimise" || command == "restore") {
            p.now.minimised = command == "minimise";
            p.emit();
        } else if (command == "screenshot") {
            std::string name;
            if (!(in >> name))
                return fail("screenshot: expected a file name");
            const std::filesystem::path shot = std::filesystem::path(name).is_absolute()
                                                   ? std::filesystem::path(name)
                                                   : file.parent_path() / name;
            p.emit(shot.string());
        } else if (command == "quit") {
            break;
        } else {
            return fail("unknown command '" + command +
                        "' (wait, move, press, release, drag, hold, key, type, drop, pressure, "
                        "minimise, restore, screenshot, quit)");
        }
    }
    return std::move(p.frames);
}

Result<std::vector<ScriptFrame>> loadInputScript(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
        return Error{file.string(), "cannot read the script (does it exist?)"};
    std::stringstream text;
    text << in.rdbuf();
    return parseInputScript(text.str(), file);
}

}  // namespace grass::editor
