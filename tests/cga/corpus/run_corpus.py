#!/usr/bin/env python3
"""The CGA corpus: CityEngine rule files written from the CGA reference, each with the
results computed by hand from CityEngine's documented semantics in NAME.expect.json. Each
file runs through `fgsg run` with both engines (--engine=interp and --engine=jit); the
engines must agree byte for byte (instances, reports) and the results must match the
expectations within a tolerance.

    run_corpus.py FGSG CORPUS_DIR [NAME ...]     (no names: every NAME.cga of the folder)

Exits 1 when any file fails; prints one line per file (PASS / FAIL with the reasons).

NAME.expect.json (every key optional but "lots"):
  "lots":      the --lots file, relative to the corpus folder
  "rule":      the rule file, relative to the corpus folder (default NAME.cga beside it)
  "args":      more fgsg run arguments (["--start-rule", "Street"])
  "count":     {symbol: number of leaf instances placed under it}  (0: none)
  "total":     number of instances in all
  "extent":    {symbol: [dx, dy, dz]}  the world bounding box's size of its instances
  "bbox":      {symbol or "*": [[x0, y0, z0], [x1, y1, z1]]}  the world bounding box
  "area":      {symbol: m2}  the summed area of its flat instances (faces, split pieces)
  "color":     {symbol: [r, g, b]}  every instance's colour
  "asset":     {symbol: asset name}  every instance's asset ("*/a.obj": any name ending so)
  "count_range": {symbol: [lo, hi]}  its count lies between (a stochastic rule)
  "count_sum": [[[symbols], n], ...]  the counts of those symbols add up to n
  "reports":   {"all": {key: {stat: value}}, "starts": [{key: {stat: value}}, ...]}
               stats as --report writes them: values, count, sum, average, min, max, nnz, strings
  "stderr":    [text, ...]  lines that stderr must contain (print)
  "uv":        {image file name: [[u0, v0], [u1, v1]]}  the range of the texture coordinates
               of the faces that use that image (the mesh is then written as OBJ + .mtl)
  "mesh":      {"area": m2, "volume": m3}  the whole written mesh's triangle area and enclosed
               volume (signed: closed outward solids add theirs; the mesh is then written as OBJ)
  "tolerance": absolute tolerance for numbers (default 1e-4)
World axes: x east, y up, z south (north is -z), as fgsg places --lots lots.
"""
import json
import os
import subprocess
import sys
import tempfile


def corners(t):
    """The 8 world corners of an instance's unit box (t: 16 numbers, column-major)."""
    out = []
    for x in (0, 1):
        for y in (0, 1):
            for z in (0, 1):
                out.append([t[0] * x + t[4] * y + t[8] * z + t[12],
                            t[1] * x + t[5] * y + t[9] * z + t[13],
                            t[2] * x + t[6] * y + t[10] * z + t[14]])
    return out


def flat_area(t):
    cols = [t[0:3], t[4:7], t[8:11]]
    norms = [sum(c * c for c in col) ** 0.5 for col in cols]
    flat = [k for k in range(3) if norms[k] < 1e-9]
    if len(flat) != 1:
        return None
    a, b = [cols[k] for k in range(3) if k != flat[0]]
    cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    return sum(c * c for c in cross) ** 0.5


def bbox(instances):
    pts = [p for inst in instances for p in corners(inst["transform"])]
    return [[min(p[k] for p in pts) for k in range(3)], [max(p[k] for p in pts) for k in range(3)]]


def close(a, b, tol):
    if isinstance(b, bool) or isinstance(a, bool) or isinstance(b, str) or b is None:
        return a == b
    if isinstance(b, (int, float)):
        return isinstance(a, (int, float)) and abs(a - b) <= tol * max(1.0, abs(b))
    if isinstance(b, list):
        return isinstance(a, list) and len(a) == len(b) and all(close(x, y, tol) for x, y in zip(a, b))
    if isinstance(b, dict):
        return isinstance(a, dict) and all(k in a and close(a[k], v, tol) for k, v in b.items())
    return a == b


def check_reports(got, want, where, tol, problems):
    for key, stats in want.items():
        if key not in got:
            problems.append("%s: no report %r (have %s)" % (where, key, sorted(got)))
            continue
        for stat, value in stats.items():
            have = got[key].get(stat)
            if not close(have, value, tol):
                problems.append("%s: report %r %s is %r, expected %r" % (where, key, stat, have, value))


