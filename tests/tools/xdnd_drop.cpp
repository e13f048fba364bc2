// xdnd_drop NAME PATH [TIMEOUT_S]: drops the file PATH onto the first top-level X11 window whose title
// contains NAME, as a file manager does (XDND version 5, type text/uri-list), and waits until the target
// reports XdndFinished. Exit 0 on success, 1 with a one-line reason otherwise. Used to test the app's
// drag-and-drop end to end under Xvfb: the real GLFW drop path, not a stand-in.
#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

using Clock = std::chrono::steady_clock;

struct Atoms {
    Atom aware, enter, position, status, drop, finished, selection, action_copy, uri_list, net_wm_name, utf8;
    explicit Atoms(Display* d)
        : aware(XInternAtom(d, "XdndAware", False)), enter(XInternAtom(d, "XdndEnter", False)),
          position(XInternAtom(d, "XdndPosition", False)), status(XInternAtom(d, "XdndStatus", False)),
          drop(XInternAtom(d, "XdndDrop", False)), finished(XInternAtom(d, "XdndFinished", False)),
          selection(XInternAtom(d, "XdndSelection", False)),
          action_copy(XInternAtom(d, "XdndActionCopy", False)),
          uri_list(XInternAtom(d, "text/uri-list", False)),
          net_wm_name(XInternAtom(d, "_NET_WM_NAME", False)), utf8(XInternAtom(d, "UTF8_STRING", False)) {}
};

std::string title_of(Display* d, Window w, const Atoms& a) {
    Atom type = None;
    int format = 0;
    unsigned long n = 0, rest = 0;
    unsigned char* data = nullptr;
    std::string title;
    if (XGetWindowProperty(d, w, a.net_wm_name, 0, 1024, False, a.utf8, &type, &format, &n, &rest, &data) ==
            Success &&
        data) {
        title.assign(reinterpret_cast<char*>(data), n);
        XFree(data);
    }
    if (title.empty()) {
        char* name = nullptr;
        if (XFetchName(d, w, &name) && name) {
            title = name;
            XFree(name);
        }
    }
    return title;
}

bool xdnd_aware(Display* d, Window w, const Atoms& a) {
    Atom type = None;
    int format = 0;
    unsigned long n = 0, rest = 0;
    unsigned char* data = nullptr;
    const bool ok = XGetWindowProperty(d, w, a.aware, 0, 1, False, AnyPropertyType, &type, &format, &n, &rest,
                                       &data) == Success &&
                    type != None;
    if (data) XFree(data);
    return ok;
}

Window find_target(Display* d, Window root, const std::string& needle, const Atoms& a) {
    Window r = 0, parent = 0, *children = nullptr;
    unsigned int n = 0;
    if (!XQueryTree(d, root, &r, &parent, &children, &n)) return 0;
    Window found = 0;
    for (unsigned int k = 0; k < n && !found; ++k) {
        XWindowAttributes wa;
        if (!XGetWindowAttributes(d, children[k], &wa) || wa.map_state != IsViewable) continue;
        if (title_of(d, children[k], a).find(needle) != std::string::npos && xdnd_aware(d, children[k], a))
            found = children[k];
        else
            found = find_target(d, children[k], needle, a); // under a window manager's frame
    }
    if (children) XFree(children);
    return found;
}

void send(Display* d, Window target, Atom type, long l0, long l1, long l2, long l3, long l4) {
    XEvent e{};
    e.xclient.type = ClientMessage;
    e.xclient.display = d;
    e.xclient.window = target;
    e.xclient.message_type = type;
    e.xclient.format = 32;
    e.xclient.data.l[0] = l0;
    e.xclient.data.l[1] = l1;
    e.xclient.data.l[2] = l2;
    e.xclient.data.l[3] = l3;
    e.xclient.data.l[4] = l4;
    XSendEvent(d, target, False, NoEventMask, &e);
    XFlush(d);
}

int fail(const std::string& why) {
    std::fprintf(stderr, "xdnd_drop: %s\n", why.c_str());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) return fail("usage: xdnd_drop NAME PATH [TIMEOUT_S]");
    const std::string needle = argv[1], path = argv[2];
    const double timeout = argc > 3 ? std::atof(argv[3]) : 20;
    const auto deadline = Clock::now() + std::chrono::duration<double>(timeout);
    Display* d = XOpenDisplay(nullptr);
    if (!d) return fail("cannot open the X display");
    const Atoms a(d);
    const Window root = DefaultRootWindow(d);

    Window target = 0;
    while (!(target = find_target(d, root, needle, a))) {
        if (Clock::now() > deadline) return fail("no XDND-aware window titled '*" + needle + "*' appeared");
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    // The source: an unmapped window that owns the XDND selection and answers for the data.
    const Window source = XCreateSimpleWindow(d, root, 0, 0, 1, 1, 0, 0, 0);
    XSetSelectionOwner(d, a.selection, source, CurrentTime);
    XWindowAttributes wa;
    XGetWindowAttributes(d, target, &wa);
    int rx = 0, ry = 0;
    Window child = 0;
    XTranslateCoordinates(d, target, root, wa.width / 2, wa.height / 2, &rx, &ry, &child);

    send(d, target, a.enter, static_cast<long>(source), 5L << 24, static_cast<long>(a.uri_list), 0, 0);
    send(d, target, a.position, static_cast<long>(source), 0, (static_cast<long>(rx) << 16) | ry, CurrentTime,
         static_cast<long>(a.action_copy));
    const std::string uri = "file://" + path + "\r\n";
    bool dropped = false;
    while (Clock::now() < deadline) {
        if (!XPending(d)) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            continue;
        }
        XEvent e;
        XNextEvent(d, &e);
        if (e.type == ClientMessage && e.xclient.message_type == a.status && !dropped) {
            if (!(e.xclient.data.l[1] & 1)) return fail("the window does not accept the drop (XdndStatus)");
            send(d, target, a.drop, static_cast<long>(source), 0, CurrentTime, 0, 0);
            dropped = true;
        } else if (e.type == SelectionRequest) {
            const XSelectionRequestEvent& r = e.xselectionrequest;
            XEvent reply{};
            reply.xselection.type = SelectionNotify;
            reply.xselection.display = d;
            reply.xselection.requestor = r.requestor;
            reply.xselection.selection = r.selection;
            reply.xselection.target = r.target;
            reply.xselection.time = r.time;
            reply.xselection.property = None;
            if (r.target == a.uri_list) {
                XChangeProperty(d, r.requestor, r.property, a.uri_list, 8, PropModeReplace,
                                reinterpret_cast<const unsigned char*>(uri.data()),
                                static_cast<int>(uri.size()));
                reply.xselection.property = r.property;
            }
            XSendEvent(d, r.requestor, False, NoEventMask, &reply);
            XFlush(d);
        } else if (e.type == ClientMessage && e.xclient.message_type == a.finished) {
            XDestroyWindow(d, source);
            XCloseDisplay(d);
            return 0;
        }
    }
    return fail(dropped ? "the window took the drop but never reported XdndFinished"
                        : "the window never answered XdndPosition");
}
