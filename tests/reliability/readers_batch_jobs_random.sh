#!/usr/bin/env bash
# fgsg batch's JOBS file is read in Python (python/fgsg/batch.py load_jobs), not in C++:
# random inputs for it instead of a libFuzzer target (issue 42). Each of some thousands of
# JOBS files (random bytes, JSON of random types, valid jobs with fields swapped for random
# values, deep nesting, invalid UTF-8, NUL) must give jobs whose paths are text, or a
# ValueError naming the file: never another exception, which fgsg batch would show as a
# traceback. The same for manifests (read_manifest). Found: a path field that is not text
# (TypeError), a nested list (RecursionError), a NUL in a path (an unlocated ValueError).
# FGSG_RANDOM_INPUTS=N and FGSG_RANDOM_SEED=S run N inputs from seed S (4000 from 42 in the
# suite; docs/testing.md has a run of 10^6).
. "$(dirname "$0")/lib.sh"
python3 - "$root/python/fgsg/batch.py" "$tmp" <<'PY' || fail "see above"
import importlib.util, json, os, random, sys

spec = importlib.util.spec_from_file_location("fgsg_batch", sys.argv[1])
batch = importlib.util.module_from_spec(spec)
spec.loader.exec_module(batch)  # load_jobs needs nothing of the compiled package
path = os.path.join(sys.argv[2], "jobs.json")
rng = random.Random(int(os.environ.get("FGSG_RANDOM_SEED", "42")))
inputs = int(os.environ.get("FGSG_RANDOM_INPUTS", "4000"))
FIELDS = ["grammar", "library", "output", "surface", "lots", "seed", "attrs", "id", "name", "jobs"]

def value(depth=0):
    kind = rng.randrange(9 if depth < 3 else 6)
    if kind == 0: return None
    if kind == 1: return rng.choice([True, False])
    if kind == 2: return rng.choice([0, -1, 1, 2**63, -2**70, 1e308, 0.5])
    if kind == 3: return rng.choice(["", "a.fgsg", "out/x.glb", "../x", "/", "\u0000", "a\u0000b", "\udcff", "é.glb", " "])
    if kind == 4: return "".join(chr(rng.randrange(1, 0x3000)) for _ in range(rng.randrange(8)))
    if kind == 5: return rng.choice(FIELDS)
    if kind == 6: return [value(depth + 1) for _ in range(rng.randrange(4))]
    return {rng.choice(FIELDS): value(depth + 1) for _ in range(rng.randrange(5))}

def job():
    j = {"grammar": "g.fgsg", "output": "o%d.glb" % rng.randrange(5)}
    for _ in range(rng.randrange(4)):
        j[rng.choice(FIELDS)] = value(1)
    return j

def text():
    kind = rng.randrange(6)
    if kind == 0: return bytes(rng.randrange(256) for _ in range(rng.randrange(64)))
    if kind == 1:
        n = rng.choice([10, 1000, 100000])
        return ("[" * n + "]" * n).encode()
    if kind == 2: return json.dumps(value()).encode()
    doc = [job() for _ in range(rng.randrange(4))]
    if kind == 3: doc = {"jobs": doc}
    data = json.dumps(doc, ensure_ascii=rng.random() < 0.5).encode("utf-8", "surrogatepass")
    if kind == 5 and data:  # a byte changed: broken JSON or text
        i = rng.randrange(len(data))
        data = data[:i] + bytes([rng.randrange(256)]) + data[i + 1:]
    return data

bad = 0
for n in range(inputs):
    if n and n % 100000 == 0:
        print(f"{n} inputs, {bad} bad", file=sys.stderr, flush=True)
    data = text()
    with open(path, "wb") as f:
        f.write(data)
    for reader in (batch.load_jobs, batch.read_manifest):
        try:
            got = reader(path)
            assert isinstance(got, list), got
            if reader is batch.load_jobs:
                for j in got:
                    for field in ("grammar", "library", "output", "surface", "lots"):
                        assert j.get(field) in (None, "") or isinstance(j[field], str), (field, j)
                    batch.job_inputs(j)  # what a resumed batch hashes
        except ValueError as e:
            if not str(e).startswith(path) and path not in str(e):
                bad += 1
                print(f"input {n}: {reader.__name__}: a message without the file: {e}", file=sys.stderr)
        except Exception as e:
            bad += 1
            print(f"input {n}: {reader.__name__}: {type(e).__name__}: {str(e)[:200]}\n  {data[:200]!r}", file=sys.stderr)
        if bad > 10:
            sys.exit(1)
sys.exit(1 if bad else 0)
PY
exit 0
