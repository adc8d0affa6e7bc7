#!/usr/bin/env python3
"""Rewrites the serialized ATN in an ANTLR 4.7.2 C++ lexer or parser so that the
intervals of every character set are listed from the highest down.

Why: the C++ runtime (4.9) deserialises each set by adding its intervals one by one,
and IntervalSet::add scans the set from its start before appending, so the tool's
ascending order costs O(n^2): with the Unicode classes of fgsg's identifiers
([\\p{L}_] [\\p{L}\\p{N}_]*, hundreds of intervals) that is 6-7 ms of every command that
parses, a quarter of a cached `fgsg run` (issue #18). Added from the highest down, each
interval goes in front after one comparison. The sets are the same; nothing else in the
array moves. Run by scripts/regen-grammar.sh.

usage: atn_descending_sets.py FILE.cpp
"""
import re
import sys

# ATN state types with an extra field (ATNState.h): LOOP_END has its loop-back state,
# the block starts their end state.
BLOCK_STARTS = {3, 4, 5}
LOOP_END = 12
INVALID_TYPE = 0
LEXER = 0
SUPPORTED_VERSION = 3
# Serialized by tool 4.7.2: every feature up to ADDED_UNICODE_SMP, so the lexer's rules
# carry no action index and the sets come in two sections (16-bit, then 32-bit bounds).
UUID_ADDED_UNICODE_SMP = "59627784-3BE5-417A-B9EB-8131A7286089"


def uuid_text(words):
    # Eight 16-bit words, least significant first (ATNDeserializer::toUUID).
    value = 0
    for i, w in enumerate(words):
        value |= w << (16 * i)
    h = "%032X" % value
    return "%s-%s-%s-%s-%s" % (h[0:8], h[8:12], h[12:16], h[16:20], h[20:32])


def reverse_sets(data):
    """data: the values as deserialised (all but the first already shifted back by 2).
    Returns the number of sets rewritten."""
    p = 0
    version = data[p]; p += 1
    if version != SUPPORTED_VERSION:
        raise SystemExit("ATN version %d: this script reads version %d" % (version, SUPPORTED_VERSION))
    uuid = uuid_text(data[p:p + 8]); p += 8
    if uuid != UUID_ADDED_UNICODE_SMP:
        raise SystemExit("ATN serialized with features %s: this script reads %s" % (uuid, UUID_ADDED_UNICODE_SMP))
    grammar_type = data[p]; p += 1
    p += 1  # max token type
    nstates = data[p]; p += 1
    for _ in range(nstates):
        stype = data[p]; p += 1
        if stype == INVALID_TYPE:
            continue
        p += 1  # rule index
        if stype == LOOP_END or stype in BLOCK_STARTS:
            p += 1
    for _ in range(2):  # non-greedy states, precedence states
        n = data[p]; p += 1
        p += n
    nrules = data[p]; p += 1
    p += nrules * (2 if grammar_type == LEXER else 1)  # start state (+ token type)
    nmodes = data[p]; p += 1
    p += nmodes
    rewritten = 0
    for width in (1, 2):  # 16-bit bounds, then 32-bit bounds (two words each)
        nsets = data[p]; p += 1
        for _ in range(nsets):
            nintervals = data[p]; p += 1
            p += 1  # contains EOF
            size = 2 * width
            intervals = [data[p + i * size:p + (i + 1) * size] for i in range(nintervals)]
            data[p:p + nintervals * size] = [w for interval in reversed(intervals) for w in interval]
            p += nintervals * size
            rewritten += 1
    return rewritten


def main():
    path = sys.argv[1]
    text = open(path, encoding="utf-8").read()
    m = re.search(r"(_serializedATN = \{)([^}]*)(\};)", text)
    if not m:
        raise SystemExit("%s: no _serializedATN array" % path)
    raw = [int(v, 16) for v in re.findall(r"0x[0-9a-fA-F]+", m.group(2))]
    data = [raw[0]] + [(v - 2) & 0xFFFF for v in raw[1:]]
    n = reverse_sets(data)
    out = [data[0]] + [(v + 2) & 0xFFFF for v in data[1:]]
    # Like the tool's layout: 4-space indent, lines of values with a trailing comma.
    lines, line = [], "    "
    for v in out:
        item = "0x%x, " % v
        if len(line) + len(item) > 78:
            lines.append(line.rstrip() + " ")
            line = "    "
        line += item
    lines.append(line)
    body = "\n" + "\n".join(lines) + "\n  "
    text = text[:m.start(2)] + body + text[m.end(2):]
    open(path, "w", encoding="utf-8").write(text)
    print("%s: %d sets listed from the highest interval down" % (path, n))


if __name__ == "__main__":
    main()
