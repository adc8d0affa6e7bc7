#!/usr/bin/env python3
"""fgsg lsp given malformed input: no Content-Length, a huge one, a header block that
never ends, bad JSON, JSON nested too deep, fields of the wrong type, a body cut short,
binary noise. Each gets its error response (the JSON-RPC code checked) and the server
goes on to answer the next message, or exits cleanly at the end of input — never a crash
(a signal) or a hang (every run has a timeout). usage: lsp_framing.py FGSG"""
import json
import subprocess
import sys

FGSG = sys.argv[1]
failures = []


def frame(obj_or_bytes):
    body = obj_or_bytes if isinstance(obj_or_bytes, bytes) else json.dumps(obj_or_bytes).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


INIT = frame({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
SHUTDOWN = frame({"jsonrpc": "2.0", "id": 99, "method": "shutdown"})
EXIT = frame({"jsonrpc": "2.0", "method": "exit"})


def responses(data):
    """The framed messages in the server's output."""
    out = []
    while data:
        head, sep, rest = data.partition(b"\r\n\r\n")
        if not sep:
            raise ValueError("unframed output: %r" % data[:80])
        length = int(head.split(b":")[1])
        out.append(json.loads(rest[:length]))
        data = rest[length:]
    return out


def case(name, middle, expected_errors, clean_end=True):
    """Runs initialize, `middle`, then shutdown and exit (when clean_end); checks the error
    responses' (id, code) in order, that shutdown was answered and the exit code."""
    stdin = INIT + middle + (SHUTDOWN + EXIT if clean_end else b"")
    try:
        run = subprocess.run([FGSG, "lsp"], input=stdin, capture_output=True, timeout=30)
    except subprocess.TimeoutExpired:
        failures.append("%s: no exit within 30 s (a hang)" % name)
        return
    if run.returncode < 0:
        failures.append("%s: killed by signal %d: %s" % (name, -run.returncode, run.stderr.decode()[-300:]))
        return
    try:
        got = responses(run.stdout)
    except ValueError as e:
        failures.append("%s: %s" % (name, e))
        return
    errors = [(m.get("id"), m["error"]["code"]) for m in got if "error" in m]
    if errors != expected_errors:
        failures.append("%s: errors %s, expected %s" % (name, errors, expected_errors))
    answered = [m.get("id") for m in got if "result" in m]
    expected_answers = [1, 99] if clean_end else [1]
    if answered != expected_answers:
        failures.append("%s: answered ids %s, expected %s" % (name, answered, expected_answers))
    expected_rc = 0 if clean_end else 1
    if run.returncode != expected_rc:
        failures.append("%s: exit code %d, expected %d" % (name, run.returncode, expected_rc))


# -32600 Invalid Request (framing), -32700 Parse error (JSON), -32603 Internal error.
case("no Content-Length", b"Content-Type: application/json\r\n\r\n{\"jsonrpc\": \"2.0\"}", [(None, -32600)])
case("huge Content-Length", b"Content-Length: 99999999999\r\n\r\n{}", [(None, -32600)])
case("Content-Length not a number", b"Content-Length: -5\r\n\r\n{}", [(None, -32600)])
case("header line without a colon", b"hello there\r\n\r\n", [(None, -32600)])
case("endless header block", b"X-Junk: " + b"a" * 100000 + b"\r\n", [(None, -32600)])
case("bad JSON", frame(b"{\"jsonrpc\": \"2.0\", \"id\": 2, \"method\""), [(None, -32700)])
case("JSON nested too deep", frame(b"[" * 100000 + b"]" * 100000), [(None, -32700)])
case("not a request", frame([1, 2, 3]), [(None, -32600)])
case("unknown method", frame({"jsonrpc": "2.0", "id": 3, "method": "no/such"}), [(3, -32601)])
case("wrong field types", frame({"jsonrpc": "2.0", "id": 4, "method": "textDocument/hover",
                                 "params": {"textDocument": {"uri": 5}, "position": {"line": "x"}}}), [(4, -32603)])
case("change to a closed document",
     frame({"jsonrpc": "2.0", "method": "textDocument/didChange",
            "params": {"textDocument": {"uri": "file:///nowhere.fgsg", "version": 2},
                       "contentChanges": [{"range": {"start": {"line": 9, "character": 9},
                                                     "end": {"line": 0, "character": 0}}, "text": "x"}]}}), [])
case("body cut short by the end of input", b"Content-Length: 100\r\n\r\n{\"jsonrpc\"", [(None, -32600)],
     clean_end=False)
case("binary noise", bytes(range(256)) * 40, [(None, -32600)], clean_end=False)

# The command line: --help, and any argument but --stdio refused.
usage = subprocess.run([FGSG, "lsp", "--help"], capture_output=True, text=True, timeout=30)
if usage.returncode != 0 or "fgsg lsp" not in usage.stdout:
    failures.append("fgsg lsp --help: exit %d, %r" % (usage.returncode, usage.stdout[:200]))
bad = subprocess.run([FGSG, "lsp", "--port", "4"], capture_output=True, text=True, timeout=30, stdin=subprocess.DEVNULL)
if bad.returncode != 2 or "unknown argument '--port'" not in bad.stderr:
    failures.append("fgsg lsp --port 4: exit %d, %r" % (bad.returncode, bad.stderr[:200]))

for f in failures:
    print("FAIL:", f)
print("ok" if not failures else "%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
