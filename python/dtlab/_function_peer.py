"""A Python function as a dtlab peer: it runs in a forked child process, so that its
segfault, exception, hang or runaway allocation is the child's end (a verdict), never
the interpreter's. The C++ side (oracle/peers/peer_function.hpp) calls `runner(fn)` once per
input with the peer's limits and judges what comes back like any peer's answer.

The child: its own process group, stdout and stderr to the peer's log (the last line
is the verdict's message), RLIMIT_AS at the memory limit, fn(points) timed, then the
tets on a pipe: b"T", f64 seconds, u64 m, m x 4 int64; or b"B" and why the return
value is no (m, 4) integer array. An exception is exit status 1 with its traceback in
the log. The parent reads the pipe while it waits (a large answer never blocks the
child), kills the group at the time limit, and on any exception (KeyboardInterrupt
included) kills and reaps the child before it re-raises. The child runs under a reaper,
the process the parent waits for (`_core.fork_under_reaper`), which adopts and ends
whatever the function leaves behind, even a process in a session of its own with an
empty environment, and then exits as the child did.
"""
from __future__ import annotations

import faulthandler
import os
import resource
import select
import signal
import struct
import sys
import time
import traceback
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from . import _core

_INT64_MAX = 2**63 - 1


def _encode(result: Any, seconds: float) -> bytes:
    try:
        a = np.asarray(result)
    except Exception as e:  # a ragged list, an object numpy cannot hold
        return b"B" + f"not an array ({type(e).__name__}: {e})".encode()
    if a.ndim != 2 or a.shape[1] != 4:
        return b"B" + f"shape {a.shape}, expected (m, 4)".encode()
    if a.dtype.kind not in "iu":
        return b"B" + f"dtype {a.dtype}, expected integers".encode()
    if a.dtype.kind == "u" and a.size and int(a.max()) > _INT64_MAX:
        return b"B" + f"vertex {int(a.max())} is not an index of the points".encode()
    rows = np.ascontiguousarray(a, dtype="<i8")
    return b"T" + struct.pack("<dQ", seconds, rows.shape[0]) + rows.tobytes()


def _child(fn: Callable[[np.ndarray], Any], points: np.ndarray, memory_bytes: int, log_path: str, w: int,
           guard_prefix: str) -> None:
    code = 1
    try:
        os.setpgid(0, 0)
        # The exit guard's tag (kernel/exit_guard.hpp): what the function starts inherits
        # it, so a descendant that leaves the group (setsid) is still found and killed.
        os.environ["DTLAB_GUARD"] = guard_prefix + str(os.getpid()).zfill(_core.guard_pid_digits())
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        fd = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.dup2(fd, 1)
        os.dup2(fd, 2)
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        # Python-level streams too: a host may have replaced them (pytest's capture)
        sys.stdout = open(1, "w", buffering=1, closefd=False)
        sys.stderr = open(2, "w", buffering=1, closefd=False)
        faulthandler.disable()  # its dump would go to the host's stderr; the signal is the verdict
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        if memory_bytes:
            resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
        try:
            t = time.perf_counter()
            payload = _encode(fn(points), time.perf_counter() - t)
        except MemoryError:
            traceback.print_exc()
            print(f"MemoryError: out of memory under the peer's limit of {memory_bytes / 1e6:.0f} MB", file=sys.stderr)
            sys.stderr.flush()
            return  # exit status 1 (finally): refused, with that line
        view = memoryview(payload)
        while view:
            view = view[os.write(w, view):]
        code = 0
    except BaseException:  # noqa: B036 (SystemExit and KeyboardInterrupt too: the child ends here)
        try:
            traceback.print_exc()
            sys.stderr.flush()
        except BaseException:  # noqa: B036
            pass
    finally:
        os._exit(code)


def _vm_hwm(pid: int) -> int:
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError):
        pass
    return 0


