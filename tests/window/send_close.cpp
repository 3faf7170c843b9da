// send_close: closes an X11 window the way a window manager does when the user clicks its
// close button, for the window tests (Xvfb runs no window manager).
//
//   send_close WINDOW_TITLE [--after-ms N] [--timeout-ms M]
//
// Polls every 20 ms (up to --timeout-ms, default 20000) for a window whose WM_NAME or
// _NET_WM_NAME is exactly WINDOW_TITLE and whose WM_PROTOCOLS lists WM_DELETE_WINDOW,
// searching the whole window tree from the root (a window manager, if any, reparents client
// windows into frames). Then waits --after-ms (default 0) and sends it the ICCCM
// WM_PROTOCOLS / WM_DELETE_WINDOW client message, as a window manager does.
// Exit status: 0 sent, 1 no such window in time, 2 usage error or no display.

#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <chrono>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>

namespace {

constexpr int kExitSent = 0;
constexpr int kExitNotFound = 1;
constexpr int kExitUsage = 2;
constexpr int kPollMs = 20;

// Windows can vanish between XQueryTree and the next request about them; that BadWindow is
// expected and must not end the program (Xlib's default handler exits).
int ignoreXErrors(Display*, XErrorEvent*) { return 0; }

struct Atoms {
    Atom wmProtocols;
    Atom wmDelete;
    Atom netWmName;
    Atom utf8String;
};

bool hasWmName(Display* display, Window window, const std::string& title) {
    char* name = nullptr;
    bool match = false;
    if (XFetchName(display, window, &name) != 0 && name != nullptr) {
        match = title == name;
    }
    if (name != nullptr) XFree(name);
    return match;
}

bool hasNetWmName(Display* display, Window window, const Atoms& atoms, const std::string& title) {
    Atom type = None;
    int format = 0;
    unsigned long count = 0, remaining = 0;
    unsigned char* data = nullptr;
    const int status = XGetWindowProperty(display, window, atoms.netWmName, 0, 4096, False, atoms.utf8String, &type,
                                          &format, &count, &remaining, &data);
    bool match = false;
    if (status == Success && data != nullptr && type == atoms.utf8String && format == 8) {
        match = std::string_view(reinterpret_cast<const char*>(data), count) == title;
    }
    if (data != nullptr) XFree(data);
    return match;
}

bool acceptsDelete(Display* display, Window window, const Atoms& atoms) {
    Atom* protocols = nullptr;
    int count = 0;
    bool found = false;
    if (XGetWMProtocols(display, window, &protocols, &count) != 0) {
        for (int i = 0; i < count; ++i) found = found || protocols[i] == atoms.wmDelete;
    }
    if (protocols != nullptr) XFree(protocols);
    return found;
}

struct Search {
    Window found = None;
    bool namedWithoutDelete = false;  // a window has the title but no WM_DELETE_WINDOW (yet)
};

void findWindow(Display* display, Window window, const Atoms& atoms, const std::string& title, Search& search) {
    if (search.found != None) return;
    if (hasWmName(display, window, title) || hasNetWmName(display, window, atoms, title)) {
        if (acceptsDelete(display, window, atoms)) {
            search.found = window;
            return;
        }
        search.namedWithoutDelete = true;
    }
    Window root = None, parent = None;
    Window* children = nullptr;
    unsigned int count = 0;
    if (XQueryTree(display, window, &root, &parent, &children, &count) == 0) return;
    for (unsigned int i = 0; i < count && search.found == None; ++i) {
        findWindow(display, children[i], atoms, title, search);
    }
    if (children != nullptr) XFree(children);
}

bool parseMs(std::string_view text, long& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end && out >= 0;
}

int usage(const char* message) {
    if (message != nullptr) std::fprintf(stderr, "send_close: error: %s\n", message);
    std::fputs("usage: send_close WINDOW_TITLE [--after-ms N] [--timeout-ms M]\n", stderr);
    return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
    std::string title;
    bool haveTitle = false;
    long afterMs = 0;
    long timeoutMs = 20000;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--after-ms" || arg == "--timeout-ms") {
            if (i + 1 >= argc) return usage("option needs a value");
            if (!parseMs(argv[++i], arg == "--after-ms" ? afterMs : timeoutMs)) {
                return usage("milliseconds must be a non-negative integer");
            }
        } else if (arg == "--help" || arg == "-h") {
            return usage(nullptr);
        } else if (!haveTitle) {
            title = std::string(arg);
            haveTitle = true;
        } else {
            return usage("more than one window title given");
        }
    }
    if (!haveTitle) return usage("no window title given");

    Display* display = XOpenDisplay(nullptr);
    if (display == nullptr) {
        const char* name = std::getenv("DISPLAY");
        std::fprintf(stderr, "send_close: error: cannot open X display '%s'\n", name != nullptr ? name : "");
        return kExitUsage;
    }
    XSetErrorHandler(ignoreXErrors);
    const Atoms atoms{
        XInternAtom(display, "WM_PROTOCOLS", False),
        XInternAtom(display, "WM_DELETE_WINDOW", False),
        XInternAtom(display, "_NET_WM_NAME", False),
        XInternAtom(display, "UTF8_STRING", False),
    };

    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
    Search search;
    for (;;) {
        search = Search{};
        findWindow(display, DefaultRootWindow(display), atoms, title, search);
        if (search.found != None || Clock::now() >= deadline) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(kPollMs));
    }
    if (search.found == None) {
        std::fprintf(stderr, "send_close: no window titled '%s'%s within %ld ms\n", title.c_str(),
                     search.namedWithoutDelete ? " accepting WM_DELETE_WINDOW" : "", timeoutMs);
        XCloseDisplay(display);
        return kExitNotFound;
    }

    std::this_thread::sleep_for(std::chrono::milliseconds(afterMs));

    // ICCCM 4.2.8.1: what a window manager sends when the user asks to close the window.
    XEvent event;
    std::memset(&event, 0, sizeof event);
    event.xclient.type = ClientMessage;
    event.xclient.window = search.found;
    event.xclient.message_type = atoms.wmProtocols;
    event.xclient.format = 32;
    event.xclient.data.l[0] = static_cast<long>(atoms.wmDelete);
    event.xclient.data.l[1] = CurrentTime;
    const Status sent = XSendEvent(display, search.found, False, NoEventMask, &event);
    XFlush(display);
    XSync(display, False);
    XCloseDisplay(display);
    if (sent == 0) {
        std::fprintf(stderr, "send_close: XSendEvent failed for window 0x%lx\n", search.found);
        return kExitNotFound;
    }
    std::printf("send_close: sent WM_DELETE_WINDOW to 0x%lx\n", search.found);
    return kExitSent;
}
