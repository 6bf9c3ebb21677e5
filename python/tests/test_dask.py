# SPDX-License-Identifier: BSD-2-Clause
"""python/README.md's fleet recipe, run as written: its module's fleet()
on a dask.distributed LocalCluster of two worker processes over 40 logs
of more than 10^6 sentences (the committed real logs, repeated) gives,
column for column, the frame of the single-process loop. Every value of
that frame is checked against independent references by test_readme.py
(the same computation per log); here the question is only whether the
distributed run changes anything.

    python3 python/tests/test_dask.py [sentences] [workers...]

times the single process and the cluster with each number of workers
(python/README.md's scaling table)."""
import importlib
import os
import re
import sys
import time

import pytest

TOP = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
LOGS = os.path.join(TOP, "tests", "nmea", "logs")
FILES = 40
SENTENCES = 10 ** 6


def recipe(folder):
    """python/README.md's fleet.py, written into `folder` and imported
    from there (the worker processes import it by name, as they would
    the user's module)."""
    with open(os.path.join(TOP, "python", "README.md")) as f:
        text = f.read()
    code = re.search(r"```python\n(# fleet\.py\n.*?)```", text, re.S).group(1)
    with open(os.path.join(folder, "fleet.py"), "w") as f:
        f.write(code)
    if folder not in sys.path:
        sys.path.insert(0, folder)
    sys.modules.pop("fleet", None)
    return importlib.import_module("fleet")


def make_logs(folder, sentences, files=FILES):
    """`files` logs of at least `sentences` lines in all, each the
    committed real logs one after another, repeated."""
    data = b"".join(open(os.path.join(d, f), "rb").read()
                    for d, _, names in sorted(os.walk(LOGS))
                    for f in sorted(names) if f.endswith((".log", ".nmea")))
    per_file = -(-sentences // files)
    copies = -(-per_file // data.count(b"\n"))
    paths = []
    for k in range(files):
        path = os.path.join(folder, "log%02d.nmea" % k)
        with open(path, "wb") as f:
            f.write(data * copies)
        paths.append(path)
    return paths, files * copies * data.count(b"\n")


def cluster(workers):
    from dask.distributed import Client, LocalCluster
    c = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                     dashboard_address=None)
    return c, Client(c)


def test_fleet_on_worker_processes_equals_one_process(tmp_path):
    pd = pytest.importorskip("pandas")
    pytest.importorskip("distributed")
    fleet = recipe(str(tmp_path))
    paths, n = make_logs(str(tmp_path), SENTENCES)
    assert n >= SENTENCES
    alone = pd.concat([fleet.fixes(p) for p in paths], ignore_index=True)
    c, client = cluster(2)
    try:
        pids = set(client.run(os.getpid).values())
        # two workers, each a process of its own
        assert len(pids) == 2 and os.getpid() not in pids
        spread = fleet.fleet(paths, client)
        # every log went to a worker, and both worked
        who = client.gather(client.map(lambda p: os.getpid(), paths,
                                       pure=False))
        assert set(who) <= pids
    finally:
        client.close()
        c.close()
    pd.testing.assert_frame_equal(spread, alone, check_exact=True)
    assert len(alone) > 0
    assert (alone.groupby("path").size() == len(alone) // FILES).all()


def main():
    import pandas as pd
    import tempfile
    sentences = int(sys.argv[1]) if len(sys.argv) > 1 else 4 * SENTENCES
    counts = [int(w) for w in sys.argv[2:]] or [1, 2, 3, 4]
    with tempfile.TemporaryDirectory() as folder:
        fleet = recipe(folder)
        paths, n = make_logs(folder, sentences)
        t = time.perf_counter()
        alone = pd.concat([fleet.fixes(p) for p in paths],
                          ignore_index=True)
        single = time.perf_counter() - t
        print("one process: %d sentences, %d fixes, %.2f s, %.0f k "
              "sentences/s" % (n, len(alone), single, n / single / 1e3))
        for workers in counts:
            t0 = time.perf_counter()
            c, client = cluster(workers)
            # each worker imports the module (and with it drdc, numpy and
            # pandas) once: start-up, not the run
            client.run(importlib.import_module, "fleet")
            t1 = time.perf_counter()
            spread = fleet.fleet(paths, client)
            t2 = time.perf_counter()
            client.close()
            c.close()
            assert spread.equals(alone)
            print("%d workers: start %.2f s, run %.2f s, %.0f k sentences/s, "
                  "%.2fx one process" % (workers, t1 - t0, t2 - t1,
                                         n / (t2 - t1) / 1e3,
                                         single / (t2 - t1)))


if __name__ == "__main__":
    main()