def check(expect, instances_doc, reports_doc, stderr, problems):
    tol = expect.get("tolerance", 1e-4)
    by_symbol = {}
    for inst in instances_doc["instances"]:
        by_symbol.setdefault(inst["symbol"], []).append(inst)
    for sym, n in expect.get("count", {}).items():
        have = len(by_symbol.get(sym, []))
        if have != n:
            problems.append("count %s: %d, expected %d" % (sym, have, n))
    if "total" in expect and len(instances_doc["instances"]) != expect["total"]:
        problems.append("instances: %d, expected %d" % (len(instances_doc["instances"]), expect["total"]))
    for sym, (lo, hi) in expect.get("count_range", {}).items():
        have = len(by_symbol.get(sym, []))
        if not lo <= have <= hi:
            problems.append("count %s: %d, expected %d to %d" % (sym, have, lo, hi))
    for group, n in expect.get("count_sum", []):
        have = sum(len(by_symbol.get(s, [])) for s in group)
        if have != n:
            problems.append("count %s: %d, expected %d" % ("+".join(group), have, n))
    for sym, want in expect.get("extent", {}).items():
        if not by_symbol.get(sym):
            problems.append("extent %s: no instances" % sym)
            continue
        lo, hi = bbox(by_symbol[sym])
        have = [hi[k] - lo[k] for k in range(3)]
        if not close(have, want, tol):
            problems.append("extent %s: %s, expected %s" % (sym, [round(v, 5) for v in have], want))
    for sym, want in expect.get("bbox", {}).items():
        insts = instances_doc["instances"] if sym == "*" else by_symbol.get(sym, [])
        if not insts:
            problems.append("bbox %s: no instances" % sym)
            continue
        have = bbox(insts)
        if not close(have, want, tol):
            problems.append("bbox %s: %s, expected %s" % (sym, [[round(v, 5) for v in c] for c in have], want))
    for sym, want in expect.get("area", {}).items():
        total, bad = 0.0, 0
        for inst in by_symbol.get(sym, []):
            a = flat_area(inst["transform"])
            if a is None:
                bad += 1
            else:
                total += a
        if bad:
            problems.append("area %s: %d instances are not flat" % (sym, bad))
        elif not close(total, want, tol):
            problems.append("area %s: %.6g, expected %.6g" % (sym, total, want))
    for sym, want in expect.get("color", {}).items():
        for inst in by_symbol.get(sym, []):
            if not close(inst["color"], want, 2e-3):
                problems.append("color %s: %s, expected %s" % (sym, inst["color"], want))
                break
    for sym, want in expect.get("asset", {}).items():
        for inst in by_symbol.get(sym, []):
            # "*NAME": an asset file, named relative to the output (any path ending in NAME)
            if inst["asset"] != want and not (want.startswith("*") and inst["asset"].endswith(want[1:])):
                problems.append("asset %s: %s, expected %s" % (sym, inst["asset"], want))
                break
    reports = expect.get("reports", {})
    if reports:
        if reports_doc is None:
            problems.append("no report file")
        else:
            check_reports(reports_doc["all"], reports.get("all", {}), "all", tol, problems)
            starts = reports.get("starts", [])
            if starts and len(reports_doc["starts"]) != len(starts):
                problems.append("%d start shapes reported, expected %d" % (len(reports_doc["starts"]), len(starts)))
            for k, want in enumerate(starts):
                if k < len(reports_doc["starts"]):
                    check_reports(reports_doc["starts"][k]["reports"], want, "start %d" % k, tol, problems)
    for text in expect.get("stderr", []):
        if text not in stderr:
            problems.append("stderr lacks %r" % text)


def mesh_totals(obj_path):
    """The written OBJ's total triangle area and enclosed volume (signed, by the divergence
    theorem: outward faces of closed solids give their volume)."""
    points, area, volume = [], 0.0, 0.0
    with open(obj_path, encoding="utf-8") as f:
        for line in f:
            w = line.split()
            if w and w[0] == "v":
                points.append([float(x) for x in w[1:4]])
            elif w and w[0] == "f":
                ix = [int(t.split("/")[0]) - 1 for t in w[1:]]
                for k in range(1, len(ix) - 1):
                    a, b, c = points[ix[0]], points[ix[k]], points[ix[k + 1]]
                    u = [b[i] - a[i] for i in range(3)]
                    v = [c[i] - a[i] for i in range(3)]
                    cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
                    area += 0.5 * sum(x * x for x in cross) ** 0.5
                    volume += sum(a[i] * (b[(i + 1) % 3] * c[(i + 2) % 3] - b[(i + 2) % 3] * c[(i + 1) % 3])
                                  for i in range(3)) / 6
    return area, volume


