"""World-sized jobs on Dask: `python -m fgsg.batch JOBS.json [--scheduler ADDRESS]
[--workers N] [--dashboard]`.

JOBS.json is a list of jobs (or {"jobs": [...]}); each job is an object
    {"grammar": "city.fgsg", "output": "out/lot-17.glb",        # required
     "seed": 17, "attrs": {"lot_width": 24}, "surface": "tile.off", "id": "lot-17",
     "lots": "block-3.geojson",                                   # footprints: fgsg run --lots
     "step": 2}                                                   # an L-system's step: fgsg run --step
("library": "libcity.so" instead of "grammar": a grammar built by `fgsg compile`, whose
compiled code runs; "name" if the file is not libNAME.so)
with paths relative to the JOBS file's folder. The jobs are mapped over a dask.distributed
cluster: an embedded LocalCluster (N worker processes, one thread each) unless
--scheduler names a running scheduler. Each worker compiles a grammar once and keeps it.
A job writes its .glb (atomically) and reports its figures; a job that fails reports its
error (with the grammar's file:line:col) and the others go on. Two jobs may not name one
output. Dask retries the jobs of a worker that dies.

The manifest, JOBS.manifest.json beside JOBS.json (written atomically), lists the outcome
of every job that finished, each with "inputs": a hash of what produced its output (the
grammar with its imported modules, or the library; the seed, the attributes, the surface,
the lots and every other field but "id" and "output"; job_inputs). Running the same
command again resumes: a job is skipped when the manifest records it succeeded with the
same inputs and its output is whole (verify_output), keeping its first run's figures;
a job whose inputs changed, that failed, that the manifest does not record, or whose
output is damaged (empty, a .glb whose header length is not the file's) runs again.
--force runs every job. Progress goes to stderr. SIGINT (Ctrl-C) or SIGTERM stops the
batch: the manifest says which jobs finished ("complete": false, "pending": the others),
one line says so, and the exit code is 130 (143 for SIGTERM). Otherwise the exit code is
0 when every job succeeded, 1 when one failed, 2 when nothing ran (a malformed JOBS file,
a manifest that cannot be written).

The tasks a cluster runs are functions of this module (run_job): its workers import
fgsg.batch, so the package must be on their PYTHONPATH (docs/scale.md).

Every server of the embedded LocalCluster (scheduler, nannies, workers, their HTTP
servers) listens on 127.0.0.1 only; the scheduler's dashboard and information pages are
off unless --dashboard asks for them (then on 127.0.0.1, the address printed).
"""
import argparse
import functools
import hashlib
import json
import logging
import os
import signal
import struct
import sys
import tempfile
import time


