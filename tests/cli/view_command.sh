#!/usr/bin/env bash
# fgsg view's usage: --help, and every bad input a clear message with exit 1 or 2 before
# any server starts (the page itself: tests/viewer/view_page.js).
set -u
fgsg="$1"
source="$2"
fail=0
expect() {  # expect CODE TEXT -- ARGS...
  local code="$1" text="$2"
  shift 3
  local out
  out="$("$fgsg" view "$@" 2>&1 </dev/null)"
  local got=$?
  if [ "$got" -ne "$code" ] || ! grep -qF -- "$text" <<<"$out"; then
    echo "FAIL: fgsg view $* -> exit $got (expected $code with '$text'):"
    echo "$out"
    fail=1
  fi
}
expect 0 "usage: fgsg view FILE" -- --help
expect 2 "no grammar file given" --
expect 2 "unknown option '--bogus'" -- "$source/examples/koch.fgsg" --bogus
expect 2 "--port" -- "$source/examples/koch.fgsg" --port 70000
expect 2 "--set expects name=value" -- "$source/examples/koch.fgsg" --set x
expect 1 "missing.fgsg" -- "$source/examples/missing.fgsg"
expect 1 "--host 300.1.1.1: not an IP address" -- "$source/examples/koch.fgsg" --host 300.1.1.1 --port 0
# A port in use says so, and how to choose another.
python3 -c 'import socket,time; s=socket.socket(); s.bind(("127.0.0.1",0)); s.listen(); print(s.getsockname()[1], flush=True); time.sleep(30)' >"${TMPDIR:-/tmp}/fgsg-view-port.$$" &
holder=$!
for _ in $(seq 50); do [ -s "${TMPDIR:-/tmp}/fgsg-view-port.$$" ] && break; sleep 0.1; done
busy=$(cat "${TMPDIR:-/tmp}/fgsg-view-port.$$")
expect 1 "Address already in use (another fgsg view?): choose another --port, or --port 0 for a free one" -- "$source/examples/koch.fgsg" --port "$busy"
kill $holder 2>/dev/null
rm -f "${TMPDIR:-/tmp}/fgsg-view-port.$$"
# A server reachable from the network without its token is refused before it starts.
expect 2 "needs its token" -- "$source/examples/koch.fgsg" --host 0.0.0.0 --no-token --port 0
expect 2 "needs its token" -- "$source/examples/koch.fgsg" --host 192.168.1.5 --no-token --port 0
expect 2 "needs its token" -- "$source/examples/koch.fgsg" --host :: --no-token --port 0
exit $fail
