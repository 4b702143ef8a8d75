"""Drops a file on the X window named NAME as a file manager does, by the XDND protocol
(https://www.freedesktop.org/wiki/Specifications/XDND/, version 5): XdndEnter with text/uri-list,
XdndPosition, XdndDrop once the target's XdndStatus came, the file's URI when the target asks for
the XdndSelection, until its XdndFinished. For the viewer's end-to-end test (test_viewer.py), so a
real drop reaches GLFW's drop callback; ctypes and libX11 only.
Usage: xdnd_drop.py NAME FILE. Exits 0 once the target sent XdndFinished, 1 when it did not within
30 seconds, 77 when libX11 cannot be loaded."""
import ctypes, ctypes.util, sys, time, urllib.parse, os

library = ctypes.util.find_library("X11")
if not library:
    print("libX11 not found")
    sys.exit(77)
x = ctypes.CDLL(library)
x.XOpenDisplay.restype = ctypes.c_void_p
x.XOpenDisplay.argtypes = [ctypes.c_char_p]
x.XDefaultRootWindow.restype = ctypes.c_ulong
x.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
x.XInternAtom.restype = ctypes.c_ulong
x.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
x.XCreateSimpleWindow.restype = ctypes.c_ulong
x.XCreateSimpleWindow.argtypes = [ctypes.c_void_p, ctypes.c_ulong] + [ctypes.c_int] * 2 + \
    [ctypes.c_uint] * 3 + [ctypes.c_ulong] * 2
x.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                         ctypes.POINTER(ctypes.c_ulong), ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)),
                         ctypes.POINTER(ctypes.c_uint)]
x.XFetchName.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_char_p)]
x.XSetSelectionOwner.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong]
x.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long, ctypes.c_void_p]
x.XChangeProperty.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_ulong, ctypes.c_ulong,
                              ctypes.c_int, ctypes.c_int, ctypes.c_char_p, ctypes.c_int]
x.XPending.argtypes = [ctypes.c_void_p]
x.XNextEvent.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
x.XFlush.argtypes = [ctypes.c_void_p]


# The XEvent members used, as Xlib lays them out (every event is sent in a 192-byte XEvent).
class ClientMessage(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                ("display", ctypes.c_void_p), ("window", ctypes.c_ulong),
                ("message_type", ctypes.c_ulong), ("format", ctypes.c_int),
                ("l", ctypes.c_long * 5)]


class SelectionRequest(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                ("display", ctypes.c_void_p), ("owner", ctypes.c_ulong),
                ("requestor", ctypes.c_ulong), ("selection", ctypes.c_ulong),
                ("target", ctypes.c_ulong), ("property", ctypes.c_ulong), ("time", ctypes.c_ulong)]


class SelectionNotify(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                ("display", ctypes.c_void_p), ("requestor", ctypes.c_ulong),
                ("selection", ctypes.c_ulong), ("target", ctypes.c_ulong),
                ("property", ctypes.c_ulong), ("time", ctypes.c_ulong)]


CLIENT_MESSAGE, SELECTION_REQUEST, SELECTION_NOTIFY = 33, 30, 31


def find(dpy, window, name):
    """The window titled `name` under `window`, depth first, or None."""
    title = ctypes.c_char_p()
    if x.XFetchName(dpy, window, ctypes.byref(title)) and title.value == name:
        return window
    root, parent, children, count = ctypes.c_ulong(), ctypes.c_ulong(), \
        ctypes.POINTER(ctypes.c_ulong)(), ctypes.c_uint()
    if not x.XQueryTree(dpy, window, ctypes.byref(root), ctypes.byref(parent),
                        ctypes.byref(children), ctypes.byref(count)):
        return None
    for i in range(count.value):
        found = find(dpy, children[i], name)
        if found:
            return found
    return None


def main():
    name, path = sys.argv[1].encode(), os.path.abspath(sys.argv[2])
    dpy = x.XOpenDisplay(None)
    assert dpy, "no display"
    atom = lambda n: x.XInternAtom(dpy, n.encode(), 0)
    root = x.XDefaultRootWindow(dpy)
    target = None
    for _ in range(300):  # the viewer's window may not be open yet
        target = find(dpy, root, name)
        if target:
            break
        time.sleep(0.1)
    assert target, "no window named " + name.decode()
    source = x.XCreateSimpleWindow(dpy, root, 0, 0, 1, 1, 0, 0, 0)
    selection = atom("XdndSelection")
    uri_list = atom("text/uri-list")
    x.XSetSelectionOwner(dpy, selection, source, 0)

    def send(kind, l):
        e = ClientMessage(CLIENT_MESSAGE, 0, 1, dpy, target, atom(kind), 32)
        for i, v in enumerate(l):
            e.l[i] = v
        buf = (ctypes.c_char * 192)()
        ctypes.memmove(buf, ctypes.byref(e), ctypes.sizeof(e))
        x.XSendEvent(dpy, target, 0, 0, buf)
        x.XFlush(dpy)

    send("XdndEnter", [source, 5 << 24, uri_list, 0, 0])
    send("XdndPosition", [source, 0, (300 << 16) | 190, 0, atom("XdndActionCopy")])
    data = ("file://" + urllib.parse.quote(path) + "\r\n").encode()
    event = (ctypes.c_char * 192)()
    dropped = False
    deadline = time.time() + 30
    while time.time() < deadline:
        while x.XPending(dpy):
            x.XNextEvent(dpy, event)
            kind = ctypes.c_int.from_buffer(event).value
            if kind == CLIENT_MESSAGE:
                m = ClientMessage.from_buffer(event)
                if m.message_type == atom("XdndStatus") and not dropped:
                    print("status: accepted" if m.l[1] & 1 else "status: refused")
                    send("XdndDrop", [source, 0, 0, 0, 0])
                    dropped = True
                elif m.message_type == atom("XdndFinished"):
                    print("finished")
                    return 0
            elif kind == SELECTION_REQUEST:
                r = SelectionRequest.from_buffer(event)
                x.XChangeProperty(dpy, r.requestor, r.property, r.target, 8, 0, data, len(data))
                n = SelectionNotify(SELECTION_NOTIFY, 0, 1, dpy, r.requestor, r.selection,
                                    r.target, r.property, r.time)
                buf = (ctypes.c_char * 192)()
                ctypes.memmove(buf, ctypes.byref(n), ctypes.sizeof(n))
                x.XSendEvent(dpy, r.requestor, 0, 0, buf)
                x.XFlush(dpy)
                print("sent", data)
        time.sleep(0.02)
    print("no XdndFinished")
    return 1


sys.exit(main())