def load_jobs(path):
    """The jobs of a JOBS file, paths made absolute (relative to its folder); raises
    ValueError naming the job and field for a malformed one."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except UnicodeDecodeError as e:
        raise ValueError(f"{path}: not UTF-8 text (byte {e.start})") from None
    except json.JSONDecodeError as e:
        raise ValueError(f"{path}:{e.lineno}:{e.colno}: not valid JSON ({e.msg})") from None
    except RecursionError:
        raise ValueError(f"{path}: nested too deeply for a JOBS file") from None
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
        _check_step(path, i, j)
        j.setdefault("id", str(i))
        j.setdefault("seed", 1)
        j.setdefault("attrs", {})
        for field in ("grammar", "library", "output", "surface", "lots"):
            value = j.get(field)
            if value is None or value == "":
                continue
            if not isinstance(value, str) or "\0" in value:
                raise ValueError(f"{path}: job {i}: \"{field}\" must be a path (text without NUL bytes), "
                                 f"not {json.dumps(value)[:60]}")
            j[field] = os.path.normpath(os.path.join(base, value))
        out.append(j)
    # Two jobs writing one file: one result would silently replace the other, and a
    # resumed batch would skip both.
    seen = {}
    for j in out:
        key = os.path.realpath(j["output"])
        if key in seen:
            raise ValueError(f"{path}: jobs {seen[key]['id']!r} and {j['id']!r} both write {j['output']}: "
                             "give each job its own output")
        seen[key] = j
    return out


_STEP_MAX = 2**31 - 1  # fgsg run --step's range


def _check_step(path, i, job):
    """A job's "step" (fgsg run --step: an L-system derived that many steps) must be a
    whole number from 0 to 2**31 - 1; null is the same as none (the whole derivation)."""
    if "step" not in job:
        return
    step = job["step"]
    if step is None:
        del job["step"]  # hashed as a job without one: its output is the same
        return
    if isinstance(step, bool) or not isinstance(step, int) or not 0 <= step <= _STEP_MAX:
        name = f"job {i}" + (f" ({job['id']!r})" if isinstance(job.get("id"), str) else "")
        raise ValueError(f"{path}: {name}: \"step\" must be a whole number from 0 to {_STEP_MAX} "
                         f"(the L-system's derivation step, as fgsg run --step), not {json.dumps(step)[:60]}")


# Bump when what job_inputs hashes changes: every recorded output is then made again.
_INPUTS_VERSION = 1
_FILE_FIELDS = ("grammar", "library", "surface", "lots")


@functools.lru_cache(maxsize=256)
def _file_digest(path, mtime_ns, size, grammar):
    """sha256 of a file's bytes; of a grammar's text with its imported modules when it
    compiles (a module changed is a grammar changed). Keyed by mtime and size too, so that
    a file changed while the process lives is hashed again."""
    if grammar:
        try:
            import fgsg
            return hashlib.sha256(fgsg.Grammar.from_file(path).source).hexdigest()
        except Exception:  # does not compile: its bytes (the job fails, and runs again)
            pass
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _describe_file(path, grammar=False):
    try:
        st = os.stat(path)
        return _file_digest(path, st.st_mtime_ns, st.st_size, grammar)
    except OSError as e:
        return f"unreadable: {e.strerror or e}"


def job_inputs(job):
    """A hash (hex sha256) of what a job's output is made from: the contents of its grammar
    (with the modules it imports) or library, surface and lots files, and its seed,
    attributes, step and every other field but "id" and "output". A resumed batch skips a job
    only when its output was made from the same inputs. Assets a grammar loads are not
    hashed: --force after changing one."""
    described = {"inputs_version": _INPUTS_VERSION}
    for key, value in job.items():
        if key in ("id", "output"):
            continue
        if key in _FILE_FIELDS and isinstance(value, str) and value:
            described[key] = {"sha256": _describe_file(value, grammar=key == "grammar")}
        elif key == "step":
            # Not the bare value: a "step" written before the batch took it was ignored,
            # and a job recorded with it so must run again.
            described[key] = {"derivation_step": value}
        else:
            described[key] = value
    text = json.dumps(described, sort_keys=True, separators=(",", ":"), default=repr)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


_GLB_MAGIC, _GLB_JSON, _GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942
_PLY_SIZES = {"char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2, "int16": 2, "uint16": 2,
              "int": 4, "uint": 4, "int32": 4, "uint32": 4, "float": 4, "float32": 4, "double": 8, "float64": 8}


def verify_output(path):
    """None when the file at `path` is a whole output as `Result.write` makes it, else why
    not (a resumed batch writes such a file again instead of skipping its job): it must be
    a regular, non-empty file; a .glb's header must say glTF 2 and its length and chunk
    lengths must add up to the file's size; a .ply's header must end and its binary
    records (triangles, as fgsg writes them) fill the rest; an .obj must end its last line."""
    try:
        if not os.path.isfile(path):
            return "not a regular file"
        size = os.path.getsize(path)
        if size == 0:
            return "the file is empty (0 bytes)"
        ext = os.path.splitext(path)[1].lower()
        with open(path, "rb") as f:
            if ext == ".glb":
                return _verify_glb(f, size)
            if ext == ".ply":
                return _verify_ply(f, size)
            if ext == ".obj":
                f.seek(size - 1)
                return None if f.read(1) == b"\n" else "the last line is cut short (no newline at the end)"
    except OSError as e:
        return f"cannot read it ({e.strerror or e})"
    return None


def _verify_glb(f, size):
    header = f.read(12)
    if len(header) < 12:
        return f"{size} bytes: shorter than a glTF header"
    magic, version, length = struct.unpack("<III", header)
    if magic != _GLB_MAGIC or version != 2:
        return "not a binary glTF 2 file (its header)"
    if length != size:
        return f"the glTF header says {length} bytes, the file has {size}"
    at, first = 12, True
    while at < size:
        chunk = f.read(8)
        if len(chunk) < 8:
            return f"a glTF chunk header is cut short at byte {at}"
        chunk_length, chunk_type = struct.unpack("<II", chunk)
        if first and chunk_type != _GLB_JSON:
            return "the first glTF chunk is not its JSON"
        if at + 8 + chunk_length > size:
            return f"a glTF chunk of {chunk_length} bytes at byte {at} runs past the end"
        at += 8 + chunk_length
        f.seek(at)
        first = False
    return "a glTF file without its JSON chunk" if first else None


def _verify_ply(f, size):
    head = f.read(min(size, 1 << 16))
    end = head.find(b"end_header\n")
    if not head.startswith(b"ply\n") or end < 0:
        return "not a PLY file with a whole header"
    expected = end + len(b"end_header\n")
    binary = False
    elements = []  # [count, bytes per record]
    for line in head[:end].decode("ascii", "replace").splitlines():
        words = line.split()
        if words[:1] == ["format"]:
            binary = len(words) > 1 and words[1] != "ascii"
        elif words[:1] == ["element"] and len(words) == 3 and words[2].isdigit():
            elements.append([int(words[2]), 0])
        elif words[:1] == ["property"] and elements:
            if len(words) == 5 and words[1] == "list":  # fgsg writes triangles: a count and 3 indices
                elements[-1][1] += _PLY_SIZES.get(words[2], 0) + 3 * _PLY_SIZES.get(words[3], 0)
            elif len(words) == 3:
                elements[-1][1] += _PLY_SIZES.get(words[1], 0)
    if not binary:
        return None
    expected += sum(count * record for count, record in elements)
    return None if expected == size else f"its header describes {expected} bytes, the file has {size}"


@functools.lru_cache(maxsize=16)
def _grammar(path, library=False, name="", version=None):
    """The grammar at `path`, compiled once per `version` of it (a hash of its text with its
    modules, or its file's mtime and size), so that a worker does not keep running a
    grammar that changed."""
    import fgsg  # in the worker's process
    return fgsg.Grammar.from_library(path, name) if library else fgsg.Grammar.from_file(path)


def _file_version(path):
    try:
        st = os.stat(path)
        return (st.st_mtime_ns, st.st_size)
    except OSError:
        return None


def run_job(job, version=None):
    """Runs one job in the calling process: a dict with its outcome, never an exception
    (a failing job must not take the batch down). `version` identifies the contents of
    the job's grammar or library (run_batch passes their hash); by default its file's
    mtime and size."""
    import fgsg
    start = time.monotonic()
    outcome = {"id": job["id"], "output": job["output"]}
    try:
        path = job.get("library") or job["grammar"]
        version = version or _file_version(path)
        grammar = (_grammar(path, True, job.get("name", ""), version) if job.get("library")
                   else _grammar(path, version=version))
        result = grammar.generate(seed=job["seed"], attrs=job["attrs"], surface=job.get("surface"),
                                  lots=job.get("lots"), step=job.get("step"))
        os.makedirs(os.path.dirname(job["output"]) or ".", exist_ok=True)
        result.write(job["output"])
        outcome.update(ok=True, triangles=result.stats["triangles"], instances=result.stats["instances"])
    except fgsg.GrammarError as e:
        outcome.update(ok=False, error=str(e), file=e.file, line=e.line, column=e.column, code=e.code)
    except Exception as e:  # a file that cannot be read or written, ...
        outcome.update(ok=False, error=f"{type(e).__name__}: {e}")
    outcome["seconds"] = round(time.monotonic() - start, 4)
    return outcome


def _outcome_of(future, job):
    """A finished future's outcome; a task that raised (a worker that cannot import fgsg,
    one killed three times) is a failed job, not the end of the batch."""
    try:
        return future.result()
    except Exception as e:
        error = f"{type(e).__name__}: {e}"
        if isinstance(e, ImportError) or "No module named 'fgsg'" in error:
            error += " (the workers must import the fgsg package: put it on their PYTHONPATH)"
        return {"id": job["id"], "output": job["output"], "ok": False, "error": error}


def run_batch(jobs, client, progress=None, on_result=None, on_damaged=None, previous=None, force=False,
              outcomes=None):
    """Maps the jobs over `client`'s cluster and returns their outcomes in job order, each
    with "inputs" (job_inputs). A job is skipped (its outcome the earlier one, "skipped":
    True) when `previous` -- the outcomes of an earlier run, a manifest's "jobs" -- says it
    succeeded with the same inputs and its output is whole (verify_output); unless `force`.
    A job run again over a damaged output says why in "replaced", one run again over a
    whole one in "rerun". `progress(done, total, failed)` and `on_result(outcome)` are
    called as results arrive, `on_damaged(job, why)` before. `outcomes`, a list, is filled
    in place as jobs finish (None for one that has not): what a caller interrupted by
    KeyboardInterrupt knows finished."""
    from distributed import as_completed

    outputs = [os.path.realpath(job["output"]) for job in jobs]
    if len(set(outputs)) != len(outputs):
        raise ValueError("two jobs name one output (load_jobs says which)")
    if outcomes is None:
        outcomes = []
    outcomes[:] = [None] * len(jobs)
    decided = [None] * len(jobs)  # into `outcomes` once every job is looked at
    earlier = {}
    for o in previous or ():
        if isinstance(o, dict) and isinstance(o.get("output"), str):
            earlier[os.path.realpath(o["output"])] = o
    inputs = [job_inputs(job) for job in jobs]
    futures = {}
    reasons = {}
    for i, job in enumerate(jobs):
        record = earlier.get(outputs[i])
        if os.path.lexists(job["output"]):
            why = verify_output(job["output"])
            if why is not None:
                reasons[i] = ("replaced", why)
                if on_damaged:
                    on_damaged(job, why)
            elif force:
                reasons[i] = ("rerun", "--force")
            elif record is None:
                reasons[i] = ("rerun", "no earlier outcome records what made the output")
            elif not record.get("ok"):
                reasons[i] = ("rerun", "it failed before")
            elif record.get("inputs") != inputs[i]:
                reasons[i] = ("rerun", "its inputs changed")
            else:
                kept = {k: v for k, v in record.items() if k not in ("replaced", "rerun")}
                decided[i] = dict(kept, id=job["id"], output=job["output"], ok=True, skipped=True)
    # Stopped before this point, a caller has nothing new to record (and keeps its manifest).
    outcomes[:] = decided
    for i, job in enumerate(jobs):
        if decided[i] is not None:
            continue
        source = job.get("library") or job["grammar"]
        version = _describe_file(source, grammar=not job.get("library"))
        futures[client.submit(run_job, job, version, key=f"fgsg-job-{i}-{job['id']}", pure=False)] = i
    done = len(jobs) - len(futures)
    failed = 0
    if progress:
        progress(done, len(jobs), failed)
    for future in as_completed(futures):
        i = futures[future]
        outcome = _outcome_of(future, jobs[i])
        outcome["inputs"] = inputs[i]
        if i in reasons:
            outcome[reasons[i][0]] = reasons[i][1]
        outcomes[i] = outcome
        done += 1
        failed += not outcome["ok"]
        if on_result:
            on_result(outcome)
        if progress:
            progress(done, len(jobs), failed)
    return outcomes


def manifest_problem(path):
    """None when the manifest can be written at `path`, else why not; asked before any
    job runs, so that a batch does not run for nothing."""
    folder = os.path.dirname(os.path.abspath(path))
    if os.path.isdir(path):
        return f"the manifest {path} is a directory: move it away (the manifest is a file)"
    if os.path.lexists(path) and not os.path.isfile(path):
        return f"the manifest {path} is not a regular file"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"cannot write the manifest {path}: its folder is not writable"
    return None


MANIFEST_VERSION = 2


def manifest_path(jobs_path):
    """Where `fgsg batch JOBS.json` writes its manifest: JOBS.manifest.json beside it."""
    return os.path.splitext(jobs_path)[0] + ".manifest.json"


def read_manifest(path):
    """The outcomes an earlier run recorded at `path` (its "jobs"); [] when there is no
    manifest. Raises ValueError for one that cannot be read as a manifest."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except FileNotFoundError:
        return []
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
        raise ValueError(f"the manifest {path} cannot be read ({e})") from None
    except RecursionError:
        raise ValueError(f"the manifest {path} cannot be read (nested too deeply)") from None
    if not isinstance(data, dict) or data.get("format") != "fgsg-batch-manifest" or \
            not isinstance(data.get("jobs"), list):
        raise ValueError(f"{path} is not an fgsg batch manifest")
    return [o for o in data["jobs"] if isinstance(o, dict)]


