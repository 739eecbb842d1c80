"""progress= of tetrahedralize, check, fracture, oracle and fuzz campaigns: the C++
loops call back from the calling thread with the GIL, a raised exception stops the call
and propagates (ending any peer process it ran), and the result is the same with and
without a listener."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import dtlab
from proc_children import children


def points(n=20000, seed=3):
    return np.random.default_rng(seed).random((n, 3))


def test_tetrahedralize_reports_insertion():
    pts = points()
    calls = []
    dt = dtlab.tetrahedralize(pts, progress=lambda done, total, stage: calls.append((done, total, stage)))
    assert calls[0] == (0, len(pts), "insert")
    assert calls[-1] == (len(pts), len(pts), "insert")
    done = [c[0] for c in calls]
    assert done == sorted(done) and len(set(done)) == len(done)
    assert 500 <= len(calls) <= 1100  # about total/1000 apart
    np.testing.assert_array_equal(dt.tets, dtlab.tetrahedralize(pts).tets)


def test_callback_runs_on_the_calling_thread_with_the_gil():
    caller = threading.get_ident()
    seen = set()
    # Python code runs in the callback, so the GIL is held; the thread is the caller's.
    dtlab.tetrahedralize(points(2000), progress=lambda *a: seen.add(threading.get_ident()))
    assert seen == {caller}


class Stop(Exception):
    pass


def test_exception_stops_the_build_and_propagates():
    calls = []

    def stop(done, total, stage):
        calls.append(done)
        if done >= total // 2:
            raise Stop(f"stopped at {done}")

    with pytest.raises(Stop, match="stopped at"):
        dtlab.tetrahedralize(points(), progress=stop)
    assert calls[-1] < 20000  # never reached the end
    assert len(dtlab.tetrahedralize(points(2000)).tets) > 0  # the module still works


def test_keyboard_interrupt_propagates():
    def interrupt(done, total, stage):
        if done:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        dtlab.tetrahedralize(points(), progress=interrupt)


def test_check_reports_its_eight_steps():
    pts = points(3000)
    dt = dtlab.tetrahedralize(pts)
    calls = []
    report = dtlab.check(pts, dt.tets, progress=lambda *a: calls.append(a), threads=2)
    assert report.ok
    assert calls == [(0, 8, "check"), (1, 8, "check"), (2, 8, "check"), (4, 8, "check"), (5, 8, "check"),
                     (6, 8, "check"), (7, 8, "check"), (8, 8, "check")]
    with pytest.raises(Stop):
        dtlab.check(pts, dt.tets, progress=lambda done, total, stage: (_ for _ in ()).throw(Stop()))


def test_fracture_reports_each_boolean():
    v, f = dtlab.read_mesh("builtin")
    calls = []
    pieces = dtlab.fracture(v, f, pieces=6, threads=2, progress=lambda *a: calls.append(a))
    assert calls and all(stage == "fracture:booleans" for _, _, stage in calls)
    assert sorted(d for d, _, _ in calls) == list(range(1, calls[0][1] + 1))
    assert len(pieces) >= 6
    with pytest.raises(Stop):
        dtlab.fracture(v, f, pieces=6, threads=2, progress=lambda *a: (_ for _ in ()).throw(Stop()))


def test_bad_progress_argument():
    with pytest.raises(ValueError, match="progress must be"):
        dtlab.tetrahedralize(points(100), progress="yes")


def test_progress_true_without_or_with_tqdm(capsys):
    dtlab.tetrahedralize(points(2000), progress=True)
    err = capsys.readouterr().err
    try:
        import tqdm  # noqa: F401
    except ImportError:
        assert "tetrahedralize: insert 0/2000" in err and "insert 2000/2000" in err
    else:
        assert "tetrahedralize insert" in err  # the bar's description


def test_tqdm_bar_reaches_the_total():
    tqdm = pytest.importorskip("tqdm")
    from dtlab._progress import StageBar
    with StageBar(True, "t") as bar:
        assert isinstance(bar._bar, tqdm.tqdm)
        dtlab.tetrahedralize(points(5000), progress=bar)
        assert bar._bar.n == bar._bar.total == 5000


def no_child_left(before, seconds=3.0):
    """True once no child of ours but those in `before` is left (a killed peer's reaping
    may lag a little on a loaded machine)."""
    deadline = time.monotonic() + seconds
    while set(children()) - set(before):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.02)
    return True


def split_stages(calls):
    """(insert calls, check calls, peer calls) of an oracle() progress record."""
    insert = [c for c in calls if c[2] == "insert"]
    check = [c for c in calls if c[2] == "check"]
    peers = [c for c in calls if c[2] not in ("insert", "check")]
    assert calls == insert + check + peers  # in that order
    return insert, check, peers


def assert_peer_stages(peer_calls, report, names):
    expected = []
    for i, name in enumerate(names):
        expected += [(i, len(names), f"{name}: running"), (i + 1, len(names), f"{name}: {report.peers[name].verdict}")]
    assert peer_calls == expected


@pytest.mark.parametrize("function_peer", [False, True])
def test_oracle_reports_build_check_and_each_peer(function_peer):
    scipy = pytest.importorskip("scipy.spatial")
    pts = points(3000)
    caller = threading.get_ident()
    calls, threads = [], set()

    def record(done, total, stage):
        calls.append((done, total, stage))
        threads.add(threading.get_ident())

    # With a function peer the session runs on this thread, else on a worker.
    fns = {"mine": lambda p: scipy.Delaunay(p).simplices} if function_peer else {}
    r = dtlab.oracle(pts, against=["cgal", "dtlab:naive"], peers=fns, progress=record)
    assert threads == {caller}
    insert, check, peer_calls = split_stages(calls)
    assert insert[0] == (0, len(pts), "insert") and insert[-1] == (len(pts), len(pts), "insert")
    assert [c[0] for c in insert] == sorted(c[0] for c in insert)
    assert check[0] == (0, 8, "check") and check[-1] == (8, 8, "check")
    assert [c[0] for c in check] == sorted(c[0] for c in check)
    assert_peer_stages(peer_calls, r, ["cgal", "dtlab:naive", *fns])
    quiet = dtlab.oracle(pts, against=["cgal", "dtlab:naive"], peers=fns)
    assert {n: p.verdict for n, p in quiet.peers.items()} == {n: p.verdict for n, p in r.peers.items()}


def test_oracle_progress_true_writes_a_line_per_stage(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "tqdm", None)  # the stderr lines, tqdm or not
    dtlab.oracle(points(500), against=["dtlab:exact"], progress=True)
    err = capsys.readouterr().err
    for line in ("oracle: insert 0/500", "oracle: insert 500/500", "oracle: check 8/8",
                 "oracle: dtlab:exact: running 0/1", "oracle: dtlab:exact: delaunay 1/1"):
        assert line in err


def peer_memory_mb():
    """The peers' memory limit for these tests: the default (0: half the machine's), but
    under `make asan` 1e9 MB, since the ASan runtime the test environment preloads is
    inherited by the peer's shell and reserves about 16 TB of address space for its
    shadow memory, which any smaller address-space limit refuses (the peer then aborts
    at once, before the test can end it)."""
    return 1e9 if "libasan" in os.environ.get("LD_PRELOAD", "") else 0.0


def sleeper(tmp_path):
    """A 'tetgen' that never answers (dtlab.oracle(tetgen=...)): it would outlive the
    call unless the call ends it."""
    path = tmp_path / "tetgen"
    path.write_text("#!/bin/sh\nexec sleep 1000\n")
    path.chmod(0o755)
    return str(path)


def test_oracle_callback_that_raises_ends_the_running_peer(tmp_path):
    before = children()
    seen, running = [], []

    def stop_while_tetgen_runs(done, total, stage):
        seen.append(stage)
        if stage == "tetgen: running":
            deadline = time.monotonic() + 10  # the peer's process starts meanwhile
            while not running and time.monotonic() < deadline:
                running.extend(set(children()) - set(before))
                time.sleep(0.005)
            raise Stop("stop")

    with pytest.raises(Stop):
        dtlab.oracle(points(2000), against=["tetgen", "cgal"], tetgen=sleeper(tmp_path), timeout=600,
                     memory_mb=peer_memory_mb(), progress=stop_while_tetgen_runs)
    assert seen[-1] == "tetgen: running" and "cgal: running" not in seen
    assert running  # the callable raised while the peer's process ran (for 1000 s unless ended)
    assert no_child_left(before)
    assert dtlab.oracle(points(500), against=["cgal"]).peers["cgal"].verdict == "delaunay"  # still works


@pytest.mark.parametrize("stage", ["insert", "check"])
def test_oracle_callback_that_raises_stops_our_build_or_check(stage):
    def stop(done, total, s):
        if s == stage and done > 0:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        dtlab.oracle(points(), against=["cgal"], progress=stop)
    with pytest.raises(Stop):  # the function peers' path: the session on this thread
        dtlab.oracle(points(), against=[], peers={"mine": lambda p: []},
                     progress=lambda d, t, s: (_ for _ in ()).throw(Stop()) if s == stage else None)


def test_ctrl_c_with_a_progress_callback_answers_at_once(tmp_path):
    marker = tmp_path / "running"
    script = textwrap.dedent(f"""
        import numpy as np, sys, time, dtlab
        sys.path.insert(0, {os.path.dirname(__file__)!r})
        from proc_children import children
        def mark(done, total, stage):
            if stage == "tetgen: running":
                open({str(marker)!r}, "w").write("x")
        try:
            dtlab.oracle(np.random.default_rng(3).random((2000, 3)), against=["tetgen"],
                         tetgen={sleeper(tmp_path)!r}, timeout=600, progress=mark,
                         memory_mb={peer_memory_mb()!r})
        except KeyboardInterrupt:
            print("KeyboardInterrupt", flush=True)
            deadline = time.monotonic() + 3
            while children() and time.monotonic() < deadline:
                time.sleep(0.02)
            print("children:", list(children()), flush=True)
            sys.exit(7)
    """)
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while not marker.exists():
        assert time.monotonic() < deadline and proc.poll() is None
        time.sleep(0.01)
    time.sleep(0.1)  # the sleeper has started
    t0 = time.monotonic()
    proc.send_signal(signal.SIGINT)
    line = proc.stdout.readline()
    assert time.monotonic() - t0 < 5  # a 50 ms poll (and half a second for the peer to end), not the peer's 1000 s
    out, _ = proc.communicate(timeout=30)
    assert proc.returncode == 7 and line.strip() == "KeyboardInterrupt" and out.strip() == "children: []"


def test_fuzz_campaign_reports_cases_per_family():
    calls = []
    families = ["uniform", "cospherical", "lattice"]
    c = dtlab.fuzz.campaign("dtlab:exact", families=families, cases=3, points=16, shrink=False,
                            progress=lambda *a: calls.append(a))
    assert calls == [(i, 3, f) for f in families for i in (1, 2, 3)]
    assert len(c.cases) == 9


def test_fuzz_campaign_callback_that_raises_stops_it():
    before = children()
    calls = []

    def stop(done, total, family):
        calls.append((done, family))
        if family == "cospherical":
            raise Stop(family)

    with pytest.raises(Stop, match="cospherical"):
        dtlab.fuzz.campaign(lambda p: [], families="uniform,cospherical,lattice", cases=2, points=16, shrink=False,
                            progress=stop)
    assert calls == [(1, "uniform"), (2, "uniform"), (1, "cospherical")]
    assert no_child_left(before)


def test_overhead_benchmark_runs(capsys):
    """python/benchmarks/progress_overhead.py works (its numbers are for python/README.md, not asserted)."""
    import importlib.util
    path = os.path.join(os.path.dirname(__file__), "..", "benchmarks", "progress_overhead.py")
    spec = importlib.util.spec_from_file_location("progress_overhead", path)
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    assert bench.main(["--sizes", "2000", "--rounds", "1"]) == 0
    rows = [line for line in capsys.readouterr().out.splitlines() if line.startswith("| 2000 |")]
    assert [r.split("|")[2].strip() for r in rows] == ["None", "no-op callable", "True"]
    assert rows[1].split("|")[-2].strip() == "1001"  # every 2 points, and the end
