#!/usr/bin/env python3
"""Batch throughput: 1,000 views on 1 worker process, then on 2, each worker rendering on
one core; rounds alternate, medians reported, and the scaling ratio = (views/s on 2) /
(2 x views/s on 1): 1.0 is perfect. Two runners, each with its N worker processes
started before the timing (a job's time is the job's alone): `local` is a
velocity.batch.LocalPool of N processes (what `velocity batch --workers N` starts for
its job), `dask` a Dask LocalCluster of N worker processes (its scheduler runs in this
process, as does the local runner's coordinator).

    PYTHONPATH=build/python python3 python/bench/bench_batch.py [--rounds 3] [--size 256] [--runner local|dask|both] [--tmp DIR] [--workers 1,2,4]

The job: 10 models (the project's test models and Debian's assimp-testmodels), 100
orbit views each, colour + depth + mask at size x size, one Dask task per 25 views.
Times the job only (the cluster is started and warmed up before), by the wall clock
and in CPU time (this process and the processes below it: the local runner's; Dask's
workers too, which are its children here).

Two controls: the disk's own scaling (files written and renamed by one process, then
by two: on this machine's virtual disk, creating a file costs about 0.2 ms and two
processes do not create them twice as fast; `--tmp /dev/shm` takes the disk out), and
the machine's own scaling: the same single-threaded C++ render loop
(velocity bench --threads 1), one copy alone, then two copies at once. On a
machine whose two cores are two hyperthreads of one physical core, or that others
share, two processes never reach 2x, whatever the batch runner does.
"""
import re
import subprocess
import argparse
import json
import os
import shutil
import statistics
import sys
import tempfile
import time

import distributed

from velocity.batch import LocalPool, run_local
from velocity.dask_runner import local_cluster, run_dask
from velocity.jobs import load_job
from velocity.progress import Progress

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODELS = [os.path.join(ROOT, "tests", "data", "models", m) for m in
          ("duck.asc", "fork.asc", "wuson_x4.obj", "CITY.ASC", "TESTI.ASC", "UUSALKU.ASC")] + [
    "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf",
    "/usr/share/assimp/models/PLY/cube.ply",
    "/usr/share/assimp/models/STL/Spider_ascii.stl",
    "/usr/share/assimp/models/3DS/test1.3ds",
]


def machine_scaling(build, rounds):
    cmd = [os.path.join(build, "velocity"), "bench", "--mesh", "sphere:128", "--size", "256x256", "--frames", "400",
           "--threads", "1"]
    ms = lambda out: float(re.search(r"median_ms=([0-9.]+)", out).group(1))  # noqa: E731
    alone, pair = [], []
    for _ in range(rounds):
        alone.append(ms(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout))
        procs = [subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True) for _ in range(2)]
        pair.append(statistics.mean(ms(p.communicate()[0]) for p in procs))
    a, b = statistics.median(alone), statistics.median(pair)
    print(f"control: one render loop alone {a:.3f} ms/frame, two at once {b:.3f} ms/frame each: "
          f"the machine scales {a / b:.3f} of 2x", flush=True)
    return a / b