def write_manifest(path, outcomes, jobs=None, stopped=None):
    """The outcomes as JSON, replacing `path` atomically; no temporary file is left when
    that fails. `outcomes` in job order, None for a job that has not finished (with `jobs`,
    those are listed in "pending" by id); `stopped` says why the batch ended early."""
    finished = [o for o in outcomes if o is not None]
    pending = [j["id"] for j, o in zip(jobs or (), outcomes) if o is None]
    summary = {"jobs": len(outcomes), "finished": len(finished),
               "succeeded": sum(1 for o in finished if o.get("ok")),
               "failed": sum(1 for o in finished if not o.get("ok")),
               "skipped": sum(1 for o in finished if o.get("skipped"))}
    document = {"format": "fgsg-batch-manifest", "version": MANIFEST_VERSION,
                "complete": len(finished) == len(outcomes), "stopped": stopped, "summary": summary,
                "jobs": finished, "pending": pending}
    folder = os.path.dirname(os.path.abspath(path))
    with tempfile.NamedTemporaryFile("w", dir=folder, delete=False, suffix=".tmp", encoding="utf-8") as f:
        try:
            json.dump(document, f, indent=1)
            f.write("\n")
        except BaseException:
            f.close()
            os.unlink(f.name)
            raise
    try:
        os.replace(f.name, path)
    except BaseException:
        os.unlink(f.name)
        raise