def _kill_group(pid: int) -> None:
    try:
        os.killpg(pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _drain(r: int, chunks: list[bytes]) -> bool:
    """Reads what the pipe holds now; True at its end."""
    while True:
        try:
            b = os.read(r, 1 << 20)
        except BlockingIOError:
            return False
        if not b:
            return True
        chunks.append(b)


def run_in_child(fn: Callable[[np.ndarray], Any], points: np.ndarray, timeout_s: float, memory_bytes: int,
                 log_path: str) -> tuple[Any, ...]:
    """(status, exit_code, signal, wall_seconds, peak_rss_bytes, answer): status "exited",
    "signaled", "timed_out" or "not_started" (then exit_code is -1 and answer the reason);
    answer the raw bytes the child sent (b"" when none)."""
    for stream in (sys.stdout, sys.stderr):  # else the child's copies of the buffers reach its log
        try:
            stream.flush()
        except (AttributeError, ValueError, OSError):
            pass
    guard_prefix = _core.guard_tag_prefix()  # the parent's nonce, before the fork
    r, w = os.pipe()
    start = time.monotonic()
    try:
        # The child runs under a reaper (oracle/peers/program_reaper.hpp), the process
        # waited for here, which ends what the function leaves, even descendants that
        # cleared their environment and left the group (env -i setsid).
        reaper, pid = _core.fork_under_reaper()
    except (OSError, RuntimeError) as e:  # a std::system_error from the fork
        os.close(r)
        os.close(w)
        return ("not_started", -1, 0, 0.0, 0, f"fork failed: {e}")
    if pid == 0:
        os.close(r)
        _child(fn, points, memory_bytes, log_path, w, guard_prefix)
    os.close(w)
    os.set_blocking(r, False)
    chunks: list[bytes] = []
    peak, status, eof, reaped = 0, 0, False, False
    try:
        while True:
            peak = max(peak, _vm_hwm(pid))
            elapsed = time.monotonic() - start
            if not eof:
                ready, _, _ = select.select([r], [], [], 0.001 if elapsed < 0.2 else 0.005 if elapsed < 2 else 0.02)
                if ready:
                    eof = _drain(r, chunks)
            else:
                time.sleep(0.001 if elapsed < 0.2 else 0.005 if elapsed < 2 else 0.02)
            got, status = os.waitpid(reaper, os.WNOHANG)
            if got == reaper:
                reaped = True
                _drain(r, chunks)  # all it wrote is in the pipe now (a grandchild may hold it open)
                break
            if time.monotonic() - start > timeout_s:
                _kill_group(pid)
                os.waitpid(reaper, 0)
                reaped = True
                return ("timed_out", -1, 0, time.monotonic() - start, peak, b"")
    finally:
        if not reaped:  # an exception here (KeyboardInterrupt): the child goes first
            _kill_group(pid)
            os.waitpid(reaper, 0)
        _kill_group(pid)  # what the function started, if it outlived the child (the reaper ended it too)
        _core.end_tagged(pid)  # and what left the group
        os.close(r)
    seconds = time.monotonic() - start
    answer = b"".join(chunks)
    if os.WIFSIGNALED(status):
        return ("signaled", -1, os.WTERMSIG(status), seconds, peak, answer)
    return ("exited", os.WEXITSTATUS(status), 0, seconds, peak, answer)


def runner(fn: Callable[[np.ndarray], Any]) -> Callable[[np.ndarray, float, int, str], tuple[Any, ...]]:
    """The callable the C++ side registers for the peer `fn`."""
    if not callable(fn):
        raise ValueError(f"peers: a peer must be a callable (points) -> (m, 4) tets, got {type(fn).__name__}")

    def run(points: np.ndarray, timeout_s: float, memory_bytes: int, log_path: str) -> tuple[Any, ...]:
        return run_in_child(fn, points, timeout_s, memory_bytes, log_path)

    return run


def runners(peers: Mapping[str, Callable[[np.ndarray], Any]] | None) -> dict[str, Any]:
    """{name: runner} for _core (names checked there)."""
    if peers is None:
        return {}
    if not isinstance(peers, Mapping):
        raise ValueError("peers: expected a mapping {name: fn}")
    return {str(name): runner(fn) for name, fn in peers.items()}
