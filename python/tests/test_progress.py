"""progress= of tetrahedralize, check and fracture: the C++ loops call back from the
calling thread with the GIL, a raised exception stops the call and propagates, and the
result is the same with and without a listener."""
import threading

import numpy as np
import pytest

import dtlab


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