# The scheduler's HTTP routes without --dashboard: its health only (no information pages,
# no JSON or Prometheus views of the cluster).
_QUIET_ROUTES = {"distributed.scheduler.http.routes": ["distributed.http.health"],
                 "distributed.worker.http.routes": ["distributed.http.health"]}


def local_cluster(workers, dashboard=False):
    """An embedded LocalCluster of `workers` processes of one thread each, whose servers
    (scheduler, nannies, workers and every HTTP server) listen on 127.0.0.1 only; the
    scheduler's dashboard and information pages only when `dashboard` (on 127.0.0.1:8787,
    or a free port when that one is taken). The caller closes it."""
    import dask
    from distributed import LocalCluster
    from distributed.worker_memory import parse_memory_limit

    workers = max(1, workers)
    # Left to itself each HTTP server binds every interface (dashboard_address ":0", and
    # a worker's server without one).
    quiet = {} if dashboard else _QUIET_ROUTES
    with dask.config.set(quiet):  # the scheduler, made here
        cluster = LocalCluster(n_workers=0, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address="127.0.0.1:8787" if dashboard else "127.0.0.1:0",
                               scheduler_kwargs={"dashboard": dashboard},
                               worker_dashboard_address="127.0.0.1:0",
                               memory_limit=parse_memory_limit("auto", 1, workers, logger=logging.getLogger("distributed.nanny")))
    # The workers, made by scale(): a worker's own dashboard (bokeh pages) follows
    # `dashboard` too; its HTTP server, which health checks use, stays on 127.0.0.1; the
    # routes reach the worker processes through their nannies' config.
    options = cluster.new_spec["options"]
    options["dashboard"] = dashboard
    if quiet:
        options["config"] = dict(quiet)
    cluster.scale(workers)
    return cluster