def tree_cpu_seconds():
    """CPU seconds (user + system) used so far by this process and every process below
    it (the local runner's forkserver and workers): on a shared, loaded machine the work
    a job costs, which wall-clock views/s are not. Processes that ended are not counted."""
    parents, ticks = {}, {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        parents[int(entry)] = int(fields[1])
        ticks[int(entry)] = int(fields[11]) + int(fields[12])
    mine, grew = {os.getpid()}, True
    while grew:
        more = {pid for pid, parent in parents.items() if parent in mine} - mine
        grew = bool(more)
        mine |= more
    return sum(ticks.get(pid, 0) for pid in mine) / os.sysconf("SC_CLK_TCK")


def _write_files(folder, n, go):
    go.wait()  # timed from here: the process has started
    for i in range(n):
        path = os.path.join(folder, f"{i}.png")
        with open(path + ".tmp", "wb") as f:
            f.write(bytes(20000))
        os.replace(path + ".tmp", path)


def disk_scaling(base, rounds, n=1500):
    """The batch's writes without the rendering: n files of 20 KB, each written to a
    temporary name and renamed (as the runner writes), by one process, then by two at
    once, each in its own folder under `base`; timed once the processes have started."""
    import multiprocessing
    ctx = multiprocessing.get_context("spawn")
    one, two = [], []
    for _ in range(rounds):
        for k, rates in ((1, one), (2, two)):
            folders = [tempfile.mkdtemp(prefix="velocity-bench-disk-", dir=base) for _ in range(k)]
            go = ctx.Event()
            procs = [ctx.Process(target=_write_files, args=(f, n, go)) for f in folders]
            for p in procs:
                p.start()
            time.sleep(1.0)  # let them start (spawn imports the interpreter anew)
            t0 = time.perf_counter()
            go.set()
            for p in procs:
                p.join()
            rates.append(k * n / (time.perf_counter() - t0))
            for f in folders:
                shutil.rmtree(f, ignore_errors=True)
    a, b = statistics.median(one), statistics.median(two)
    print(f"control: writing files in {base or tempfile.gettempdir()}: one process {a:.0f} files/s, two at once "
          f"{b:.0f} files/s: the disk scales {b / (2 * a):.3f} of 2x (each view writes 3 files)", flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--views", type=int, default=100, help="views per model")
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--tmp", default=None,
                   help="where the job writes (default: the system's temporary folder; /dev/shm measures the "
                        "runner rather than the disk)")
    p.add_argument("--chunk", type=int, default=25, help="views per task")
    p.add_argument("--runner", choices=("local", "dask", "both"), default="both")
    p.add_argument("--workers", default="1,2",
                   help="worker counts to time, comma-separated; each is compared with 1 (default 1,2)")
    args = p.parse_args()
    args.workers = sorted({1} | {int(n) for n in args.workers.split(",")})
    control = machine_scaling(args.build, args.rounds)
    disk_scaling(args.tmp, args.rounds)
    runners = ("local", "dask") if args.runner == "both" else (args.runner,)
    for runner in runners:
        rates = measure(runner, args)
        for n in args.workers[1:]:
            print(f"{runner}: median 1 worker {rates[1]:.1f} views/s, {n} workers {rates[n]:.1f} views/s, "
                  f"scaling {rates[n] / (n * rates[1]):.3f} of {n}x (cores: {os.cpu_count()}); "
                  f"the machine itself: {control:.3f} of 2x", flush=True)


def measure(runner, args):
    """Median views/s of the job on each count of worker processes, rounds alternating."""
    tmp = tempfile.mkdtemp(prefix="velocity-bench-batch-", dir=args.tmp)
    spec = {"models": MODELS, "size": [args.size, args.size], "views": {"type": "orbit", "count": args.views},
            "outputs": ["color", "depth", "mask"], "chunk": args.chunk}
    total = len(MODELS) * args.views
    clusters, pools = {}, {}
    if runner == "local":
        pools = {n: LocalPool(n, threads=1) for n in args.workers}
    if runner == "dask":
        for n in args.workers:
            cluster = local_cluster(n, silence_logs=50)  # as run_dask starts its own
            clusters[n] = (cluster, distributed.Client(cluster))
    rates = {n: [] for n in args.workers}
    cpu_ms = {n: [] for n in args.workers}
    try:
        for r in range(args.rounds + 1):  # round 0 warms up (imports, renderers, page cache)
            for n in args.workers:
                out = os.path.join(tmp, f"out-{n}")
                shutil.rmtree(out, ignore_errors=True)
                job = load_job(spec, out)
                t0, c0 = time.perf_counter(), tree_cpu_seconds()
                if runner == "dask":
                    m = run_dask(job, client=clusters[n][1], progress=Progress(False))
                else:
                    m = run_local(job, pool=pools[n], progress=Progress(False))
                dt, cpu = time.perf_counter() - t0, tree_cpu_seconds() - c0
                assert m["views_done"] == total and not m["models_failed"], json.dumps(m["models_failed"])
                if r:
                    rates[n].append(total / dt)
                    cpu_ms[n].append(1e3 * cpu / total)
                print(f"{runner} round {r}{' (warm-up)' if not r else ''}: {n} worker(s): {total} views in {dt:.2f} s "
                      f"= {total / dt:.1f} views/s, {1e3 * cpu / total:.2f} CPU ms/view", flush=True)
    finally:
        for cluster, client in clusters.values():
            client.close()
            cluster.close()
        for pool in pools.values():
            pool.close()
        shutil.rmtree(tmp, ignore_errors=True)
    for n in args.workers:
        print(f"{runner}: {n} worker(s): median {statistics.median(rates[n]):.1f} views/s, "
              f"{statistics.median(cpu_ms[n]):.2f} CPU ms/view", flush=True)
    return {n: statistics.median(r) for n, r in rates.items()}


if __name__ == "__main__":
    sys.exit(main())
