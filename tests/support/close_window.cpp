// close_window NAME: asks the X window whose name contains NAME to close, as a window manager's
// close button does (a WM_DELETE_WINDOW message), for tests of the editor's close button under
// Xvfb, where no window manager runs and xdotool can only destroy or kill a window. Waits up to
// 10 s for the window to appear; exit status 1 when none does.
#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

namespace {

// The window's title: _NET_WM_NAME (UTF-8, what GLFW sets; WM_NAME holds a title with an em dash
// as compound text, which XFetchName does not return), else WM_NAME.
std::string titleOf(Display* display, Window window) {
    Atom type = 0;
    int format = 0;
    unsigned long items = 0, after = 0;
    unsigned char* data = nullptr;
    std::string title;
    if (XGetWindowProperty(display, window, XInternAtom(display, "_NET_WM_NAME", False), 0, 1024,
                           False, XInternAtom(display, "UTF8_STRING", False), &type, &format,
                           &items, &after, &data) == Success &&
        data != nullptr) {
        title.assign(reinterpret_cast<const char*>(data), items);
        XFree(data);
    }
    char* name = nullptr;
    if (title.empty() && XFetchName(display, window, &name) != 0 && name != nullptr) {
        title = name;
        XFree(name);
    }
    return title;
}

// The first window below `window` (itself included) whose title contains `name`.
Window findNamed(Display* display, Window window, const char* name) {
    if (titleOf(display, window).find(name) != std::string::npos)
        return window;
    Window root = 0, parent = 0, *children = nullptr;
    unsigned count = 0;
    if (XQueryTree(display, window, &root, &parent, &children, &count) == 0)
        return 0;
    Window found = 0;
    for (unsigned i = 0; i < count && found == 0; ++i)
        found = findNamed(display, children[i], name);
    if (children != nullptr)
        XFree(children);
    return found;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: close_window NAME (part of the window's title)\n");
        return 2;
    }
    Display* display = XOpenDisplay(nullptr);
    if (display == nullptr) {
        std::fprintf(stderr, "close_window: cannot open the X display (is DISPLAY set?)\n");
        return 2;
    }
    Window target = 0;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while ((target = findNamed(display, DefaultRootWindow(display), argv[1])) == 0 &&
           std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (target == 0) {
        std::fprintf(stderr, "close_window: no window named like \"%s\"\n", argv[1]);
        XCloseDisplay(display);
        return 1;
    }
    XEvent event{};
    event.xclient.type = ClientMessage;
    event.xclient.window = target;
    event.xclient.message_type = XInternAtom(display, "WM_PROTOCOLS", False);
    event.xclient.format = 32;
    event.xclient.data.l[0] = static_cast<long>(XInternAtom(display, "WM_DELETE_WINDOW", False));
    event.xclient.data.l[1] = CurrentTime;
    XSendEvent(display, target, False, NoEventMask, &event);
    XFlush(display);
    XCloseDisplay(display);
    return 0;
}