class _Terminated(BaseException):
    """SIGTERM, raised in the main thread as KeyboardInterrupt is for SIGINT."""


# While jobs run, the manifest is written again at most this often (seconds): a batch
# killed outright (SIGKILL, a lost machine) still leaves what finished until then.
MANIFEST_EVERY = 10.0


class IgnoreSigint:
    """A worker plugin for the workers of `fgsg batch`'s own LocalCluster: a terminal's
    Ctrl-C reaches every process of the batch, and the batch, which stops its workers, is
    the one to answer it (a worker would print a traceback of its own). setup runs in the
    worker's main thread, its event loop's."""

    name = "fgsg-batch-ignore-sigint"

    def setup(self, worker):
        import threading
        if threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGINT, signal.SIG_IGN)


def main(argv=None):
    parser = argparse.ArgumentParser(prog=os.environ.get("FGSG_BATCH_PROG", "python -m fgsg.batch"),
                                     description="Runs fgsg jobs on Dask (docs/scale.md).")
    parser.add_argument("jobs", help="JOBS.json: a list of {grammar, output, seed, attrs, surface, step, id}")
    parser.add_argument("--scheduler", help="a running dask scheduler, tcp://host:port (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 2,
                        help="LocalCluster worker processes (default: the cores)")
    parser.add_argument("--dashboard", action="store_true",
                        help="serve the LocalCluster's Dask dashboard on 127.0.0.1 (default: off)")
    parser.add_argument("--force", action="store_true",
                        help="run every job, also those the manifest records as done with the same inputs")
    args = parser.parse_args(argv)
    if os.path.isdir(args.jobs):
        print(f"fgsg batch: {args.jobs} is a directory, not a JOBS file", file=sys.stderr)
        return 2
    try:
        jobs = load_jobs(args.jobs)
    except (OSError, ValueError) as e:
        print(f"fgsg batch: {e}", file=sys.stderr)
        return 2
    manifest = manifest_path(args.jobs)
    problem = manifest_problem(manifest)
    if problem:
        print(f"fgsg batch: {problem}; no job was run", file=sys.stderr)
        return 2
    try:
        previous = read_manifest(manifest)
    except ValueError as e:
        print(f"fgsg batch: {e}: every job runs", file=sys.stderr)
        previous = []

    import threading
    main_thread = threading.current_thread() is threading.main_thread()
    line_open = [False]  # a progress line on a terminal not yet ended

    def progress(done, total, failed):
        end = "\n" if done == total or not sys.stderr.isatty() else ""
        line_open[0] = not end
        print(f"\rfgsg batch: {done}/{total} jobs done" + (f", {failed} failed" if failed else ""),
              end=end, file=sys.stderr, flush=True)

    def damaged(job, why):
        print(f"fgsg batch: job {job['id']}: {job['output']} is damaged ({why}); running it again", file=sys.stderr)

    outcomes = []  # filled by run_batch as jobs finish
    last_write = [time.monotonic()]

    def on_result(outcome):
        if time.monotonic() - last_write[0] >= MANIFEST_EVERY:
            try:
                write_manifest(manifest, outcomes, jobs)
            except OSError:
                pass  # said at the end, when it is written for good
            last_write[0] = time.monotonic()

    def terminated(signum, frame):
        raise _Terminated()

    old_term = signal.signal(signal.SIGTERM, terminated) if main_thread else None
    stopped = None
    client = cluster = None
    try:
        from distributed import Client
        if args.scheduler:
            client = Client(args.scheduler)
        else:
            cluster = local_cluster(args.workers, dashboard=args.dashboard)
            client = Client(cluster)
            client.register_worker_plugin(IgnoreSigint(), name=IgnoreSigint.name)
            if args.dashboard:
                print(f"fgsg batch: dashboard at {cluster.dashboard_link}", file=sys.stderr)
        run_batch(jobs, client, progress=progress, on_result=on_result, on_damaged=damaged,
                  previous=previous, force=args.force, outcomes=outcomes)
    except KeyboardInterrupt:
        stopped = "SIGINT"
    except _Terminated:
        stopped = "SIGTERM"
    finally:
        if main_thread:  # a second Ctrl-C while the cluster closes: no traceback either
            old_int = signal.signal(signal.SIGINT, signal.SIG_IGN)
            signal.signal(signal.SIGTERM, signal.SIG_IGN)
        if stopped:  # closing a cluster mid-run: Dask's complaints are not news
            logging.getLogger("distributed").setLevel(logging.CRITICAL)
        for closing in (client, cluster):
            try:
                if closing is not None:
                    closing.close()
            except Exception:
                if not stopped:
                    raise
        if main_thread:
            signal.signal(signal.SIGINT, old_int)
            signal.signal(signal.SIGTERM, old_term)
    if line_open[0]:
        print(file=sys.stderr)
    code = {"SIGINT": 130, "SIGTERM": 143}.get(stopped)
    if stopped and all(o is None for o in outcomes):
        # Nothing finished or was found done: the earlier manifest still says what is.
        print(f"fgsg batch: stopped by {stopped} before any job finished; {manifest} is unchanged", file=sys.stderr)
        return code
    try:
        write_manifest(manifest, outcomes, jobs, stopped=stopped and f"stopped by {stopped}")
    except OSError as e:
        print(f"fgsg batch: cannot write the manifest {manifest}: {e}", file=sys.stderr)
        return code or 2
    finished = [o for o in outcomes if o is not None]
    failures = [o for o in finished if not o["ok"]]
    if stopped:
        print(f"fgsg batch: stopped by {stopped}: wrote {manifest} ({len(finished)} of {len(outcomes)} jobs "
              f"finished, {len(failures)} failed); run the same command to go on", file=sys.stderr)
        return code
    for o in failures:
        print(f"fgsg batch: job {o['id']} failed: {o['error']}", file=sys.stderr)
    print(f"fgsg batch: wrote {manifest} ({len(outcomes) - len(failures)} of {len(outcomes)} jobs succeeded)",
          file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    # `python -m fgsg.batch`: run the imported module's main, so that the tasks a cluster
    # runs are fgsg.batch.run_job, which its workers import, not __main__'s (theirs is
    # dask-worker's).
    from fgsg.batch import main as _main
    sys.exit(_main())
