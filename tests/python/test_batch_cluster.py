"""fgsg batch on a real Dask cluster, as docs/scale.md starts one: a `dask-scheduler` and
two `dask-worker` processes on 127.0.0.1 (free ports, the package on their PYTHONPATH),
then `fgsg batch JOBS --scheduler tcp://127.0.0.1:PORT` runs city jobs on them — the task
is fgsg.batch.run_job, which the workers import (it was __main__'s, which they cannot) —
with the bytes of run_job in this process; `python3 -m fgsg.batch --force` runs them
all again there. The processes
are stopped by the test, every wait bounded."""
import json
import os
import signal
import socket
import subprocess
import sys
import time

import pytest
from distributed import Client

from fgsg import batch

SOURCE = os.environ["FGSG_SOURCE"]
FGSG = os.environ["FGSG_BINARY"]
CITY_JOBS = os.path.join(SOURCE, "examples", "city_jobs.json")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_listening(port, process, seconds):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if process.poll() is not None:
            raise RuntimeError(f"dask-scheduler ended ({process.returncode}) before listening")
        try:
            socket.create_connection(("127.0.0.1", port), timeout=1).close()
            return
        except OSError:
            time.sleep(0.2)
    raise TimeoutError(f"nothing listens on 127.0.0.1:{port} after {seconds} s")


def stop(processes):
    for p in processes:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGTERM)
    for p in processes:
        try:
            p.wait(30)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(10)


@pytest.fixture
def scheduler(tmp_path):
    """The address of a dask-scheduler with two dask-workers (one thread each), all on
    127.0.0.1; stopped afterwards. Their logs are in tmp_path/*.log."""
    port = free_port()
    quiet = ["--dashboard-address", "127.0.0.1:0", "--no-dashboard"]
    processes = []

    def start(name, words):
        log = open(tmp_path / f"{name}.log", "w")
        processes.append(subprocess.Popen(words, stdout=log, stderr=subprocess.STDOUT, start_new_session=True))
        log.close()
        return processes[-1]

    try:
        address = f"tcp://127.0.0.1:{port}"
        wait_listening(port, start("scheduler", ["dask-scheduler", "--host", "127.0.0.1", "--port", str(port)] + quiet), 60)
        for k in range(2):  # each node's worker, the package on its PYTHONPATH (CTest's)
            start(f"worker-{k}", ["dask-worker", address, "--host", "127.0.0.1", "--nthreads", "1",
                                  "--death-timeout", "60"] + quiet)
        with Client(address, timeout=30) as client:
            client.wait_for_workers(2, timeout=120)
        yield address
    finally:
        stop(processes[::-1])


def test_fgsg_batch_runs_the_city_jobs_on_a_running_scheduler_and_its_workers(tmp_path, scheduler):
    jobs = [dict(j, output=str(tmp_path / "out" / os.path.basename(j["output"])))
            for j in batch.load_jobs(CITY_JOBS)[:24]]
    (tmp_path / "city.json").write_text(json.dumps({"jobs": jobs}))
    run = subprocess.run([FGSG, "batch", str(tmp_path / "city.json"), "--scheduler", scheduler],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "24 of 24 jobs succeeded" in run.stderr and "Traceback" not in run.stderr
    manifest = json.loads((tmp_path / "city.manifest.json").read_text())
    assert manifest["complete"] and [o["id"] for o in manifest["jobs"]] == [j["id"] for j in jobs]
    assert all(o["ok"] and not o.get("skipped") for o in manifest["jobs"])
    for job in jobs[:3]:  # the workers' bytes are this process's
        here = dict(job, output=str(tmp_path / "here.glb"))
        assert batch.run_job(here)["ok"]
        assert (tmp_path / "here.glb").read_bytes() == open(job["output"], "rb").read()
    # Both workers ran jobs: each has the grammar it compiled in its cache.
    with Client(scheduler, timeout=30) as client:
        cached = client.run(lambda: __import__("fgsg.batch").batch._grammar.cache_info().currsize)
    assert len(cached) == 2 and all(n >= 1 for n in cached.values()), cached

    # `python3 -m fgsg.batch`, as docs/scale.md also names it: its tasks too are fgsg.batch's.
    again = subprocess.run([sys.executable, "-m", "fgsg.batch", str(tmp_path / "city.json"), "--scheduler", scheduler,
                            "--force"], capture_output=True, text=True, timeout=300)
    assert again.returncode == 0, again.stderr
    manifest = json.loads((tmp_path / "city.manifest.json").read_text())
    assert manifest["summary"] == {"jobs": 24, "finished": 24, "succeeded": 24, "failed": 0, "skipped": 0}
