"""fgsg.batch throughput (#21): the 100 lots of examples/city_jobs.json (Muller's building
with per-lot seeds and sizes), jobs per second run one after another in this process
against a dask LocalCluster of W worker processes (start-up and shut-down of the cluster
counted separately). Prints one JSON line.
usage: PYTHONPATH=build/python python3 bench/batch_jobs.py [WORKERS]"""
import json
import os
import sys
import tempfile
import time

from distributed import Client, LocalCluster

from fgsg import batch


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    workers = int(sys.argv[1]) if len(sys.argv) > 1 else 2
    jobs = batch.load_jobs(os.path.join(root, "examples", "city_jobs.json"))
    with tempfile.TemporaryDirectory() as tmp:
        def into(folder):
            return [dict(j, output=os.path.join(tmp, folder, os.path.basename(j["output"]))) for j in jobs]
        seq = into("seq")
        t = time.monotonic()
        assert all(batch.run_job(j)["ok"] for j in seq)
        sequential = time.monotonic() - t
        t = time.monotonic()
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0")
        client = Client(cluster)
        startup = time.monotonic() - t
        par = into("par")
        t = time.monotonic()
        assert all(o["ok"] for o in batch.run_batch(par, client))
        parallel = time.monotonic() - t
        same = all(open(a["output"], "rb").read() == open(b["output"], "rb").read() for a, b in zip(seq, par))
        client.close()
        cluster.close()
    print(json.dumps({"bench": "batch_jobs", "jobs": len(jobs), "workers": workers,
                      "sequential_jobs_per_s": round(len(jobs) / sequential, 1),
                      "cluster_jobs_per_s": round(len(jobs) / parallel, 1), "cluster_startup_s": round(startup, 2),
                      "same_bytes": same}))


if __name__ == "__main__":  # the cluster's worker processes import this file
    main()
