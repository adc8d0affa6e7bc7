"""World-sized jobs on Dask: `python -m fgsg.batch JOBS.json [--scheduler ADDRESS]
[--workers N]`.

JOBS.json is a list of jobs (or {"jobs": [...]}); each job is an object
    {"grammar": "city.fgsg", "output": "out/lot-17.glb",        # required
     "seed": 17, "attrs": {"lot_width": 24}, "surface": "tile.off", "id": "lot-17",
     "lots": "block-3.geojson"}                                   # footprints: fgsg run --lots
("library": "libcity.so" instead of "grammar": a grammar built by `fgsg compile`, whose
compiled code runs; "name" if the file is not libNAME.so)
with paths relative to the JOBS file's folder. The jobs are mapped over a dask.distributed
cluster: an embedded LocalCluster (N worker processes, one thread each) unless
--scheduler names a running scheduler. Each worker compiles a grammar once and keeps it.
A job writes its .glb (atomically) and reports its figures; a job that fails reports its
error (with the grammar's file:line:col) and the others go on. A job whose output exists
is skipped, so a batch that was stopped resumes where it was. Dask retries the jobs of a
worker that dies. The manifest, JOBS.manifest.json beside JOBS.json, lists every job's
outcome; progress goes to stderr; the exit code is 0 when every job succeeded, else 1.
"""
import argparse
import functools
import json
import os
import sys
import tempfile
import time


def load_jobs(path):
    """The jobs of a JOBS file, paths made absolute (relative to its folder); raises
    ValueError naming the job and field for a malformed one."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    jobs = data.get("jobs") if isinstance(data, dict) else data
    if not isinstance(jobs, list):
        raise ValueError(f"{path}: expected a list of jobs or {{\"jobs\": [...]}}")
    base = os.path.dirname(os.path.abspath(path))
    out = []
    for i, job in enumerate(jobs):
        if not isinstance(job, dict):
            raise ValueError(f"{path}: job {i} is not an object")
        if not isinstance(job.get("grammar") or job.get("library"), str):
            raise ValueError(f"{path}: job {i} needs \"grammar\" (or \"library\", a compiled grammar)")
        if not isinstance(job.get("output"), str) or not job["output"]:
            raise ValueError(f"{path}: job {i} needs \"output\" (a path)")
        j = dict(job)
        j.setdefault("id", str(i))
        j.setdefault("seed", 1)
        j.setdefault("attrs", {})
        for field in ("grammar", "library", "output", "surface", "lots"):
            if j.get(field):
                j[field] = os.path.normpath(os.path.join(base, j[field]))
        out.append(j)
    return out


@functools.lru_cache(maxsize=16)
def _grammar(path, library=False, name=""):
    import fgsg  # in the worker's process
    return fgsg.Grammar.from_library(path, name) if library else fgsg.Grammar.from_file(path)


def run_job(job):
    """Runs one job in the calling process: a dict with its outcome, never an exception
    (a failing job must not take the batch down)."""
    import fgsg
    start = time.monotonic()
    outcome = {"id": job["id"], "output": job["output"]}
    try:
        grammar = (_grammar(job["library"], True, job.get("name", "")) if job.get("library")
                   else _grammar(job["grammar"]))
        result = grammar.generate(seed=job["seed"], attrs=job["attrs"], surface=job.get("surface"),
                                  lots=job.get("lots"))
        os.makedirs(os.path.dirname(job["output"]) or ".", exist_ok=True)
        result.write(job["output"])
        outcome.update(ok=True, triangles=result.stats["triangles"], instances=result.stats["instances"])
    except fgsg.GrammarError as e:
        outcome.update(ok=False, error=str(e), file=e.file, line=e.line, column=e.column, code=e.code)
    except Exception as e:  # a file that cannot be read or written, ...
        outcome.update(ok=False, error=f"{type(e).__name__}: {e}")
    outcome["seconds"] = round(time.monotonic() - start, 4)
    return outcome


def run_batch(jobs, client, progress=None, on_result=None):
    """Maps the jobs whose output does not exist yet over `client`'s cluster; returns the
    outcomes in job order (skipped ones say so). `progress(done, total, failed)` and
    `on_result(outcome)` are called as results arrive."""
    from distributed import as_completed

    outcomes = [None] * len(jobs)
    futures = {}
    for i, job in enumerate(jobs):
        if os.path.exists(job["output"]):
            outcomes[i] = {"id": job["id"], "output": job["output"], "ok": True, "skipped": True}
        else:
            futures[client.submit(run_job, job, key=f"fgsg-job-{i}-{job['id']}", pure=False)] = i
    done = len(jobs) - len(futures)
    failed = 0
    if progress:
        progress(done, len(jobs), failed)
    for future in as_completed(futures):
        outcome = future.result()
        outcomes[futures[future]] = outcome
        done += 1
        failed += not outcome["ok"]
        if on_result:
            on_result(outcome)
        if progress:
            progress(done, len(jobs), failed)
    return outcomes


def write_manifest(path, outcomes):
    """The outcomes as JSON, replacing `path` atomically."""
    folder = os.path.dirname(os.path.abspath(path))
    with tempfile.NamedTemporaryFile("w", dir=folder, delete=False, suffix=".tmp", encoding="utf-8") as f:
        json.dump({"format": "fgsg-batch-manifest", "version": 1, "jobs": outcomes}, f, indent=1)
        f.write("\n")
    os.replace(f.name, path)


def main(argv=None):
    parser = argparse.ArgumentParser(prog=os.environ.get("FGSG_BATCH_PROG", "python -m fgsg.batch"),
                                     description="Runs fgsg jobs on Dask (docs/scale.md).")
    parser.add_argument("jobs", help="JOBS.json: a list of {grammar, output, seed, attrs, surface, id}")
    parser.add_argument("--scheduler", help="a running dask scheduler, tcp://host:port (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 2,
                        help="LocalCluster worker processes (default: the cores)")
    args = parser.parse_args(argv)
    try:
        jobs = load_jobs(args.jobs)
    except (OSError, ValueError) as e:
        print(f"fgsg batch: {e}", file=sys.stderr)
        return 2

    from distributed import Client, LocalCluster

    def progress(done, total, failed):
        end = "\n" if done == total or not sys.stderr.isatty() else ""
        print(f"\rfgsg batch: {done}/{total} jobs done" + (f", {failed} failed" if failed else ""),
              end=end, file=sys.stderr, flush=True)

    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(n_workers=max(1, args.workers), threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        client = Client(cluster)
    try:
        outcomes = run_batch(jobs, client, progress=progress)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    manifest = os.path.splitext(args.jobs)[0] + ".manifest.json"
    write_manifest(manifest, outcomes)
    failures = [o for o in outcomes if not o["ok"]]
    for o in failures:
        print(f"fgsg batch: job {o['id']} failed: {o['error']}", file=sys.stderr)
    print(f"fgsg batch: wrote {manifest} ({len(outcomes) - len(failures)} of {len(outcomes)} jobs succeeded)",
          file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
