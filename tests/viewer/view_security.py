#!/usr/bin/env python3
"""fgsg view as an attacker on the same machine, or a web page in the user's browser,
would try it (issue 41): every path out of the page's files, foreign Host and Origin,
missing and wrong tokens, garbage, deep and oversized messages, then load: 50 pages at
once and 2 000 HTTP requests. The server must refuse each, keep answering and stay
bounded in memory. Only 127.0.0.1 is contacted; every loop is bounded in count and time.

usage: view_security.py FGSG SOURCE_DIR
"""
import base64
import json
import os
import re
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

fgsg, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def http(port, request, timeout=10):
    """Sends raw bytes (paths exactly as written), returns (status, headers, body)."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        s.sendall(request)
        data = b""
        while True:
            chunk = s.recv(65536)
            if not chunk:
                break
            data += chunk
            head, _, body = data.partition(b"\r\n\r\n")
            m = re.search(rb"content-length: *(\d+)", head, re.I)
            if m and len(body) >= int(m.group(1)):
                break
    head, _, body = data.partition(b"\r\n\r\n")
    status = int(head.split(b" ")[1]) if head.startswith(b"HTTP/") else 0
    return status, head.decode("latin-1"), body


def get(port, path, host=None, cookie=None, extra=b""):
    req = b"GET " + path + b" HTTP/1.1\r\nHost: " + (host or b"127.0.0.1:%d" % port) + b"\r\n"
    if cookie:
        req += b"Cookie: " + cookie + b"\r\n"
    return http(port, req + extra + b"Connection: close\r\n\r\n")


class WebSocket:
    """The smallest client that speaks RFC 6455: masked frames, text and binary."""

    def __init__(self, port, resource, host=None, origin=None, timeout=30):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=timeout)
        key = base64.b64encode(os.urandom(16))
        req = (b"GET " + resource + b" HTTP/1.1\r\nHost: " + (host or b"127.0.0.1:%d" % port) +
               b"\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: " + key +
               b"\r\nSec-WebSocket-Version: 13\r\n")
        if origin is not None:
            req += b"Origin: " + origin + b"\r\n"
        self.sock.sendall(req + b"\r\n")
        self.buffer = b""
        while b"\r\n\r\n" not in self.buffer:
            chunk = self.sock.recv(4096)
            if not chunk:
                break
            self.buffer += chunk
        head, _, self.buffer = self.buffer.partition(b"\r\n\r\n")
        self.status = int(head.split(b" ")[1]) if head.startswith(b"HTTP/") else 0

    def send(self, payload, opcode=1):
        if isinstance(payload, str):
            payload = payload.encode()
        n = len(payload)
        header = bytes([0x80 | opcode])
        if n < 126:
            header += bytes([0x80 | n])
        elif n < 65536:
            header += bytes([0x80 | 126]) + struct.pack(">H", n)
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", n)
        mask = os.urandom(4)
        body = bytes(b ^ mask[i % 4] for i, b in enumerate(payload)) if n < 1 << 16 else \
            (int.from_bytes(payload, "big") ^ int.from_bytes((mask * (n // 4 + 1))[:n], "big")).to_bytes(n, "big")
        self.sock.sendall(header + mask + body)

    def _read(self, n):
        while len(self.buffer) < n:
            chunk = self.sock.recv(65536)
            if not chunk:
                raise ConnectionError("closed")
            self.buffer += chunk
        out, self.buffer = self.buffer[:n], self.buffer[n:]
        return out

    def receive(self):
        """(opcode, payload) of the next frame; opcode 8 is a close."""
        b0, b1 = self._read(2)
        n = b1 & 0x7F
        if n == 126:
            n = struct.unpack(">H", self._read(2))[0]
        elif n == 127:
            n = struct.unpack(">Q", self._read(8))[0]
        return b0 & 0x0F, self._read(n)

    def next_text(self, want_type, limit_s=60):
        """The next text message of the given type, skipping others."""
        end = time.time() + limit_s
        while time.time() < end:
            op, payload = self.receive()
            if op == 8:
                return None
            if op == 1:
                m = json.loads(payload)
                if m.get("type") == want_type:
                    return m
                if m.get("type") in ("error", "rejected"):
                    print("     (skipped: %s)" % payload[:200].decode(errors="replace"), flush=True)
        return None

    def close(self):
        try:
            self.sock.close()
        except OSError:
            pass


def rss_kib(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


work = tempfile.mkdtemp(prefix="fgsg-view-security-")
grammar = os.path.join(work, "g.fgsg")
shutil.copy(os.path.join(source, "examples/mueller_building.fgsg"), grammar)
os.symlink(os.path.join(source, "examples/assets"), os.path.join(work, "assets"))
env = dict(os.environ, FGSG_CACHE_DIR=os.path.join(work, "cache"))
server = subprocess.Popen([fgsg, "view", grammar, "--port", "0"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          env=env, text=True)
try:
    line = server.stdout.readline()
    m = re.search(r"http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{48})", line)
    check(m is not None, "the printed address carries a 48-digit token: " + line.strip())
    if not m:
        raise SystemExit(1)
    port, token = int(m.group(1)), m.group(2).encode()
    cookie = b"fgsg-view-token-%d=" % port + token

    # 1. The page with its token; the token becomes an HttpOnly cookie.
    status, head, body = get(port, b"/?token=" + token)
    check(status == 200 and b"<html" in body, "GET /?token=... answers the page (%d)" % status)
    check("HttpOnly" in head and "SameSite=Strict" in head, "the page sets its token as an HttpOnly, SameSite cookie")
    status, _, body = get(port, b"/viewer.js", cookie=cookie)
    check(status == 200 and b"WebSocket" in body, "the page's script with the cookie (%d)" % status)
    status, _, _ = get(port, b"/three/build/three.module.js", cookie=cookie)
    check(status == 200, "three.js's module with the cookie (%d)" % status)

    # 2. Paths out of the page's files: all 404 (or 400 where HTTP itself refuses them).
    rel = os.path.relpath(grammar, "/").encode()
    for path in [b"//etc/passwd", b"//proc/self/environ", b"//proc/self/maps", b"/" + b"/" + rel, b"/etc/passwd",
                 b"/../CMakeLists.txt", b"/../../../../etc/passwd", b"/%2e%2e/%2e%2e/etc/passwd",
                 b"/..%2f..%2fetc%2fpasswd", b"/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd", b"/.%2e/.%2e/etc/passwd",
                 b"/three/../../../../etc/passwd", b"/three/build/../../index.html", b"/./index.html",
                 b"/index.html%00", b"/index.html%00.js", b"/\\..\\..\\etc\\passwd", b"/%5c..%5c..%5cetc%5cpasswd",
                 b"/..;/etc/passwd", b"/" + b"a" * 10000, b"/three", b"/three/", b"/CMakeLists.txt", b"/g.fgsg",
                 b"/assets/flatbrick.obj", b"file:///etc/passwd", b"http://127.0.0.1/etc/passwd"]:
        status, _, body = get(port, path, cookie=cookie)
        check(status in (400, 404) and b"root:" not in body and b"PATH=" not in body,
              "GET %s -> %d" % (path[:60].decode("latin-1"), status))
    status, _, _ = http(port, b"GET /index.html\x00 HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nCookie: " % port + cookie +
                        b"\r\nConnection: close\r\n\r\n")
    check(status in (0, 400, 404), "a NUL byte in the path -> %d" % status)
    status, _, _ = http(port, b"POST / HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nCookie: " % port + cookie +
                        b"\r\nContent-Length: 0\r\nConnection: close\r\n\r\n")
    check(status == 405, "POST -> %d" % status)

    # 3. Host (DNS rebinding) and token, over HTTP.
    for host in [b"evil.example.com:%d" % port, b"evil.example.com", b"127.0.0.1:1", b"127.0.0.1.evil.example:%d" % port]:
        status, _, body = get(port, b"/?token=" + token, host=host)
        check(status == 403 and b"<html" not in body, "Host %s -> %d" % (host.decode(), status))
    status, _, _ = get(port, b"/")
    check(status == 403, "the page without a token -> %d" % status)
    status, _, _ = get(port, b"/?token=" + b"0" * 48)
    check(status == 403, "a wrong token -> %d" % status)
    status, _, _ = get(port, b"/viewer.js", cookie=b"fgsg-view-token-%d=" % port + b"1" * 48)
    check(status == 403, "a wrong cookie -> %d" % status)
    status, _, _ = get(port, b"/", extra=b"Authorization: token " + token + b"\r\n")
    check(status == 200, "Authorization: token ... -> %d" % status)

    # 4. WebSocket handshakes: foreign Origin or Host, missing or wrong token.
    own = b"http://127.0.0.1:%d" % port
    for what, resource, host, origin, want in [
        ("a foreign Origin", b"/?token=" + token, None, b"http://evil.example.com", 403),
        ("Origin null", b"/?token=" + token, None, b"null", 403),
        ("a foreign Host", b"/?token=" + token, b"evil.example.com:%d" % port, b"http://evil.example.com:%d" % port, 403),
        ("no token", b"/", None, own, 403),
        ("a wrong token", b"/?token=" + b"f" * 48, None, own, 403),
        ("the page's own Origin and token", b"/?token=" + token, None, own, 101),
    ]:
        ws = WebSocket(port, resource, host, origin)
        check(ws.status == want, "WebSocket with %s -> %d" % (what, ws.status))
        ws.close()

    # 5. Messages: each bad one gets a reason and changes nothing; the server lives on.
    ws = WebSocket(port, b"/?token=" + token, origin=own)
    info = ws.next_text("info")
    check(info is not None and info["seed"] == 1, "a page gets the grammar's info")
    model = ws.next_text("model")
    check(model is not None, "a page gets its model")
    triangles = model["figures"]["triangles"] if model else None
    bad = [
        '{"type":"set","attrs":{"lot_width":' + "[" * 100000 + "]" * 100000 + "}}",  # V3: over the size cap
        '{"type":"set","attrs":{"lot_width":' + "[" * 30000 + "]" * 30000 + "}}",  # under it: the nesting cap
        "x" * 200000,
        "\x00\x01 not json",
        '{"type":"set","attrs":{"lot_width":"wide"}}',
        '{"type":"set","attrs":{"no_such_attr":"1"}}',
        '{"type":"set","attrs":{"lot_width":1e999}}',
        '{"type":"set","seed":-4}',
        '{"type":"read","file":"/etc/passwd"}',
        '{"type":"set","file":"/etc/passwd"}',
        '{"type":"pick","instance":99999999}',
    ]
    for text in bad:
        ws.send(text)
        reply = ws.next_text("rejected", 30)
        check(reply is not None and reply.get("reason"), "rejected with a reason: %s... (%s)" %
              (text[:40].replace("\x00", "\\0"), reply and reply.get("reason", "")[:70]))
    ws.send(b"\xff\xfe invalid utf-8", opcode=1)  # the protocol layer closes on invalid UTF-8
    ws.close()
    # A frame over the bound is refused by the protocol (close 1009), not read whole.
    # The server may close while the frame is still being sent: a broken pipe or a reset
    # on send is that same refusal, as it is on receive.
    ws = WebSocket(port, b"/?token=" + token, origin=own)
    op = None
    try:
        ws.send("y" * (1 << 20))
        while op != 8:
            op, _ = ws.receive()
    except (ConnectionError, OSError):
        op = 8
    check(op == 8, "a 1 MiB message closes that connection")
    ws.close()
    # The model did not change, and a good message still derives.
    ws = WebSocket(port, b"/?token=" + token, origin=own)
    again = ws.next_text("model")
    check(again is not None and again["figures"]["triangles"] == triangles, "the bad messages changed nothing")
    ws.send('{"type":"set","attrs":{"lot_width":"28"},"seed":1}')
    wider = ws.next_text("model")
    check(wider is not None and wider["figures"]["triangles"] > triangles, "a good message still derives")
    ws.close()
    check(server.poll() is None, "the server is alive after the attacks")

    # 6. Load: 50 pages at once, each with its model; then 2 000 HTTP requests.
    time.sleep(1)
    before = rss_kib(server.pid)
    pages = [WebSocket(port, b"/?token=" + token, origin=own, timeout=120) for _ in range(50)]
    got = [None] * len(pages)

    def take(i):
        try:
            got[i] = pages[i].next_text("model", 120)
        except (OSError, ConnectionError, ValueError):
            got[i] = None

    threads = [threading.Thread(target=take, args=(i,)) for i in range(len(pages))]
    t0 = time.time()
    for t in threads:
        t.start()
    for t in threads:
        t.join(150)
    check(all(g is not None for g in got), "50 pages at once each got a model (%.1f s)" % (time.time() - t0))
    peak = rss_kib(server.pid)
    for p in pages:
        p.close()
    answered = [0]

    def hammer(count):
        for _ in range(count):
            try:
                status, _, _ = get(port, b"/viewer.js", cookie=cookie)
                answered[0] += status == 200
            except OSError:
                pass

    t0 = time.time()
    threads = [threading.Thread(target=hammer, args=(250,)) for _ in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(300)
    check(answered[0] == 2000, "2 000 HTTP requests answered: %d in %.1f s" % (answered[0], time.time() - t0))
    time.sleep(1)
    after = rss_kib(server.pid)
    print("memory: %d MiB before, %d MiB with 50 pages, %d MiB after" % (before >> 10, peak >> 10, after >> 10))
    check(after < before + 300 * 1024, "memory stays bounded (%d -> %d MiB)" % (before >> 10, after >> 10))
    status, _, _ = get(port, b"/?token=" + token)
    check(status == 200 and server.poll() is None, "the server still answers")
finally:
    server.terminate()
    try:
        server.wait(20)
    except subprocess.TimeoutExpired:
        server.kill()
    shutil.rmtree(work, ignore_errors=True)



def edit_attacks():
    """7. The editing messages (#49): seeds and paint write files, so each is tried as an
    attacker would: paths for texture names, textures that resolve outside the grammar's
    folder (a '..' in the grammar, a symlink), oversized and malformed lists, unknown fields,
    a foreign Origin. Each must be refused and leave every file as it was."""
    work = tempfile.mkdtemp(prefix="fgsg-view-edit-security-")
    folder, outside = os.path.join(work, "grammar"), os.path.join(work, "outside")
    os.makedirs(folder)
    os.makedirs(outside)
    white = os.path.join(source, "examples/assets/ivy_anywhere.png")
    for name in ("mask.png", "real.png"):
        shutil.copy(white, os.path.join(folder, name))
    for name in ("secret.png", "above.png"):
        shutil.copy(white, os.path.join(outside, name))
    os.symlink(os.path.join(outside, "secret.png"), os.path.join(folder, "linked.png"))
    with open(os.path.join(source, "examples/ivy.fgsg")) as f:
        text = f.read().replace('texture mask = "ivy_anywhere.png";', 'texture mask = "mask.png";\n'
                                'texture linked = "linked.png";\ntexture above = "../outside/above.png";')
    grammar = os.path.join(folder, "g.fgsg")
    with open(grammar, "w") as f:
        f.write(text)
    seeds = os.path.join(folder, "g.seeds")

    def contents():
        out = {}
        for d in (folder, outside):
            for name in sorted(os.listdir(d)):
                p = os.path.join(d, name)
                if os.path.isfile(p) and not name.endswith(".fgsg"):
                    with open(p, "rb") as f:
                        out[p] = f.read()
        return out

    env = dict(os.environ, FGSG_CACHE_DIR=os.path.join(work, "cache"))
    server = subprocess.Popen([fgsg, "view", grammar, "--port", "0"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              env=env, text=True)
    try:
        m = re.search(r"http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{48})", server.stdout.readline())
        check(m is not None, "the editing server prints its address")
        if not m:
            return
        port, token = int(m.group(1)), m.group(2).encode()
        own = b"http://127.0.0.1:%d" % port
        # A foreign page cannot open the socket that carries seeds and paint at all.
        ws = WebSocket(port, b"/?token=" + token, origin=b"http://evil.example.com")
        check(ws.status == 403, "seeds and paint from a foreign Origin: handshake -> %d" % ws.status)
        ws.close()
        ws = WebSocket(port, b"/?token=" + token, origin=own)
        surface = ws.next_text("surface", 120)
        check(surface is not None, "the page gets the surface")
        why = {t["name"]: t["why"] for t in surface["textures"]} if surface else {}
        check(why.get("mask") == "", "mask.png inside the folder may be painted")
        check("symbolic link" in why.get("linked", ""), "a texture that is a symlink may not: " + why.get("linked", ""))
        check("outside the grammar's folder" in why.get("above", ""), "a texture above the folder may not: " +
              why.get("above", ""))
        check(ws.next_text("model", 120) is not None, "the page gets its model")
        before = contents()
        dab = '"stroke":1,"dabs":[[0,0,1]],"radius":0.5'
        many_seeds = ",".join(["[0,0,1]"] * 1025)
        many_dabs = ",".join(["[0,0,1]"] * 257)
        bad = [
            '{"type":"paint","texture":"linked",%s}' % dab,
            '{"type":"paint","texture":"above",%s}' % dab,
            '{"type":"paint","texture":"../outside/secret",%s}' % dab,
            '{"type":"paint","texture":"/etc/passwd",%s}' % dab,
            '{"type":"paint","texture":"mask.png",%s}' % dab,
            '{"type":"paint","texture":"real",%s}' % dab,  # a file in the folder the grammar does not declare
            '{"type":"paint","texture":"mask","file":"../outside/secret.png",%s}' % dab,
            '{"type":"paint","texture":"mask","stroke":1,"dabs":[%s],"radius":0.5}' % many_dabs,
            '{"type":"paint","texture":"mask","stroke":1,"dabs":[[0,0,1]],"radius":1e300}',
            '{"type":"paint","texture":"mask","stroke":1,"dabs":[[0,0,1]],"radius":"0.5"}',
            '{"type":"paint","texture":"mask",%s,"strength":7}' % dab,
            '{"type":"paint","texture":"mask","stroke":1,"dabs":[[0,0,"1"]],"radius":0.5}',
            '{"type":"paint","texture":"mask","stroke":1,"dabs":[[[[0]]]],"radius":0.5}',
            '{"type":"seeds","seeds":[%s]}' % many_seeds,
            '{"type":"seeds","seeds":[[0,0,1]],"file":"/tmp/x.seeds"}',
            '{"type":"seeds","seeds":[[0,0,1e300]]}',
            '{"type":"seeds","seeds":[[0,0,1,0,0,0]]}',
            '{"type":"seeds","seeds":"0,0,1"}',
            '{"type":"undo"}',
            '{"type":"redo","count":100}',
            '{"type":"field","file":"/etc/passwd"}',  # the overlay names no file: an unknown field
            '{"type":"resend","pieces":[0,1]}',  # the whole model again: it takes no field
            '{"type":"resend","file":"/etc/passwd"}',
        ]
        for text in bad:
            ws.send(text)
            reply = ws.next_text("rejected", 30)
            check(reply is not None and reply.get("reason"), "edit rejected: %s... (%s)" %
                  (text[:60], reply and reply.get("reason", "")[:90]))
        check(contents() == before and not os.path.exists(seeds), "the refused edits wrote no file")
        # The same messages done right are taken: the mask keeps its size, the seed file
        # is written where it belongs.
        ws.send('{"type":"paint","texture":"mask",%s,"value":0}' % dab)
        written = ws.next_text("written", 30)
        check(written is not None and written["file"] == "mask.png", "a good stroke writes mask.png")
        with open(os.path.join(folder, "mask.png"), "rb") as f:
            png = f.read()
        check(png[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", png[16:24]) == (16, 16),
              "the painted mask is a PNG of the texture's own 16 x 16 texels")
        ws.send('{"type":"seeds","seeds":[[0,0,1]]}')
        written = ws.next_text("written", 30)
        check(written is not None and written["file"] == "g.seeds" and os.path.isfile(seeds), "good seeds write g.seeds")
        after = contents()
        check(all(after[p] == before[p] for p in before if not p.endswith("mask.png")),
              "no file but mask.png and g.seeds changed (the symlink's target and the folder above included)")
        ws.close()
        check(server.poll() is None, "the editing server is alive after the attacks")
    finally:
        server.terminate()
        try:
            server.wait(20)
        except subprocess.TimeoutExpired:
            server.kill()
        shutil.rmtree(work, ignore_errors=True)


def field_element_attacks():
    """8. Design elements edited from the page (#49, item 3) rewrite the grammar itself, so
    every malformed, out-of-range or out-of-place fieldElement message must be refused with
    a reason and leave the grammar (and every other file) byte for byte as it was; a good one
    changes only its element's words; a grammar that is a symbolic link is never written.
    Undo and redo of element edits ({"type":"undo","history":"field"}) take no other field,
    give back the exact text, and never overwrite a grammar saved outside since."""
    work = tempfile.mkdtemp(prefix="fgsg-view-field-security-")
    folder, outside = os.path.join(work, "grammar"), os.path.join(work, "outside")
    os.makedirs(folder)
    os.makedirs(outside)
    text = ("surface plane(10, 10, 24);\n"
            "field F = design tensor {\n  wedge at (-2, 0, 0) decay 1;\n  trisector at (2, 0, 0) decay 1;\n};\n"
            "Axiom ~> I(\"cube\");\n")
    grammar = os.path.join(folder, "g.fgsg")
    with open(grammar, "w") as f:
        f.write(text)
    with open(os.path.join(outside, "real.fgsg"), "w") as f:
        f.write(text)
    os.symlink(os.path.join(outside, "real.fgsg"), os.path.join(folder, "linked.fgsg"))

    def contents():
        out = {}
        for d in (folder, outside):
            for name in sorted(os.listdir(d)):
                with open(os.path.join(d, name), "rb") as f:
                    out[os.path.join(d, name)] = f.read()
        return out

    env = dict(os.environ, FGSG_CACHE_DIR=os.path.join(work, "cache"))

    def serve(path):
        server = subprocess.Popen([fgsg, "view", path, "--port", "0"], stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, env=env, text=True)
        m = re.search(r"http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{48})", server.stdout.readline())
        check(m is not None, "the design server prints its address")
        port, token = int(m.group(1)), m.group(2).encode()
        return server, WebSocket(port, b"/?token=" + token, origin=b"http://127.0.0.1:%d" % port)

    def stop(server):
        server.terminate()
        try:
            server.wait(20)
        except subprocess.TimeoutExpired:
            server.kill()

    good_move = '{"type":"fieldElement","op":"move","index":0,"position":[-1,1,0]}'
    server = None
    try:
        server, ws = serve(grammar)
        check(ws.next_text("model", 120) is not None, "the page gets its model")
        before = contents()
        ws.send(good_move)
        reply = ws.next_text("rejected", 30)
        check(reply is not None and "no field overlay" in reply.get("reason", ""),
              "an edit before the overlay is refused: %s" % (reply and reply.get("reason")))
        ws.send('{"type":"field"}')
        overlay = ws.next_text("field", 120)
        check(overlay is not None and len(overlay.get("elements", [])) == 2, "the overlay lists the two elements")
        bad = [
            '{"type":"fieldElement"}',
            '{"type":"fieldElement","op":"rename","index":0}',
            '{"type":"fieldElement","op":["move"],"index":0,"position":[0,0,0]}',
            '{"type":"fieldElement","op":"add","kind":"vortex","position":[0,0,0]}',
            '{"type":"fieldElement","op":"add","kind":"wedge;\\nAxiom ~> I(\\"x\\")","position":[0,0,0]}',
            '{"type":"fieldElement","op":"add","kind":"Wedge","position":[0,0,0]}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0]}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,"0"]}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,1e300]}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[500,0,0]}',  # far off the 10 x 10 plane
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,0],"index":0}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,0],"direction":[1,0,0]}',
            '{"type":"fieldElement","op":"add","kind":"regular","position":[0,0,0],"direction":[0,0,0]}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,0],"strength":1e6}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,0],"strength":"2"}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,0],"file":"/etc/passwd"}',
            '{"type":"fieldElement","op":"move","index":2,"position":[0,0,0]}',  # two elements
            '{"type":"fieldElement","op":"move","index":-1,"position":[0,0,0]}',
            '{"type":"fieldElement","op":"move","index":0.5,"position":[0,0,0]}',
            '{"type":"fieldElement","op":"move","index":99999999999,"position":[0,0,0]}',
            '{"type":"fieldElement","op":"move","index":0}',
            '{"type":"fieldElement","op":"move","index":0,"position":[[[0]]]}',
            '{"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"text":"field G = tensor(\\"/etc/passwd\\");"}',
            '{"type":"fieldElement","op":"strength","index":0}',
            '{"type":"fieldElement","op":"strength","index":0,"strength":-1001}',
            '{"type":"fieldElement","op":"delete","index":5}',
            '{"type":"fieldElement","op":"delete","index":0,"position":[0,0,0]}',
            '{"type":"fieldElement","op":"add","kind":"%s","position":[0,0,0]}' % ("w" * 70000),
            '{"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"drag":0}',
            '{"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"drag":-1}',
            '{"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"drag":"1"}',
            '{"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"drag":1.5}',
            '{"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"drag":9007199254740992}',
            '{"type":"fieldElement","op":"move","index":0,"position":[0,0,0],"drag":[1]}',
            '{"type":"fieldElement","op":"add","kind":"wedge","position":[0,0,0],"drag":1}',
            '{"type":"undo","history":"field"}',  # nothing to undo yet
            '{"type":"redo","history":"field"}',
            '{"type":"undo","history":"grammar"}',
            '{"type":"undo","history":"../g.fgsg"}',
            '{"type":"undo","history":["field"]}',
            '{"type":"undo","history":{"field":1}}',
            '{"type":"undo","history":"field","file":"/etc/passwd"}',
            '{"type":"redo","history":"field","text":"Axiom ~> I(\\"x\\");"}',
            '{"type":"undo","history":"field","count":100}',
        ]
        for message in bad:
            ws.send(message)
            reply = ws.next_text("rejected", 30)
            check(reply is not None and reply.get("reason"), "element edit rejected: %s... (%s)" %
                  (message[:70], reply and reply.get("reason", "")[:90]))
        check(contents() == before, "the refused element edits changed no file (the grammar byte for byte)")
        ws.send(good_move)
        written = ws.next_text("written", 30)
        check(written is not None and written["file"] == "g.fgsg", "a good move writes g.fgsg")
        with open(grammar) as f:
            check(f.read() == text.replace("wedge at (-2, 0, 0)", "wedge at (-1, 1, 0)"),
                  "only the wedge's `at` words changed")
        after = contents()
        check(all(after[p] == before[p] for p in before if p != grammar), "no other file changed")
        moved = text.replace("wedge at (-2, 0, 0)", "wedge at (-1, 1, 0)")
        ws.send('{"type":"undo","history":"field"}')
        written = ws.next_text("written", 30)
        check(written is not None and written["file"] == "g.fgsg" and contents()[grammar] == text.encode(),
              "undo writes the grammar back byte for byte")
        ws.send('{"type":"redo","history":"field"}')
        written = ws.next_text("written", 30)
        check(written is not None and contents()[grammar] == moved.encode(), "redo writes the move again")
        # Saved from an editor meanwhile: an undo must not overwrite it.
        saved = moved + "// saved outside the viewer\n"
        with open(grammar, "w") as f:
            f.write(saved)
        ws.send('{"type":"undo","history":"field"}')
        reply = ws.next_text("rejected", 30)
        check(reply is not None and "changed outside the viewer" in reply.get("reason", ""),
              "undo after an outside save is refused: %s" % (reply and reply.get("reason")))
        ws.send('{"type":"redo","history":"field"}')
        reply = ws.next_text("rejected", 30)
        check(reply is not None and "no field edit to redo" in reply.get("reason", ""),
              "and the history is gone: %s" % (reply and reply.get("reason")))
        check(contents()[grammar] == saved.encode(), "the grammar saved outside stays byte for byte")
        ws.close()
        check(server.poll() is None, "the design server is alive after the attacks")
        stop(server)

        # A grammar reached through a symbolic link: shown, never written.
        server, ws = serve(os.path.join(folder, "linked.fgsg"))
        check(ws.next_text("model", 120) is not None, "the linked grammar's page gets its model")
        ws.send('{"type":"field"}')
        check(ws.next_text("field", 120) is not None, "and its overlay")
        ws.send(good_move)
        reply = ws.next_text("rejected", 30)
        check(reply is not None and "symbolic link" in reply.get("reason", ""),
              "an edit of a linked grammar is refused: %s" % (reply and reply.get("reason")))
        with open(os.path.join(outside, "real.fgsg")) as f:
            check(f.read() == text and os.path.islink(os.path.join(folder, "linked.fgsg")),
                  "the link and its target are as they were")
        ws.close()
    finally:
        if server:
            stop(server)
        shutil.rmtree(work, ignore_errors=True)


edit_attacks()
field_element_attacks()

if failures:
    print("FAIL: %d checks failed" % len(failures))
    sys.exit(1)
print("PASS")