def check_mesh(expect, obj_path, problems):
    """"mesh": {"area": A, "volume": V}: the totals of the whole written mesh (an OBJ)."""
    if "mesh" not in expect:
        return
    area, volume = mesh_totals(obj_path)
    for key, have in (("area", area), ("volume", volume)):
        want = expect["mesh"].get(key)
        if want is not None and not close(have, want, expect.get("tolerance", 1e-4)):
            problems.append("mesh %s: %.7g, expected %.7g" % (key, have, want))


def uv_ranges(obj_path):
    """{image file name: [[u0, v0], [u1, v1]]} over the faces of an OBJ that use it (map_Kd)."""
    images, image = {}, None
    with open(obj_path[:-4] + ".mtl", encoding="utf-8") as f:
        for line in f:
            words = line.split()
            if words[:1] == ["newmtl"]:
                image = words[1]
            elif words[:1] == ["map_Kd"]:
                images[image] = os.path.basename(words[-1])
    uvs, ranges, image = [], {}, None
    with open(obj_path, encoding="utf-8") as f:
        for line in f:
            words = line.split()
            if words[:1] == ["vt"]:
                uvs.append([float(words[1]), float(words[2])])
            elif words[:1] == ["usemtl"]:
                image = images.get(words[1])
            elif words[:1] == ["f"] and image:
                for corner in words[1:]:
                    parts = corner.split("/")
                    if len(parts) > 1 and parts[1]:
                        u, v = uvs[int(parts[1]) - 1]
                        lo, hi = ranges.setdefault(image, [[u, v], [u, v]])
                        lo[:] = [min(lo[0], u), min(lo[1], v)]
                        hi[:] = [max(hi[0], u), max(hi[1], v)]
    return ranges


def run_one(fgsg, folder, name, work):
    cga = os.path.join(folder, name + ".cga")
    if not os.path.exists(cga) and os.path.exists(os.path.join(folder, name + ".fgsg")):
        cga = os.path.join(folder, name + ".fgsg")  # the same checks for fgsg's dialect
    with open(os.path.join(folder, name + ".expect.json"), encoding="utf-8") as f:
        expect = json.load(f)
    if "rule" in expect:  # a rule file kept elsewhere (the tutorials in examples/)
        cga = os.path.join(folder, expect["rule"])
    outputs, problems = {}, []
    for engine in ("interp", "jit"):
        inst, rep = os.path.join(work, name + "." + engine + ".json"), os.path.join(work, name + "." + engine + ".report.json")
        mesh = os.path.join(work, name + "." + engine + (".obj" if "uv" in expect or "mesh" in expect else ".glb"))
        cmd = [fgsg, "run", cga, "--engine=" + engine, "-o", mesh,
               "--instances", inst, "--report", rep, "--stats"]
        if "lots" in expect:
            cmd += ["--lots", os.path.join(folder, expect["lots"])]
        cmd += expect.get("args", [])
        try:
            run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        except subprocess.TimeoutExpired:
            return ["%s: timed out" % engine]
        if run.returncode != 0:
            lines = [l for l in run.stderr.splitlines() if l.strip()]
            first = next((l for l in lines if "error" in l), lines[0] if lines else "")
            return ["%s: exit %d: %s" % (engine, run.returncode, first.strip())]
        with open(inst, encoding="utf-8") as f:
            inst_text = f.read()
        with open(rep, encoding="utf-8") as f:
            rep_text = f.read()
        outputs[engine] = (inst_text, rep_text)
        engine_problems = []
        check(expect, json.loads(inst_text), json.loads(rep_text), run.stderr, engine_problems)
        check_mesh(expect, mesh, engine_problems)
        if "uv" in expect:
            have = uv_ranges(mesh)
            for image, want in expect["uv"].items():
                if not close(have.get(image), want, expect.get("tolerance", 1e-4)):
                    engine_problems.append("uv %s: %s, expected %s" % (image, have.get(image), want))
        problems += ["%s: %s" % (engine, p) for p in engine_problems]
    if outputs["interp"][0] != outputs["jit"][0]:
        problems.append("the engines' instances differ")
    if outputs["interp"][1] != outputs["jit"][1]:
        problems.append("the engines' reports differ")
    return problems


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    fgsg, folder = sys.argv[1], sys.argv[2]
    names = sys.argv[3:] or sorted(f[:-4] for f in os.listdir(folder) if f.endswith(".cga"))
    failed = []
    with tempfile.TemporaryDirectory() as work:
        for name in names:
            problems = run_one(fgsg, folder, name, work)
            if problems:
                failed.append(name)
                print("FAIL %s" % name)
                for p in problems[:8]:
                    print("     %s" % p)
            else:
                print("PASS %s" % name)
    print("%d of %d CGA corpus files pass with both engines" % (len(names) - len(failed), len(names)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
