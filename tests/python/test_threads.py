"""The package from 16 Python threads at once (issue 52; scripts/tsan.sh runs this under
ThreadSanitizer): CGA, an L-system, a parallel Koch curve and a surface pattern with
collisions, by both engines, with several seeds and attributes, half of the threads on
Grammar objects they share and half on ones each compiles itself, and every result the
bytes of the same generate() run alone on one thread."""
import os
import threading

import numpy as np

import fgsg

SOURCE = os.environ["FGSG_SOURCE"]
THREADS = 16


def example(name):
    return os.path.join(SOURCE, "examples", name + ".fgsg")


# (grammar, seed, attrs): each taken by both engines.
CASES = [
    (example("mueller_building"), 3, {"lot_width": 18}),
    (example("mueller_building"), 11, {"lot_width": 26, "roof_angle": 35.5}),
    (example("abop_plant"), 5, None),
    (example("abop_plant"), 9, None),
    (example("koch"), 1, None),
    (example("fig4_on_surface"), 2, None),
    (example("fig1_cracks_surface"), 4, None),
    (example("fig1_cracks_surface"), 8, None),
]
JOBS = [(path, seed, attrs, engine) for path, seed, attrs in CASES for engine in ("jit", "interp")]
assert len(JOBS) == THREADS


def arrays(result):
    return (result.positions.copy(), result.normals.copy(), result.indices.copy(), result.instances.copy(),
            result.stats["instances"])


def same(a, b):
    for x, y in zip(a[:-1], b[:-1]):
        np.testing.assert_array_equal(x, y)
    assert a[-1] == b[-1]


def test_16_threads_give_the_results_of_one():
    shared = {path: fgsg.Grammar.from_file(path) for path, _, _ in CASES}
    alone = [arrays(shared[path].generate(seed=seed, attrs=attrs, engine=engine))
             for path, seed, attrs, engine in JOBS]
    results = [None] * THREADS
    errors = []
    start = threading.Barrier(THREADS)

    def work(i):
        try:
            path, seed, attrs, engine = JOBS[i]
            # Odd threads compile their own Grammar, concurrently with the others' work.
            g = shared[path] if i % 2 == 0 else fgsg.Grammar.from_file(path)
            start.wait()
            results[i] = arrays(g.generate(seed=seed, attrs=attrs, engine=engine))
        except BaseException as e:  # reported below, with the thread's job
            errors.append((JOBS[i], repr(e)))
            start.abort()

    threads = [threading.Thread(target=work, args=(i,)) for i in range(THREADS)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for i in range(THREADS):
        assert results[i][0].size > 0, JOBS[i]
        same(alone[i], results[i])
